// The browser side of the speed-accuracy bench (bench/run.js drives it; test/browser/dense.test.js
// uses it too): `window.bench` builds a scene with the real pipeline in a real EffectComposer,
// renders the dense 2D reference once per profile (the pipeline's own method 'dense'), then
// measures each setting's error against it and its time, all through the library's public API.
//
// Times: `gpuMs` = EXT_disjoint_timer_query_webgl2 around the SSS stage (both blurs, or the dense
// pass), from the pipeline's stage timer (dev/gpuTimer.js); `ms` = a whole composer.render()
// closed by a 1-pixel readPixels (the fence: gl.finish() does not wait in Chromium). The runner
// takes the medians over many frames (bench/run.js).
import {
  ACESFilmicToneMapping, FloatType, HalfFloatType, UnsignedByteType, Vector2, WebGLRenderer, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering, AUTO_SAMPLES, AUTO_REACH, pixelsPerMm } from '/src/index.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { GpuStageTimer, median } from '/dev/gpuTimer.js';
import { radianceErrors, maskedSsim } from '/dev/metrics.js';
import { buildScene } from './scenes.js';
import { drawChart } from './chart.js';

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

let session = null;

/** Renderer, browser and GPU as WebGL reports them. */
function info() {
  const renderer = new WebGLRenderer();
  const gl = renderer.getContext();
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const out = {
    userAgent: navigator.userAgent,
    vendor: gl.getParameter(debug ? debug.UNMASKED_VENDOR_WEBGL : gl.VENDOR),
    renderer: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
    version: gl.getParameter(gl.VERSION),
    timerQuery: gl.getExtension('EXT_disjoint_timer_query_webgl2') !== null,
    hardwareConcurrency: navigator.hardwareConcurrency,
    autoSamples: AUTO_SAMPLES, // the tap levels samples 'auto' chooses from
    autoReach: AUTO_REACH, // its rule: (taps - 3) / 2 >= autoReach x the estimated radius
  };
  renderer.dispose();
  renderer.forceContextLoss();
  return out;
}

/**
 * Builds `scene` at width × height with the pipeline (profile 'skin', footprint, 17 taps until
 * `measure` says otherwise) and the dense pass.
 * @param {{ scene: string, width: number, height: number, float?: boolean, widthMm?: number, tiltDeg?: number }} options
 *   float: float targets everywhere (the dense test), else half float as in the demo; widthMm: the
 *   materials' scattering width instead of the scene's (small test images with wide kernels);
 *   tiltDeg: the grazing plane's tilt (default 75°)
 */
