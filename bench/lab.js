// The browser side of the speed-accuracy bench (bench/run.js drives it; test/browser/dense.test.js
// uses it too): `window.bench` builds a scene with the real pipeline, renders the dense 2D
// reference once per profile, then measures each setting's error against it and its time.
//
// Two composers share the pipeline's passes:
//   separable: [scene pass, ⟨timer⟩, horizontal blur, vertical blur, ⟨/timer⟩, compose]
//   dense:     [scene pass, ⟨timer⟩, DenseSubsurfacePass,              ⟨/timer⟩, compose]
// Times: `gpuMs` = EXT_disjoint_timer_query_webgl2 around the SSS passes only; `ms` = a whole
// composer.render() closed by a 1-pixel readPixels (the fence: gl.finish() does not wait in
// Chromium). The runner takes the medians over many frames (bench/run.js).
import {
  ACESFilmicToneMapping, FloatType, HalfFloatType, UnsignedByteType, Vector2, WebGLRenderer, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { SubsurfaceScattering, DenseSubsurfacePass, QuadrantEnergyLookup, AUTO_SAMPLES, AUTO_REACH } from '/src/index.js';
import { readRenderTargetFloats } from '/demo/readback.js';
import { radianceErrors, maskedSsim } from '/test/oracle/metrics.js';
import { buildScene } from './scenes.js';
import { drawChart } from './chart.js';

/** The dense pass's loop bound; a reference whose radius reaches it is refused. */
const MAX_RADIUS_PX = 160;

const lookups = new Map();
/** One QuadrantEnergyLookup per profile for the whole page (building one takes a few 100 ms). */
function energyLookup(profile) {
  if (!lookups.has(profile)) lookups.set(profile, new QuadrantEnergyLookup(profile));
  return lookups.get(profile);
}

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

/** Timer queries around a span of passes; results are read once control returns to the browser. */
class GpuTimer {
  constructor(gl) {
    this.gl = gl;
    this.ext = gl.getExtension('EXT_disjoint_timer_query_webgl2');
    this.recording = false;
    this.active = null;
    this.pending = [];
  }

  begin() {
    if (!this.ext || !this.recording) return;
    this.active = this.gl.createQuery();
    this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, this.active);
  }

  end() {
    if (!this.active) return;
    this.gl.endQuery(this.ext.TIME_ELAPSED_EXT);
    this.pending.push(this.active);
    this.active = null;
  }

  /** Milliseconds of every query since the last call (none if the extension is missing or disjoint). */
  async collect() {
    const { gl, pending } = this;
    this.pending = [];
    if (!this.ext || pending.length === 0) return [];
    for (let tries = 0; tries < 2000; tries++) {
      if (gl.getQueryParameter(pending[pending.length - 1], gl.QUERY_RESULT_AVAILABLE)) break;
      await nextTask();
    }
    const disjoint = gl.getParameter(this.ext.GPU_DISJOINT_EXT);
    const ms = pending.map((q) => gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6);
    for (const q of pending) gl.deleteQuery(q);
    return disjoint ? [] : ms;
  }
}

/** A pass that only starts or stops the timer (no drawing, no swap). */
class TimerMark extends Pass {
  constructor(timer, edge) {
    super();
    this.needsSwap = false;
    this.timer = timer;
    this.edge = edge;
  }

  render() {
    if (this.edge === 'begin') this.timer.begin();
    else this.timer.end();
  }
}

function makeComposer(renderer, type, passes) {
  const size = renderer.getDrawingBufferSize(new Vector2());
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(size.x, size.y, { type }));
  composer.renderToScreen = false;
  for (const pass of passes) composer.addPass(pass);
  return composer;
}

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
 * @param {{ scene: string, width: number, height: number, float?: boolean, widthMm?: number }} options
 *   float: float targets everywhere (the dense test), else half float as in the demo; widthMm: the
 *   materials' scattering width instead of the scene's (small test images with wide kernels)
 */
async function open({ scene, width, height, float = false, widthMm }) {
  close();
  const renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping; // what OutputPass applies: the SSIM's input
  const built = await buildScene(scene, { aspect: width / height });
  const type = float ? FloatType : HalfFloatType;
  const sss = new SubsurfaceScattering({
    scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: built.worldUnitInMm, type,
  });
  for (const material of built.subsurface) sss.makeSubsurface(material, { widthMm: widthMm ?? built.widthMm });
  const dense = new DenseSubsurfacePass({
    camera: built.camera,
    surfaceTexture: sss.scenePass.surfaceTexture,
    diffuseTexture: sss.scenePass.diffuseTexture,
    energyLookup: energyLookup('skin'),
    followSurface: sss.followSurface,
    depthThresholdWorld: sss.horizontalPass.depthThresholdWorld,
    foreshortening: sss.horizontalPass.foreshortening,
    maxRadiusPx: MAX_RADIUS_PX,
  });
  const timer = new GpuTimer(renderer.getContext());
  const mark = (edge) => new TimerMark(timer, edge);
  const separable = makeComposer(renderer, type, [
    sss.scenePass, mark('begin'), sss.horizontalPass, sss.verticalPass, mark('end'), sss.composePass,
  ]);
  const denseComposer = makeComposer(renderer, type, [sss.scenePass, mark('begin'), dense, mark('end'), sss.composePass]);
  const ldr = new WebGLRenderTarget(width, height, { type: UnsignedByteType });
  session = {
    scene, width, height, renderer, built, sss, dense, timer, separable, denseComposer, ldr,
    outputPass: new OutputPass(), references: new Map(),
  };
  return { isStandIn: built.isStandIn, worldUnitInMm: built.worldUnitInMm };
}

