// The bench's side-by-side (browser side; bench/lab.js's peerImages and peerMeasure): in one
// page and one Chromium, the head of the open session drawn four ways at the same resolution:
//   threePlain    three.js alone: a RenderPass in the same kind of composer
//   ours          the pipeline with its defaults (the session's composer)
//   babylonPlain  Babylon.js alone (bench/babylonHead.js)
//   babylonSss    Babylon.js with its prepass subsurface scattering
// plus the fetch-only floor of the blur (bench/floorPass.js) over the same frame's subsurface
// pixels. Every frame is timed with EXT_disjoint_timer_query_webgl2 around the whole frame (one
// query: the stages of ours are timed in frames of their own); bench/run.js interleaves the
// measures in rounds of a rotating order and reads the GPU process's CPU clock around each.
import { HalfFloatType, Mesh, MeshStandardMaterial, PlaneGeometry, SphereGeometry, WebGLRenderTarget } from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { GpuStageTimer } from '/dev/gpuTimer.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { createBabylonHead } from './babylonHead.js';
import { FetchFloor } from './floorPass.js';
import { FEATURES, PEER_MEASURES, STAGES, VARIANTS } from './peerPlan.js';

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));


/**
 * Builds the peers of `session` (bench/lab.js's: the head with the pipeline).
 * @param {object} session
 * @returns {Promise<object>} the peers, kept on the session until it closes
 */
export async function openPeers(session) {
  const { renderer, built, composer, width, height } = session;
  const plainComposer = (samples) => {
    const c = new EffectComposer(renderer, new WebGLRenderTarget(width, height, { type: HalfFloatType, samples }));
    c.renderToScreen = false;
    c.addPass(new RenderPass(built.scene, built.camera));
    return c;
  };
  const plain = plainComposer(0);
  const plainMsaa = plainComposer(4);
  const babylon = await createBabylonHead(built.rig, { width, height, worldUnitInMm: built.worldUnitInMm });
  const threeTimer = new GpuStageTimer(renderer);
  const babylonTimer = new GpuStageTimer({ getContext: () => babylon.gl });
  const floor = new FetchFloor(session.sss);
  const draw = {
    threePlain: () => (MSAA_FEATURES.includes(peers.feature) ? plainMsaa : plain).render(),
    ours: () => composer.render(),
    babylonPlain: () => babylon.plain.scene.render(),
    babylonSss: () => babylon.sss.scene.render(),
  };
  const timerOf = (variant) => (variant.startsWith('babylon') ? babylonTimer : threeTimer);
  // In front of the mouth and chin, half see-through: the transparent feature's object.
  const pane = new Mesh(new PlaneGeometry(3, 1.5), new MeshStandardMaterial({ color: 0x88aaff, transparent: true, opacity: 0.3 }));
  pane.position.set(0, -0.6, 3);
  // Below the head's cheeks, left and right: the two balls of the profile features, a marble and a
  // milk one (threeProfiles), or both in the head's skin (threeObjects: the same pixels, one profile).
  const ballGeometry = new SphereGeometry(1.1, 48, 32);
  const balls = [['marble', -4.2], ['milk', 4.2]].map(([profile, x]) => {
    const ball = new Mesh(ballGeometry, new MeshStandardMaterial({ color: 0xf2efe8, roughness: 0.35 }));
    ball.position.set(x, -2.6, 1.5);
    return { ball, profile };
  });
  const peers = {
    plain, plainMsaa, babylon, floor, draw, timerOf, threeTimer, babylonTimer, pane, balls,
    /** The feature on for this measure (FEATURES), or null. */
    feature: null,
    dispose() {
      threeTimer.dispose();
      babylonTimer.dispose();
      floor.dispose();
      for (const c of [plain, plainMsaa]) c.dispose();
      pane.geometry.dispose();
      pane.material.dispose();
      ballGeometry.dispose();
      for (const { ball } of balls) ball.material.dispose();
      babylon.dispose();
    },
  };
  return peers;
}

