// The browser side of the speed-accuracy bench (bench/run.js drives it; test/browser/3-blur/dense.test.js
// uses it too): `window.bench` builds a scene with the real pipeline in a real EffectComposer,
// renders the dense 2D reference once per profile (the pipeline's own, through internals' useDenseReference), then
// measures each setting's error against it and its time, all through the library's API.
//
// Times: `gpuMs` = EXT_disjoint_timer_query_webgl2 around the SSS stage (both blurs, or the dense
// pass), from the pipeline's stage timer (dev/gpuTimer.js); `ms` = a whole composer.render()
// closed by a 1-pixel readPixels (the fence: gl.finish() does not wait in Chromium). The runner
// takes the medians over many frames (bench/run.js).
import {
  ACESFilmicToneMapping, FloatType, HalfFloatType, UnsignedByteType, Vector2, WebGLRenderer, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from '/src/index.js';
import { pixelsPerMm } from '/src/stages.js';
import { AUTO_SAMPLES, footprintTable, useDenseReference } from '/src/internals.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';
import { AUTO_STEP_ERROR, footprintRowOf } from '/src/profiles/footprints.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { GpuStageTimer, sssStageTimes } from '/dev/gpuTimer.js';
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
    autoSamples: AUTO_SAMPLES, // the tap levels 'auto' chooses from for the fixed-tap methods
    autoStepError: AUTO_STEP_ERROR, // 'footprint' with 'auto': per pixel the fewest taps within this step-edge error
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
  const { sss, composer, ldr, outputPass, renderer, timer, peers } = session;
  peers?.dispose();
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
  if (sss._profileLookup.profile.name !== profile) sss.profile = profile;
}

/** The dense reference with `coverage` as the pipeline's blur stage. */
function useDense(coverage) {
  const dense = useDenseReference(session.sss);
  dense.setCoverage(coverage);
  return dense;
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
  const surface = await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.SURFACE);
  const mask = Float32Array.from({ length: session.width * session.height }, (_, i) => surface[i * 4 + 1]);
  const radiusPx = radiusPixels(surface, dense.radiusMm);
  const bound = dense.uniforms.maxRadiusPx.value;
  if (radiusPx >= bound) throw new RangeError(`reference: the kernel reaches ${radiusPx.toFixed(0)} px, beyond the dense pass's bound ${bound}`);
  session.references.set(profile, { ...images, mask, coverage });
  return { ms, radiusPx, radiusMm: dense.radiusMm, subsurfacePixels: mask.filter((m) => m > 0).length };
}

/**
 * The taps per direction samples 'auto' allocates to the subsurface pixels of the last frame: per
 * pixel and axis, the footprint table's count for the row of the pixel's scale (the shader's row;
 * the grazing-angle correction can only lower the scale, so these are upper bounds).
 * @returns {Promise<{ mean: number, max: number, min: number }>} over pixels and both axes
 */
async function autoTaps() {
  const { renderer, sss, built, width, height } = session;
  const profile = sss._profileLookup.profile;
  session.autoTables ??= new Map();
  if (!session.autoTables.has(profile)) session.autoTables.set(profile, footprintTable((x) => sss._profileLookup.marginalEnergy(x), 'auto'));
  const { samples, data, columns } = session.autoTables.get(profile);
  const surface = await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.SURFACE);
  const p = built.camera.projectionMatrix.elements;
  let sum = 0, count = 0, max = 0, min = Infinity, centred = 0;
  for (let i = 0; i < width * height; i++) {
    const widthWorld = surface[i * 4 + 1];
    if (!(widthWorld > 0)) continue;
    for (const [scale, size] of [[p[0], width], [p[5], height]]) {
      const s = pixelsPerMm(widthWorld, surface[i * 4], scale, size);
      const row = footprintRowOf(s);
      const taps = samples[row];
      sum += taps;
      count++;
      max = Math.max(max, taps);
      min = Math.min(min, taps);
      // Footprints one pixel wide, snapped as the shader snaps them: their two taps sit on texel
      // centres (one texel fetched each).
      for (let k = 0, lastEdge = 0; k < (taps - 1) / 2; k++) {
        const edgeMm = data[2 * (row * columns + k)];
        if (!Number.isFinite(edgeMm)) break; // the tail
        const edge = Math.max(Math.floor(edgeMm * s + 0.5), lastEdge + 1);
        if (edge === lastEdge + 1) centred += 2;
        lastEdge = edge;
      }
    }
  }
  return { mean: sum / count, max, min, centredMean: centred / count };
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
  const pixel = sss._blur.scatteredTarget.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  const ms = [];
  for (let i = 0; i < count; i++) {
    const t0 = performance.now();
    sss._renderScattering(renderer);
    renderer.readRenderTargetPixels(sss._blur.scatteredTarget, 0, 0, 1, 1, pixel);
    ms.push(performance.now() - t0);
  }
  return ms;
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
    // 'auto': 'footprint' picks per pixel; the fixed-tap methods per frame, when the frame starts.
    const auto = samples === 'auto';
    useDenseReference(sss, false);
    Object.assign(sss, { method, samples });
    if (auto) composer.render();
    const perPixel = auto && method === 'footprint';
    Object.assign(row, { method, samples: perPixel ? 'auto' : sss._blur.kernel.length / 4, auto });
    if (perPixel) row.taps = await autoTaps();
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
  row.kernelPixels = sss.plan.kernelPixels;
  timer.recording = true;
  try {
    const frameMs = timeFrames(frames);
    const sssWallMs = timeSssStage(sssFrames);
    await nextTask();
    row.times = { frameMs, sssWallMs, gpuMs: sssStageTimes(await timer.collect()) };
  } finally {
    timer.recording = false;
  }
  return row;
}

