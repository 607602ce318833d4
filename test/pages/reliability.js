// The browser side of the reliability suite (test/browser/reliability.test.js) and of the long soak
// (npm run soak, scripts/soak.js), on `window.reliability`:
//   badInputs()          runs every line of test/reliability/badInputs.js, returns what each gave
//   cycles({ count })    create → render → dispose cycles; live WebGL objects and renderer.info
//   soakStart(options), soakRun(frames), soakStop()   frames with option changes and a moving
//                        camera and light: GL errors, NaN pixels, live objects
//   contextLoss()        the same frame before a WebGL context loss and after the restore
// reliability.html counts the live WebGL objects (glObjects.js) before this module runs. Nothing
// here is part of the library.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import * as SSS from '/test/harness/sss.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { ALL_CASES, CALL_CASES } from '/test/reliability/badInputs.js';
import { createFixture } from '/test/reliability/fixture.js';

const WIDTH = 64;
const HEIGHT = 36;

function createRenderer(width = WIDTH, height = HEIGHT) {
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  return renderer;
}

const fixtureOn = (renderer, options) => createFixture(THREE, SSS, { renderer, EffectComposer, read: readRenderTargetFloats, ...options });

/** Runs `fn` with console.warn collected (and not printed): [result or error, warnings]. */
async function collectingWarnings(fn) {
  const warnings = [];
  const warn = console.warn;
  console.warn = (...args) => warnings.push(args.map(String).join(' '));
  try {
    return [await fn(), warnings];
  } finally {
    console.warn = warn;
  }
}

/** Every line of the bad-input table, in the table's order: { input, error, warnings, frame, glError }. */
async function badInputs() {
  const renderer = createRenderer(48, 27);
  const gl = renderer.getContext();
  // Kept alive meanwhile so that three keeps the pipeline's programs: each case's first frame
  // then compiles nothing.
  const keeper = fixtureOn(renderer);
  await keeper.frame();
  const results = [];
  for (let i = 0; i < ALL_CASES.length; i++) {
    const [input, run] = ALL_CASES[i];
    const needsFrame = i >= CALL_CASES.length;
    const t = fixtureOn(renderer);
    gl.getError(); // clear
    const [outcome, warnings] = await collectingWarnings(async () => {
      try {
        await run(t);
        return { frame: needsFrame ? await t.frame() : null };
      } catch (e) {
        return { error: { name: e?.constructor?.name, message: String(e?.message ?? e) } };
      }
    });
    const glError = gl.getError();
    try { t.dispose(); } catch (e) { outcome.disposeError = e.message; }
    results.push({ input, ...outcome, warnings, glError });
  }
  keeper.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  return results;
}

/** What the renderer holds: live WebGL objects by kind, three's memory counters and programs. */
function holdings(renderer) {
  return {
    gl: window.glObjects.live(),
    total: window.glObjects.total(),
    memory: { ...renderer.info.memory },
    programs: renderer.info.programs.length,
  };
}

/**
 * `count` cycles on one renderer: a pipeline (the cycle's method; MSAA every other cycle; the
 * dense reference every fourth), its composer, two frames, then everything disposed. The first
 * cycle warms three's own lazily made objects; the baseline is taken after it.
 */
async function cycles({ count = 20 } = {}) {
  const renderer = createRenderer();
  const gl = renderer.getContext();
  const errors = [];
  const cycle = async (i) => {
    const t = fixtureOn(renderer, { width: WIDTH, height: HEIGHT });
    t.usePipeline({ method: SSS.METHODS[i % SSS.METHODS.length], multisampling: i % 2 ? 4 : 0 });
    if (i % 4 === 3) SSS.useDenseReference(t.sss);
    t.sss.debugView = i % 3 === 0 ? 'final' : 'transmittance';
    const frame = await t.frame();
    t.dispose();
    const error = gl.getError();
    if (error || frame.nonFinite) errors.push({ cycle: i, error, nonFinite: frame.nonFinite });
  };
  await cycle(0);
  const baseline = holdings(renderer);
  const during = [];
  const t0 = performance.now();
  for (let i = 1; i <= count; i++) {
    await cycle(i);
    if (i % 10 === 0 || i === count) during.push({ cycle: i, total: window.glObjects.total() });
  }
  const ms = performance.now() - t0;
  const after = holdings(renderer);
  renderer.dispose();
  renderer.forceContextLoss();
  return { count, baseline, after, during, errors, msPerCycle: ms / count };
}