/** The additions switched on by a field (bench/peerPlan.js's ADDITIONS), as [object of the pipeline, field, value]. */
const ADDITION_SWITCHES = Object.freeze({
  isotropic: (sss) => [sss, 'kernelGroups', 'auto'],
});

/** The features measured with MSAA 4 in the scene split (and the plain frame in a 4-sample buffer). */
const MSAA_FEATURES = Object.freeze(['msaa4']);

/**
 * Turns `feature` on for the session's head (FEATURES) and returns what turns it off again.
 * msaa4: the scene split multisampled 4 times (the plain frame draws into a 4-sample buffer too);
 * transparent: a half see-through pane in front of the chin; isotropic: the blur in groups
 * (`kernelGroups: 'auto'`; the default is one kernel); threeProfiles: a marble and a milk ball
 * beside the head, each with its own profile (three in the frame), threeObjects: the same balls in
 * the head's profile.
 */
function applyFeature(peers, session, feature) {
  const { sss, built } = session;
  peers.feature = feature;
  const off = () => { peers.feature = null; };
  if (feature === null) return off;
  if (!FEATURES.includes(feature)) throw new RangeError(`peerMeasure: feature must be one of ${FEATURES.join(', ')}, got ${feature}`);
  if (MSAA_FEATURES.includes(feature)) sss.multisampling = 4;
  const msaaOff = MSAA_FEATURES.includes(feature) ? () => { sss.multisampling = 'auto'; off(); } : off;
  if (feature === 'msaa4') return msaaOff;
  if (feature === 'transparent') {
    built.scene.add(peers.pane);
    return () => { built.scene.remove(peers.pane); off(); };
  }
  if (feature === 'threeProfiles' || feature === 'threeObjects') {
    for (const { ball, profile } of peers.balls) {
      built.scene.add(ball);
      sss.makeSubsurface(ball.material, { widthMm: built.widthMm, ...(feature === 'threeProfiles' ? { profile } : {}) });
    }
    return () => {
      for (const { ball } of peers.balls) {
        sss.removeSubsurface(ball.material);
        built.scene.remove(ball);
      }
      off();
    };
  }
  const [object, field, value] = ADDITION_SWITCHES[feature](sss);
  const before = object[field];
  object[field] = value;
  return () => { object[field] = before; msaaOff(); };
}

/** Renders `variant` once with one timer query around the whole frame. */
function timedFrame(peers, session, variant) {
  const timer = peers.timerOf(variant);
  const { sss } = session;
  const stageTimer = sss.stageTimer;
  sss.stageTimer = null; // one query at a time: the whole frame's
  try {
    timer.begin(variant);
    peers.draw[variant]();
    timer.end(variant);
  } finally {
    sss.stageTimer = stageTimer;
  }
}

/** Runs `draw` `count` times with `timer` recording; returns the times it took, [{ stage, ms }]. */
async function recorded(timer, count, draw) {
  timer.recording = true;
  try {
    for (let i = 0; i < count; i++) draw();
    await nextTask();
    return await timer.collect(); // waits for the queries: the frames are done
  } finally {
    timer.recording = false;
  }
}

const msOf = (times, stage) => times.filter((t) => t.stage === stage).map((t) => t.ms);

/**
 * Renders `measure` `frames` times, each timed with EXT_disjoint_timer_query_webgl2, after `warmUp`
 * untimed frames:
 * - a variant (VARIANTS): whole frames, one query each;
 * - 'stages': whole frames of ours, each stage timed (its breakdown);
 * - 'blur': the pipeline's two blur passes re-run over the last frame's scene split;
 * - 'floor': the fetch-only floor's two passes over the same.
 * The times of the queries are known only once the frames are done, so when this returns the
 * GPU process has finished them (the runner reads its CPU clock around the timed call).
 * @param {object} peers from openPeers
 * @param {object} session bench/lab.js's
 * @param {{ measure: string, frames: number, warmUp?: number, feature?: string|null }} options
 *   feature: one of FEATURES on while it runs (see applyFeature)
 * @returns {Promise<Record<string, number[]>>} ms per frame: the variant's, each stage's, 'blur' or 'floor'
 */
