// The browser side of test/browser/creases.test.js: the demo's first view (demo/state.js's
// defaults: the face close-up, its key light; MSAA 4, half floats, OutputPass's tone mapping and
// sRGB, as demo/main.js draws it), rendered as a crop of a larger frame (a view offset: the demo's
// scale in few pixels), dollied slowly; each frame read back as the output a user sees, in output
// steps, and its pops counted. Nothing here is part of the library.
import { HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { shotCamera } from '/demo/framing.js';
import { defaultState } from '/demo/state.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { headRig } from './headRig.js';
import { popDepartures, countPops } from './pops.js';
import '/test/pages/lab.js';

let rig = null;
/** Each dolly's departures (pops.js) by name, for later counts against them. */
const dollies = new Map();

/**
 * One pipeline (`sss`: its options over the demo's) drawing the crop `[x, y, width, height]`
 * (pixels from the top left) of the first view at `fullWidth` × `fullHeight`.
 */
async function open({ fullWidth, fullHeight, crop, sss = {} }) {
  close();
  const { THREE, SSS, createRenderer, createComposer } = window.lab;
  const [x, y, width, height] = crop;
  const renderer = createRenderer(width, height);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const head = await headRig(fullWidth / fullHeight);
  const state = defaultState();
  setLightDirection(head, state.lightAzimuth, state.lightElevation);
  head.light.intensity = state.lightIntensity;
  const shot = shotCamera(state.shot, fullWidth / fullHeight, head.camera.fov);
  const target = new THREE.Vector3(shot[3], shot[4], shot[5]);
  const offset = new THREE.Vector3(shot[0], shot[1], shot[2]).sub(target);
  head.camera.setViewOffset(fullWidth, fullHeight, x, y, width, height);
  const pipeline = new SSS.SubsurfaceScattering({
    scene: head.scene, camera: head.camera, light: head.light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, samples: 'auto', ...sss,
  });
  pipeline.makeSubsurface(head.head.material);
  const composer = createComposer(renderer, { samples: 4 });
  composer.addPass(pipeline);
  composer.addPass(new OutputPass());
  rig = { renderer, composer, pipeline, head, target, offset, width, height };
  return { isStandIn: head.isStandIn, distance: offset.length() };
}

/** The output with the camera at `factor` times the shot's distance, RGB in output steps (255 per unit). */
async function frame(factor) {
  const { camera } = rig.head;
  camera.position.copy(rig.target).addScaledVector(rig.offset, factor);
  camera.lookAt(rig.target);
  camera.updateMatrixWorld();
  rig.composer.render();
  const rgba = await window.lab.read(rig.renderer, rig.composer.readBuffer);
  const out = new Float32Array((rgba.length / 4) * 3);
  for (let p = 0; p < rgba.length / 4; p++) for (let c = 0; c < 3; c++) out[p * 3 + c] = 255 * rgba[p * 4 + c];
  return out;
}

/**
 * `frames` frames, the camera `step` of its distance nearer each time; keeps their departures
 * (pops.js) as `name`. Returns the GL error after the last frame.
 */
async function dolly({ name, frames, step }) {
  const images = [];
  for (let f = 0; f < frames; f++) images.push(await frame((1 - step) ** f));
  dollies.set(name, popDepartures(images, rig.width, rig.height));
  return { glError: rig.renderer.getContext().getError() };
}

/** pops.js's countPops of dolly `name`, explained by dolly `explainedBy`'s. */
const pops = ({ name, explainedBy }) => countPops(dollies.get(name), dollies.get(explainedBy));

function close() {
  if (!rig) return;
  rig.head.camera.clearViewOffset();
  rig.pipeline.dispose();
  rig.composer.dispose();
  rig.renderer.dispose();
  rig.renderer.forceContextLoss();
  rig = null;
}

window.creases = { open, dolly, pops, close };
window.testReady = true;