// The soak: one pipeline, frames with the camera and the light moving, and every `every` frames
// the next option change. The changes go round in a cycle that ends where it began (the last one
// resets), so the state after each full cycle is the same: what is held then must not grow.
const CHANGES = [
  (s) => { s.sss.method = 'marginal'; },
  (s) => Object.assign(s.sss, { method: 'footprint', samples: 9 }), // a footprint table of another width
  (s) => { s.sss.profile = 'marble'; },
  (s) => Object.assign(s.sss, { followSurface: 'lerp', depthThresholdMm: 4 }),
  (s) => { s.sss.debugView = 'diffuse'; },
  (s) => { s.sss.split = 0.5; },
  (s) => { s.sss.scattering = false; },
  (s) => { s.sss.transmittance = false; },
  (s) => { s.sss.multisampling = 4; },
  (s) => s.composer.setSize(WIDTH + 16, HEIGHT + 9),
  (s) => { s.sss.foreshortening = false; },
  (s) => s.sss._lightDepth.setSize(32),
  (s) => s.sss.makeSubsurface(s.material, { widthMm: 8, translucency: 0.3 }),
  (s) => Object.assign(s.sss, { profile: 'skinBurley', method: 'reference', samples: 'auto' }),
  (s) => { s.sss.debugView = 'thickness'; },
  (s) => { s.sss.profile = 'skin'; SSS.useDenseReference(s.sss); },
  (s) => { s.sss.worldUnitInMm = 50; },
  (s) => { s.sss.clear = false; },
  (s) => { s.sss.transmittance = true; },
  (s) => {
    const { sss } = s;
    SSS.useDenseReference(sss, false);
    Object.assign(sss, { method: 'footprint', samples: 'auto', profile: 'skin', followSurface: 'drop', depthThresholdMm: 6, debugView: 'final', split: 0 });
    sss.scattering = true;
    sss.multisampling = 'auto';
    s.composer.setSize(WIDTH, HEIGHT);
    sss.foreshortening = true;
    sss._lightDepth.setSize(64);
    sss.makeSubsurface(s.material, { widthMm: 5, translucency: 0 });
    sss.worldUnitInMm = 100;
    sss.clear = true;
  },
];

let soak = null;

/** Sets the soak up: { every } frames between option changes (a full cycle is CHANGES.length × every). */
function soakStart({ every = 25 } = {}) {
  if (soak) soakStop();
  const renderer = createRenderer();
  const t = fixtureOn(renderer, { width: WIDTH, height: HEIGHT });
  t.composer.setSize(WIDTH, HEIGHT);
  soak = { renderer, gl: renderer.getContext(), t, every, frame: 0, changes: 0, glErrors: [], nonFinite: 0, reads: 0, problems: new Set() };
  return { cycleFrames: CHANGES.length * every, changes: CHANGES.length };
}

/** Runs `frames` more frames of the soak; every 10th checks for GL errors, every 50th reads the frame back. */
async function soakRun(frames) {
  const s = soak;
  const { t, gl } = s;
  for (let i = 0; i < frames; i++) {
    const f = s.frame++;
    if (f > 0 && f % s.every === 0) {
      CHANGES[s.changes % CHANGES.length](t);
      s.changes++;
    }
    const a = f * 0.013;
    t.camera.position.set(Math.sin(a) * 5, 0.4 * Math.sin(a / 3), Math.cos(a) * 5);
    t.camera.lookAt(0, 0, 0);
    t.camera.updateMatrixWorld();
    t.light.position.set(Math.sin(a + 2.6) * 3, 0.2 + 0.5 * Math.cos(a / 2), Math.cos(a + 2.6) * 3);
    t.composer.render();
    for (const p of t.sss.problems) s.problems.add(p);
    if (f % 10 === 9) {
      const error = gl.getError();
      if (error) s.glErrors.push({ frame: f, error });
    }
    if (f % 50 === 49) {
      const data = await readRenderTargetFloats(s.renderer, t.composer.readBuffer);
      for (let k = 0; k < data.length; k += 4) if (!(Number.isFinite(data[k]) && Number.isFinite(data[k + 1]) && Number.isFinite(data[k + 2]))) s.nonFinite++;
      s.reads++;
    }
  }
  return soakState();
}

function soakState() {
  const s = soak;
  return {
    frames: s.frame, changes: s.changes, glErrors: s.glErrors.slice(0, 10), glErrorCount: s.glErrors.length,
    nonFinite: s.nonFinite, reads: s.reads, problems: [...s.problems], ...holdings(s.renderer),
  };
}

function soakStop() {
  if (!soak) return null;
  const state = soakState();
  soak.t.dispose();
  soak.renderer.dispose();
  soak.renderer.forceContextLoss();
  soak = null;
  return state;
}

/** One frame, a WebGL context loss and restore (WEBGL_lose_context), the same frame again. */
async function contextLoss() {
  const renderer = createRenderer();
  const gl = renderer.getContext();
  const canvas = renderer.domElement;
  const t = fixtureOn(renderer, { width: WIDTH, height: HEIGHT });
  const read = async () => {
    t.composer.render();
    return readRenderTargetFloats(renderer, t.composer.readBuffer);
  };
  await read();
  const before = await read();
  const lose = gl.getExtension('WEBGL_lose_context');
  const lost = new Promise((resolve) => canvas.addEventListener('webglcontextlost', resolve, { once: true }));
  lose.loseContext();
  await lost;
  // The browser reads whether the event's default was prevented (three prevents it, which allows
  // a restore) after the listeners return: restore from a later task, not from this microtask.
  await new Promise((resolve) => setTimeout(resolve, 0));
  const lostFlag = gl.isContextLost();
  const restored = new Promise((resolve) => canvas.addEventListener('webglcontextrestored', resolve, { once: true }));
  lose.restoreContext();
  await restored;
  const after = await read();
  let differing = 0;
  let nonFinite = 0;
  let lit = 0;
  for (let i = 0; i < before.length; i++) {
    if (before[i] !== after[i]) differing++;
    if (!Number.isFinite(after[i])) nonFinite++;
  }
  for (let i = 0; i < after.length; i += 4) if (after[i] + after[i + 1] + after[i + 2] > 0.05) lit++;
  const glError = gl.getError();
  t.dispose();
  renderer.dispose();
  renderer.forceContextLoss();
  return { lostFlag, values: before.length, differing, nonFinite, litPixels: lit, glError };
}

window.reliability = { badInputs, cycles, soakStart, soakRun, soakState, soakStop, contextLoss, THREE, SSS };
window.testReady = true;