export async function peerMeasure(peers, session, { measure, frames, warmUp = 0, feature = null }) {
  if (!PEER_MEASURES.includes(measure)) throw new RangeError(`peerMeasure: measure must be one of ${PEER_MEASURES.join(', ')}, got ${measure}`);
  const off = applyFeature(peers, session, feature);
  try {
    return await measured(peers, session, { measure, frames, warmUp });
  } finally {
    off();
  }
}

/**
 * Waits until the GPU process has drawn everything asked of it so far (a 1-pixel read-back of the
 * engine that drew), so that warm-up frames do not spill into the timed call's CPU clock.
 */
function fence(peers, session, measure) {
  if (measure.startsWith('babylon')) {
    const { gl } = peers.babylon;
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return;
  }
  const target = measure === 'threePlain' ? (MSAA_FEATURES.includes(peers.feature) ? peers.plainMsaa : peers.plain).readBuffer
    : measure === 'blur' ? session.sss._blur.scatteredTarget
      : measure === 'floor' ? peers.floor.targets[1] : session.composer.readBuffer;
  session.renderer.readRenderTargetPixels(target, 0, 0, 1, 1, new Uint16Array(4)); // half-float targets
}

async function measured(peers, session, { measure, frames, warmUp }) {
  if (warmUp > 0) {
    await warmedUp(peers, session, { measure, warmUp });
    fence(peers, session, measure);
  }
  if (frames === 0) return {};
  return timed(peers, session, { measure, frames });
}

function warmedUp(peers, session, { measure, warmUp }) {
  const { renderer, sss } = session;
  const draw = VARIANTS.includes(measure) ? peers.draw[measure]
    : measure === 'stages' ? peers.draw.ours
      : measure === 'blur' ? () => sss._renderScattering(renderer) : () => peers.floor.render(renderer, { begin() {}, end() {} });
  for (let i = 0; i < warmUp; i++) draw();
}

async function timed(peers, session, { measure, frames }) {
  const { renderer, sss, timer: stageTimer } = session;
  if (VARIANTS.includes(measure)) {
    const times = await recorded(peers.timerOf(measure), frames, () => timedFrame(peers, session, measure));
    return { [measure]: msOf(times, measure) };
  }
  if (measure === 'stages') {
    const times = await recorded(stageTimer, frames, () => peers.draw.ours());
    return Object.fromEntries(STAGES.map((stage) => [stage, msOf(times, stage)]));
  }
  const run = measure === 'blur' ? () => sss._renderScattering(renderer) : () => peers.floor.render(renderer, stageTimer);
  const times = await recorded(stageTimer, frames, run);
  const [first, second] = measure === 'blur' ? ['blurH', 'blurV'] : ['floorH', 'floorV'];
  const a = msOf(times, first);
  const b = msOf(times, second);
  return { [measure]: a.map((ms, i) => ms + b[i]) };
}

/** Reads the tone-mapped 8-bit image a three.js composer holds (OutputPass: ACES, sRGB). */
async function threeImage(session, composer) {
  const { renderer, outputPass, ldr, width, height } = session;
  outputPass.render(renderer, ldr, composer.readBuffer);
  const pixels = new Uint8Array(width * height * 4);
  await renderer.readRenderTargetPixelsAsync(ldr, 0, 0, width, height, pixels);
  return pixels;
}