async function open({ scene, width, height, float = false, widthMm, tiltDeg }) {
  close();
  const renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping; // what OutputPass applies: the SSIM's input
  const built = await buildScene(scene, { aspect: width / height, tiltDeg });
  const type = float ? FloatType : HalfFloatType;
  const sss = new SubsurfaceScattering({
    scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: built.worldUnitInMm, type,
  });
  for (const material of built.subsurface) sss.makeSubsurface(material, { widthMm: widthMm ?? built.widthMm });
  const size = renderer.getDrawingBufferSize(new Vector2());
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(size.x, size.y, { type }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  const timer = new GpuStageTimer(renderer);
  timer.recording = false;
  sss.stageTimer = timer;
  const ldr = new WebGLRenderTarget(width, height, { type: UnsignedByteType });
  session = {
    scene, width, height, renderer, built, sss, timer, composer, ldr, outputPass: new OutputPass(), references: new Map(),
  };
  return { isStandIn: built.isStandIn, worldUnitInMm: built.worldUnitInMm };
}

function close() {
  if (!session) return;
  const { sss, composer, ldr, outputPass, renderer, timer } = session;
  timer.dispose();
  sss.dispose();
  composer.dispose();
  ldr.dispose();
  outputPass.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  session = null;
}

/** Renders one frame; reads the linear output and its tone-mapped 8-bit image. */
async function renderImages() {
  const { renderer, composer, ldr, outputPass, width, height } = session;
  composer.render();
  const linear = await readRenderTargetFloats(renderer, composer.readBuffer);
  outputPass.render(renderer, ldr, composer.readBuffer);
  const toneMapped = new Uint8Array(width * height * 4);
  await renderer.readRenderTargetPixelsAsync(ldr, 0, 0, width, height, toneMapped);
  return { linear, toneMapped };
}

/** Largest on-screen radius of `radiusMm` over the subsurface pixels, from the surface read-back. */
function radiusPixels(surface, radiusMm) {
  const { width, height, built } = session;
  const p = built.camera.projectionMatrix.elements;
  let largest = 0;
  for (let i = 0; i < width * height; i++) {
    const widthWorld = surface[i * 4 + 1];
    if (!(widthWorld > 0)) continue;
    const depth = surface[i * 4];
    largest = Math.max(largest, radiusMm * pixelsPerMm(widthWorld, depth, p[0], width), radiusMm * pixelsPerMm(widthWorld, depth, p[5], height));
  }
  return largest;
}

/** The pipeline's profile (the scene split's transmittance, the blur and the dense reference). */
function useProfile(profile) {
  const { sss } = session;
  if (sss.profileLookup.profile.name !== profile) sss.setKernel({ profile });
}

/** The dense reference with `coverage` as the pipeline's blur stage. */
function useDense(coverage) {
  const { sss } = session;
  sss.setKernel({ method: 'dense' });
  sss.densePass.setCoverage(coverage);
  return sss.densePass;
}

/**
 * Renders the dense 2D reference once for `profile` (coverage 0.997) and keeps it for `measure`.
 * @returns {{ ms: number, radiusPx: number, subsurfacePixels: number }}
 */
async function reference({ profile, coverage = 0.997 }) {
  const { renderer, sss } = session;
  useProfile(profile);
  const dense = useDense(coverage);
  const t0 = performance.now();
  const images = await renderImages();
  const ms = performance.now() - t0;
  const surface = await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 2);
  const mask = Float32Array.from({ length: session.width * session.height }, (_, i) => surface[i * 4 + 1]);
  const radiusPx = radiusPixels(surface, dense.radiusMm);
  const bound = dense.uniforms.maxRadiusPx.value;
  if (radiusPx >= bound) throw new RangeError(`reference: the kernel reaches ${radiusPx.toFixed(0)} px, beyond the dense pass's bound ${bound}`);
  session.references.set(profile, { ...images, mask, coverage });
  return { ms, radiusPx, radiusMm: dense.radiusMm, subsurfacePixels: mask.filter((m) => m > 0).length };
}

/** Renders `count` whole frames with a 1-pixel read-back fence each; returns their wall times. */
function timeFrames(count) {
  const { renderer, composer } = session;
  const pixel = composer.readBuffer.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  const ms = [];
  for (let i = 0; i < count; i++) {
    const t0 = performance.now();
    composer.render();
    renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel);
    ms.push(performance.now() - t0);
  }
  return ms;
}

/** Re-runs only the SSS stage over the frame's scene split `count` times (the stage timer times each). */
function timeSssStage(count) {
  const { renderer, sss } = session;
  const pixel = sss.scatteredTarget.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  const ms = [];
  for (let i = 0; i < count; i++) {
    const t0 = performance.now();
    sss.renderScattering(renderer);
    renderer.readRenderTargetPixels(sss.scatteredTarget, 0, 0, 1, 1, pixel);
    ms.push(performance.now() - t0);
  }
  return ms;
}

/** The SSS stage's GPU time of each frame or re-run: blurH + blurV, or dense. */
function sssTimes(times) {
  const out = [];
  let horizontal = 0;
  for (const { stage, ms } of times) {
    if (stage === 'blurH') horizontal = ms;
    else if (stage === 'blurV') out.push(horizontal + ms);
    else if (stage === 'dense') out.push(ms);
  }
  return out;
}

/**
 * Sets the pipeline to one setting and measures it: its error against the reference of its
 * profile (when `errors`), then its times. Returns the raw times so that the runner can pool the
 * samples of several rounds.
 * @param {object} o
 * @param {'separable'|'dense'} o.kind
 * @param {string} o.profile
 * @param {string} [o.method] 'footprint', 'marginal', 'reference' (separable)
 * @param {number|'auto'} [o.samples] 'auto': the module's choice (SubsurfaceScattering's samples 'auto')
 * @param {number} [o.coverage] dense only
 * @param {number} o.frames whole frames timed (each also gives a timer query)
 * @param {number} o.sssFrames SSS-only re-runs timed
 * @param {boolean} [o.errors=true] compare with the reference (this frame also compiles the shaders)
 * @param {boolean} [o.warmUp=true] without `errors`: render one untimed frame first
 */