function close() {
  if (!session) return;
  const { sss, dense, separable, denseComposer, ldr, outputPass, renderer } = session;
  sss.dispose();
  dense.dispose();
  separable.dispose();
  denseComposer.dispose();
  ldr.dispose();
  outputPass.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  session = null;
}

/** Renders one frame with `composer`; reads the linear output and its tone-mapped 8-bit image. */
async function renderImages(composer) {
  const { renderer, ldr, outputPass, width, height } = session;
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
    largest = Math.max(largest, (radiusMm * widthWorld * Math.max(p[0] * width, p[5] * height)) / (2 * depth));
  }
  return largest;
}

/** The pipeline's profile for both the scene pass (transmittance) and the dense pass. */
function useProfile(profile) {
  const { sss, dense } = session;
  if (sss.profileLookup.profile.name !== profile) sss.setKernel({ profile });
  if (dense.profile.name !== profile) dense.setProfile(energyLookup(profile));
}

/**
 * Renders the dense 2D reference once for `profile` (coverage 0.997) and keeps it for `measure`.
 * @returns {{ ms: number, radiusPx: number, subsurfacePixels: number }}
 */
async function reference({ profile, coverage = 0.997 }) {
  const { dense, renderer, denseComposer } = session;
  useProfile(profile);
  dense.setCoverage(coverage);
  const t0 = performance.now();
  const images = await renderImages(denseComposer);
  const ms = performance.now() - t0;
  const surface = await readRenderTargetFloats(renderer, session.sss.scenePass.renderTarget, 2);
  const mask = Float32Array.from({ length: session.width * session.height }, (_, i) => surface[i * 4 + 1]);
  const radiusPx = radiusPixels(surface, dense.radiusMm);
  if (radiusPx >= MAX_RADIUS_PX) throw new RangeError(`reference: the kernel reaches ${radiusPx.toFixed(0)} px, beyond the dense pass's bound ${MAX_RADIUS_PX}`);
  session.references.set(profile, { ...images, mask, coverage });
  return { ms, radiusPx, radiusMm: dense.radiusMm, subsurfacePixels: mask.filter((m) => m > 0).length };
}

/** Renders `count` whole frames with a 1-pixel read-back fence each; returns their wall times. */
function timeFrames(composer, count) {
  const { renderer } = session;
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

/** Re-runs only the SSS passes over the frame's scene targets `count` times, timed by the timer. */
function timeSssPasses(kind, count) {
  const { renderer, sss, dense, separable, denseComposer, timer } = session;
  const composer = kind === 'dense' ? denseComposer : separable;
  const pixel = composer.readBuffer.texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  const ms = [];
  for (let i = 0; i < count; i++) {
    const t0 = performance.now();
    timer.begin();
    if (kind === 'dense') {
      dense.render(renderer, composer.writeBuffer, composer.readBuffer);
    } else {
      sss.horizontalPass.render(renderer, composer.writeBuffer, composer.readBuffer);
      sss.verticalPass.render(renderer, composer.readBuffer, composer.writeBuffer);
    }
    timer.end();
    renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel);
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
  const { sss, dense, separable, denseComposer, timer, width, height } = session;
  useProfile(profile);
  let composer = separable;
  const row = { kind, profile };
  if (kind === 'dense') {
    dense.setCoverage(coverage);
    composer = denseComposer;
    Object.assign(row, { method: 'dense', samples: null, coverage, radiusMm: dense.radiusMm });
  } else {
    // 'auto': the module picks the taps from the on-screen kernel size when the frame starts.
    const auto = samples === 'auto';
    sss.setKernel({ method, samples });
    if (auto) separable.render();
    Object.assign(row, { method, samples: sss.kernel.length / 4, auto });
  }
  if (errors) {
    const ref = session.references.get(profile);
    if (!ref) throw new Error(`measure: render the reference of ${profile} first`);
    const images = await renderImages(composer);
    const e = radianceErrors(images.linear, ref.linear, ref.mask);
    Object.assign(row, { rmse: e.rmse, maxError: e.maxError, psnr: e.psnr });
    row.ssim = maskedSsim(images.toneMapped, ref.toneMapped, ref.mask, width, height);
  } else if (warmUp) {
    timeFrames(composer, 1);
  }
  row.kernelPixels = sss.kernelPixels;
  timer.recording = true;
  try {
    const frameMs = timeFrames(composer, frames);
    const sssWallMs = timeSssPasses(kind, sssFrames);
    await nextTask();
    row.times = { frameMs, sssWallMs, gpuMs: await timer.collect() };
  } finally {
    timer.recording = false;
  }
  return row;
}

/**
 * The images the dense test compares with the float64 oracle: the scene pass's diffuse light and
 * surface, and the dense pass's output alone (before compose).
 */
async function readDense({ profile, coverage = 0.997, followSurface = 'drop', foreshortening = true }) {
  const { sss, dense, denseComposer, renderer, built, width, height } = session;
  useProfile(profile);
  dense.setCoverage(coverage);
  dense.setFollowSurface(followSurface);
  dense.setForeshortening(foreshortening);
  sss.composePass.enabled = false;
  try {
    denseComposer.render();
  } finally {
    sss.composePass.enabled = true;
  }
  const p = built.camera.projectionMatrix.elements;
  return {
    width, height,
    output: await readRenderTargetFloats(renderer, denseComposer.readBuffer),
    diffuse: await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 1),
    surface: await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 2),
    projectionScale: [p[0], p[5]],
    depthThresholdWorld: dense.depthThresholdWorld,
    followSurface: dense.followSurface,
    foreshortening: dense.foreshortening,
    glError: renderer.getContext().getError(),
  };
}

window.bench = { info, open, close, reference, measure, readDense, drawChart };
window.testReady = true;
