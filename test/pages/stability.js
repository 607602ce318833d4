// The browser side of test/browser/stability.test.js and bench/stability.js: the demo's head
// dollied towards its face, each frame read back as the scattering signal s (the output minus the
// same frame's unscattered light: the colour and diffuse attachments summed) and that unscattered
// image, float. Nothing here is part of the library.
import { HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';
import { headRig } from './headRig.js';
import { distanceForScale, dollyDepartures, dollyDirection, placeOnDolly, scatteringSignal } from './dolly.js';
import '/test/pages/lab.js';

let rig = null;

/**
 * One pipeline over the head at `width` × `height` (float buffers: s near the skip is small),
 * `fovDeg` zooming in, the light `lightAzimuthDeg` round from the camera (from the side: more
 * light crosses shadow edges, more to scatter).
 */
async function open({ width, height, fovDeg, lightAzimuthDeg = 30, sss = {} }) {
  const key = JSON.stringify([width, height, lightAzimuthDeg, sss]);
  if (rig?.key === key) return zoom(fovDeg); // the same pipeline: nothing compiles again
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
  const direction = dollyDirection(head.camera);
  rig = { key, renderer, composer, pipeline, head, direction, isStandIn: head.isStandIn };
  composer.render(); // compiles, and the scene pass learns its meshes
  return { isStandIn: head.isStandIn };
}

/** The kept pipeline's camera zoomed to `fovDeg`. */
function zoom(fovDeg) {
  rig.head.camera.fov = fovDeg;
  rig.head.camera.updateProjectionMatrix();
  return { isStandIn: rig.isStandIn };
}

/** The camera `distance` world units from the face centre (dolly.js). */
const place = (distance) => placeOnDolly(rig.head.camera, rig.direction, distance);

/** The frame plan's scale (pixels per profile mm) with the camera at `distance`: no rendering. */
function pixelsPerMmAt(distance) {
  place(distance);
  return rig.pipeline._pixelsPerMm();
}

/** The distance at which the plan's scale is `pixelsPerMm`. */
const distanceFor = (pixelsPerMm) => distanceForScale(pixelsPerMmAt, pixelsPerMm);

/** One frame at `distance`: s and the unscattered image as RGB floats, and the plan. */
async function frame(distance) {
  const { renderer, composer, pipeline } = rig;
  place(distance);
  composer.render();
  const { read } = window.lab;
  const target = pipeline._scenePass.renderTarget;
  const { s, unscattered } = scatteringSignal(await read(renderer, composer.readBuffer), await read(renderer, target, ATTACHMENTS.COLOR), await read(renderer, target, ATTACHMENTS.DIFFUSE));
  const { groupings, ...plan } = pipeline.plan;
  return { s, unscattered, plan, glError: renderer.getContext().getError() };
}

/**
 * Frames at each of `distances`, measured as dolly.js's dollyDepartures says, with each
 * frame's plan.
 */
async function dolly(distances) {
  const frames = [];
  for (const d of distances) frames.push(await frame(d));
  return { ...dollyDepartures(frames), plans: frames.map((f) => f.plan), glError: Math.max(...frames.map((f) => f.glError)) };
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

window.stability = { open, pixelsPerMmAt, distanceFor, frame, dolly, time, close };
window.testReady = true;