/** Reads Babylon's canvas (its image processing: ACES, sRGB), rows bottom-up as three's. */
function babylonImage(peers, session) {
  const { gl } = peers.babylon;
  const pixels = new Uint8Array(session.width * session.height * 4);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.readPixels(0, 0, session.width, session.height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return pixels;
}

/** Pixels that differ from the background (the image's corner) by more than 8/255 in a channel. */
function foreground(pixels) {
  const mask = new Uint8Array(pixels.length / 4);
  for (let i = 0; i < mask.length; i++) {
    let d = 0;
    for (let c = 0; c < 3; c++) d = Math.max(d, Math.abs(pixels[i * 4 + c] - pixels[c]));
    mask[i] = d > 8 ? 1 : 0;
  }
  return mask;
}

const luma = (p, i) => 0.2126 * p[i * 4] + 0.7152 * p[i * 4 + 1] + 0.0722 * p[i * 4 + 2];

/**
 * The two plain frames against each other: how much of the head's silhouette they share
 * (intersection over union of their foregrounds) and the ratio of their mean 8-bit luma there.
 */
function compareFrames(a, b) {
  const ma = foreground(a);
  const mb = foreground(b);
  let both = 0, either = 0, lumaA = 0, lumaB = 0;
  for (let i = 0; i < ma.length; i++) {
    if (ma[i] || mb[i]) either++;
    if (!(ma[i] && mb[i])) continue;
    both++;
    lumaA += luma(a, i);
    lumaB += luma(b, i);
  }
  return { silhouetteIoU: either > 0 ? both / either : NaN, lumaRatio: lumaB / lumaA, meanLuma: [lumaA / both, lumaB / both] };
}

/** How much an engine's SSS changes its frame: the mean |difference| of 8-bit luma over the head. */
function change(plain, withSss) {
  const mask = foreground(plain);
  let sum = 0, n = 0;
  for (let i = 0; i < mask.length; i++) {
    if (!mask[i]) continue;
    sum += Math.abs(luma(withSss, i) - luma(plain, i));
    n++;
  }
  return sum / n;
}

/** Images side by side as one PNG (rows bottom-up in, top-down out), each with its caption. */
function sideBySide(images, captions, width, height) {
  const canvas = document.createElement('canvas');
  canvas.width = images.length * width;
  canvas.height = height;
  const ctx = canvas.getContext('2d');
  images.forEach((pixels, k) => {
    const data = new ImageData(width, height);
    for (let y = 0; y < height; y++) data.data.set(pixels.subarray((height - 1 - y) * width * 4, (height - y) * width * 4), y * width * 4);
    const x0 = k * width;
    ctx.putImageData(data, x0, 0);
    ctx.font = `${Math.round(height / 22)}px sans-serif`;
    ctx.fillStyle = '#ffffff';
    ctx.fillText(captions[k], x0 + 8, height / 14);
  });
  return canvas.toDataURL('image/png');
}

/**
 * Each engine's image, plain and with its SSS, and how well the two plain frames agree.
 * @returns {Promise<{ png: { three: string, babylon: string }, plain: object, withSss: object, sssChange: object }>}
 *   png: per engine, its plain frame and its SSS frame side by side (data URLs)
 */
export async function peerImages(peers, session) {
  const { width, height } = session;
  peers.draw.threePlain();
  const threePlain = await threeImage(session, peers.plain);
  peers.draw.ours();
  const ours = await threeImage(session, session.composer);
  peers.draw.babylonPlain();
  const babylonPlain = babylonImage(peers, session);
  peers.draw.babylonSss();
  const babylonSss = babylonImage(peers, session);
  return {
    png: {
      three: sideBySide([threePlain, ours], ['three.js, plain', 'three.js + three-separable-sss (defaults)'], width, height),
      babylon: sideBySide([babylonPlain, babylonSss], ['Babylon.js, plain', 'Babylon.js + its prepass SSS'], width, height),
    },
    plain: compareFrames(threePlain, babylonPlain),
    withSss: compareFrames(ours, babylonSss),
    sssChange: { three: change(threePlain, ours), babylon: change(babylonPlain, babylonSss) },
  };
}

/**
 * The floor's input and output over the last frame of ours (the bench test checks the floor
 * against a box filter computed from the input): the diffuse attachment and both passes' output.
 */
export async function floorImages(peers, session) {
  const { renderer, sss } = session;
  peers.draw.ours();
  peers.floor.render(renderer, { begin() {}, end() {} });
  return {
    width: session.width,
    height: session.height,
    diffuse: await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, 1),
    horizontal: await readRenderTargetFloats(renderer, peers.floor.targets[0]),
    output: await readRenderTargetFloats(renderer, peers.floor.targets[1]),
  };
}