/**
 * Re-runs the SSS stage of the current setting `count` times over the last frame's scene split,
 * timed by the stage timer (bench/run.js reads the GPU process's CPU clock around this call).
 * @returns {Promise<{ gpuMs: number[], sssWallMs: number[] }>}
 */
async function timeSss({ count }) {
  const { timer } = session;
  timer.recording = true;
  try {
    const sssWallMs = timeSssStage(count);
    await nextTask();
    return { gpuMs: sssStageTimes(await timer.collect()), sssWallMs };
  } finally {
    timer.recording = false;
  }
}

/**
 * The images the dense test compares with the float64 oracle: the scene split's diffuse light and
 * surface, and the dense stage's output alone (before the compose).
 */
async function readDense({ profile, coverage = 0.997, followSurface = 'drop', foreshortening = true }) {
  const { sss, composer, renderer, built, width, height } = session;
  useProfile(profile);
  const dense = useDense(coverage);
  Object.assign(sss, { followSurface, foreshortening });
  composer.render();
  const p = built.camera.projectionMatrix.elements;
  return {
    width, height,
    output: await readRenderTargetFloats(renderer, sss._blur.scatteredTarget),
    diffuse: await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.DIFFUSE),
    surface: await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.SURFACE),
    projectionScale: [p[0], p[5]],
    depthThresholdWorld: dense.depthThresholdWorld,
    followSurface: dense.followSurface,
    foreshortening: dense.foreshortening,
    glError: renderer.getContext().getError(),
  };
}

/** The peers of the open head scene (bench/peers.js), built on first use: Babylon.js loads only then. */
async function peersOf() {
  if (!session.built.rig) throw new Error(`peers: only the head scene has them, not ${session.scene}`);
  if (!session.peers) {
    const { openPeers } = await import('./peers.js');
    session.peers = await openPeers(session);
  }
  return session.peers;
}

/** Each engine's image, plain and with its SSS, tone-mapped 8-bit (see bench/peers.js's peerImages). */
async function peerImages() {
  const { peerImages: images } = await import('./peers.js');
  return images(await peersOf(), session);
}

/** The floor pass's input and output (bench/peers.js's floorImages). */
async function peerFloorImages() {
  const { floorImages } = await import('./peers.js');
  return floorImages(await peersOf(), session);
}

/** A few timed frames of one peer measure (bench/peers.js's peerMeasure); bench/run.js interleaves them. */
async function peerMeasure(options) {
  const { peerMeasure: measurePeer } = await import('./peers.js');
  return measurePeer(await peersOf(), session, options);
}

/**
 * What the cost model (bench/costModel.js) needs of the frame of ours the side-by-side times: its
 * subsurface pixels (the diffuse alpha), the pixels of their screen box (the blur's scissor) and
 * the taps 'auto' allocates there.
 * @returns {Promise<{ pixels: number, subsurfacePixels: number, boxPixels: number, box: object|null, taps: object }>}
 */
async function peerCoverage() {
  const { renderer, sss, width, height } = session;
  (await peersOf()).draw.ours();
  const diffuse = await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, ATTACHMENTS.DIFFUSE);
  let subsurfacePixels = 0;
  for (let i = 3; i < diffuse.length; i += 4) if (diffuse[i] > 0) subsurfacePixels++;
  const box = sss._scenePass.subsurfaceBox;
  return { pixels: width * height, subsurfacePixels, boxPixels: box ? box.width * box.height : width * height, box, taps: await autoTaps() };
}

/** The memory the pipeline allocates with `options` (bench/memory.js), on a renderer of its own. */
async function memory(options) {
  const { measureMemory } = await import('./memory.js');
  return measureMemory(options);
}

window.bench = { info, open, close, reference, measure, readDense, timeSss, peerImages, peerFloorImages, peerMeasure, peerCoverage, drawChart, memory };
window.testReady = true;
