// The browser side of test/browser/stability.test.js and bench/stability.js: the demo's head
// dollied towards its face, each frame read back as the scattering signal s (the output minus the
// same frame's unscattered light: the colour and diffuse attachments summed) and that unscattered
// image, float. Nothing here is part of the library.
import { FACE_CENTRE, HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';
import { headRig } from './headRig.js';
import '/test/pages/lab.js';

let rig = null;

/**
 * One pipeline over the head at `width` × `height` (float buffers: s near the skip is small),
 * `fovDeg` zooming in, the light `lightAzimuthDeg` round from the camera (from the side: more
 * light crosses shadow edges, more to scatter).
 */
async function open({ width, height, fovDeg, lightAzimuthDeg = 30, sss = {} }) {
  close();
  const { THREE, SSS, createRenderer, createComposer } = window.lab;
  const renderer = createRenderer(width, height);
  const head = await headRig(width / height, fovDeg);
  setLightDirection(head, lightAzimuthDeg, 25);
  head.camera.far = 2000; // the dolly goes far
  head.camera.updateProjectionMatrix();
  const pipeline = new SSS.SubsurfaceScattering({
    scene: head.scene, camera: head.camera, light: head.light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, type: THREE.FloatType, ...sss,
  });
  pipeline.makeSubsurface(head.head.material);
  const composer = createComposer(renderer, { type: THREE.FloatType });
  composer.addPass(pipeline);
  const direction = head.camera.position.clone().sub(FACE_CENTRE).normalize();
  rig = { renderer, composer, pipeline, head, direction, isStandIn: head.isStandIn };
  composer.render(); // compiles, and the scene pass learns its meshes
  return { isStandIn: head.isStandIn };
}

/** The camera `distance` world units from the face centre on the demo's line of sight, looking at it. */
function place(distance) {
  const { camera } = rig.head;
  camera.position.copy(FACE_CENTRE).addScaledVector(rig.direction, distance);
  camera.lookAt(FACE_CENTRE);
  camera.updateMatrixWorld();
}

/** The frame plan's scale (pixels per profile mm) with the camera at `distance`: no rendering. */
function pixelsPerMmAt(distance) {
  place(distance);
  return rig.pipeline._pixelsPerMm();
}

/** The distance at which the plan's scale is `pixelsPerMm` (it falls with the distance): bisection. */
function distanceFor(pixelsPerMm, near = 1.5, far = 1500) {
  let [a, b] = [near, far];
  for (let i = 0; i < 80; i++) {
    const mid = Math.sqrt(a * b);
    if (pixelsPerMmAt(mid) > pixelsPerMm) a = mid;
    else b = mid;
  }
  return Math.sqrt(a * b);
}

/** One frame at `distance`: s and the unscattered image as RGB floats, and the plan. */
async function frame(distance) {
  const { renderer, composer, pipeline } = rig;
  place(distance);
  composer.render();
  const { read } = window.lab;
  const output = await read(renderer, composer.readBuffer);
  const target = pipeline._scenePass.renderTarget;
  const colour = await read(renderer, target, ATTACHMENTS.COLOR);
  const diffuse = await read(renderer, target, ATTACHMENTS.DIFFUSE);
  const pixels = output.length / 4;
  const s = new Float32Array(pixels * 3);
  const unscattered = new Float32Array(pixels * 3);
  for (let p = 0; p < pixels; p++) {
    for (let c = 0; c < 3; c++) {
      const u = colour[p * 4 + c] + diffuse[p * 4 + c];
      unscattered[p * 3 + c] = u;
      s[p * 3 + c] = output[p * 4 + c] - u;
    }
  }
  const { groupings, ...plan } = pipeline.plan;
  return { s, unscattered, plan, glError: renderer.getContext().getError() };
}

/**
 * The mean |value| over the values that are not 0, the largest tenth left out: a change of the
 * whole face counts, the pixels that pop on their own (a footprint edge snapping to the next
 * pixel, a slope estimate switching) do not.
 */
function trimmedMean(values) {
  const magnitudes = Float32Array.from(values, Math.abs).filter((v) => v > 0).sort();
  const kept = magnitudes.subarray(0, Math.floor(magnitudes.length * 0.9));
  return kept.reduce((sum, v) => sum + v, 0) / Math.max(kept.length, 1);
}

/**
 * Frames at each of `distances`, and how each pair's change of s (and of the unscattered image)
 * departs from the steady change of a dolly: r_k = Δ_k − (x_{k+2} − x_{k−1}) / 3 for the pairs with
 * a frame either side (k = 1 .. n − 3), whose steady part (linear in the step) cancels. Returned as
 * trimmed means of |·| (trimmedMean), with the frames' largest trimmed means of s and of the unscattered image, and each frame's plan.
 */
async function dolly(distances) {
  const frames = [];
  for (const d of distances) frames.push(await frame(d));
  const departure = (name, k) => {
    const x = frames.map((f) => f[name]);
    return trimmedMean(x[k].map((_, i) => x[k + 1][i] - x[k][i] - (x[k + 2][i] - x[k - 1][i]) / 3));
  };
  const pairs = [];
  for (let k = 1; k + 2 < frames.length; k++) pairs.push({ k, s: departure('s', k), unscattered: departure('unscattered', k) });
  return {
    pairs, s: Math.max(...frames.map((f) => trimmedMean(f.s))), unscattered: Math.max(...frames.map((f) => trimmedMean(f.unscattered))),
    plans: frames.map((f) => f.plan), glError: Math.max(...frames.map((f) => f.glError)),
  };
}

/** One frame at `distance`, as the L2 norms of s and of the unscattered image over the frame, and the plan. */
async function norms(distance) {
  const { s, unscattered, plan, glError } = await frame(distance);
  const norm = (a) => Math.sqrt(a.reduce((sum, v) => sum + v * v, 0));
  return { s: norm(s), unscattered: norm(unscattered), plan, glError };
}

/** Renders `count` frames at `distance` and returns the median milliseconds of one (bench/stability.js). */
function time(distance, count) {
  const { composer, renderer } = rig;
  place(distance);
  const times = [];
  const pixel = new Float32Array(4);
  for (let i = 0; i < count; i++) {
    const start = performance.now();
    composer.render();
    renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel); // waits for the frame
    times.push(performance.now() - start);
  }
  times.sort((a, b) => a - b);
  return times[times.length >> 1];
}

function close() {
  if (!rig) return;
  rig.pipeline.dispose();
  rig.composer.dispose();
  rig.renderer.dispose();
  rig.renderer.forceContextLoss();
  rig = null;
}

window.stability = { open, pixelsPerMmAt, distanceFor, frame, norms, dolly, time, close };
window.testReady = true;