async function measure({ kind, profile, method, samples, coverage, frames, sssFrames, errors = true, warmUp = true }) {
  const { sss, composer, timer, width, height } = session;
  useProfile(profile);
  const row = { kind, profile };
  if (kind === 'dense') {
    const dense = useDense(coverage);
    Object.assign(row, { method: 'dense', samples: null, coverage, radiusMm: dense.radiusMm });
  } else {
    // 'auto': the module picks the taps from the on-screen kernel size when the frame starts.
    const auto = samples === 'auto';
    sss.setKernel({ method, samples });
    if (auto) composer.render();
    Object.assign(row, { method, samples: sss.kernel.length / 4, auto });
  }
  if (errors) {
    const ref = session.references.get(profile);
    if (!ref) throw new Error(`measure: render the reference of ${profile} first`);
    const images = await renderImages();
    const e = radianceErrors(images.linear, ref.linear, ref.mask);
    Object.assign(row, { rmse: e.rmse, maxError: e.maxError, psnr: e.psnr });
    row.ssim = maskedSsim(images.toneMapped, ref.toneMapped, ref.mask, width, height);
  } else if (warmUp) {
    timeFrames(1);
  }
  row.kernelPixels = sss.kernelPixels;
  timer.recording = true;
  try {
    const frameMs = timeFrames(frames);
    const sssWallMs = timeSssStage(sssFrames);
    await nextTask();
    row.times = { frameMs, sssWallMs, gpuMs: sssTimes(await timer.collect()) };
  } finally {
    timer.recording = false;
  }
  return row;
}

/**
 * The images the dense test compares with the float64 oracle: the scene split's diffuse light and
 * surface, and the dense stage's output alone (before the compose).
 */
async function readDense({ profile, coverage = 0.997, followSurface = 'drop', foreshortening = true }) {
  const { sss, composer, renderer, built, width, height } = session;
  useProfile(profile);
  const dense = useDense(coverage);
  sss.setFollowSurface(followSurface);
  sss.setForeshortening(foreshortening);
  composer.render();
  const p = built.camera.projectionMatrix.elements;
  return {
    width, height,
    output: await readRenderTargetFloats(renderer, sss.scatteredTarget),
    diffuse: await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 1),
    surface: await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 2),
    projectionScale: [p[0], p[5]],
    depthThresholdWorld: dense.depthThresholdWorld,
    followSurface: dense.followSurface,
    foreshortening: dense.foreshortening,
    glError: renderer.getContext().getError(),
  };
}

/**
 * Per-stage GPU times of whole frames of the pipeline as it stands, and of a plain three.js frame
 * (a RenderPass of the same scene into the same kind of composer), interleaved frame by frame.
 * @param {{ frames?: number }} [options]
 * @returns {Promise<{ stages: object, plainMs: number, frames: number }>} medians, ms
 */
async function breakdown({ frames = 9 } = {}) {
  const { renderer, built, composer, timer, sss } = session;
  const plain = new EffectComposer(renderer, composer.readBuffer.clone());
  plain.renderToScreen = false;
  plain.addPass(new RenderPass(built.scene, built.camera));
  plain.render();
  composer.render();
  await timer.collect();
  const times = [];
  timer.recording = true;
  try {
    for (let i = 0; i < frames; i++) {
      composer.render();
      timer.begin('plain');
      plain.render();
      timer.end('plain');
      await nextTask();
      times.push(...await timer.collect());
    }
  } finally {
    timer.recording = false;
    plain.renderTarget1.dispose();
    plain.renderTarget2.dispose();
  }
  const byStage = {};
  for (const { stage, ms } of times) (byStage[stage] ??= []).push(ms);
  const stages = Object.fromEntries(Object.entries(byStage).map(([stage, list]) => [stage, median(list)]));
  return { stages, frames, kernelPixels: sss.kernelPixels, samples: sss.kernel.length / 4 };
}

window.bench = { info, open, close, reference, measure, readDense, breakdown, drawChart };
window.testReady = true;
