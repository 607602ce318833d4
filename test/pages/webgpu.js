// The browser side of the WebGPURenderer tests (test/browser/webgpu*.test.js): the library's
// `three-separable-sss/webgpu` node on WebGPU or on WebGPURenderer's WebGL 2 backend
// (`backend: 'webgl'`, forceWebGL), on the scenes the WebGL path's tests use, read back as floats.
// Nothing here is part of the library.
import * as THREE from 'three/webgpu';
import { cos, pass, positionLocal, uniform, vec3 } from 'three/tsl';
import * as NODE from '/src/webgpu/index.js';
import { flatScene, spheresScene } from './flatScene.js';
import { HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { headRig } from './headRig.js';
import { ATTACHMENTS } from '/src/2-scene-split/subsurfaceTarget.js';
import { ROWS as SCENE_GRAPH_ROWS, WIDTH as SCENE_GRAPH_WIDTH, HEIGHT as SCENE_GRAPH_HEIGHT, WIDTH_MM as SCENE_GRAPH_WIDTH_MM, compare } from './sceneGraph.js';
import './lab.js'; // window.lab: the WebGL pipeline's side of the comparisons
import { estimatePixelsPerMm } from '/src/framePlan.js';
import { distanceForScale, dollyDirection, placeOnDolly, scatteringSignal, dollyDepartures } from './dolly.js';

/** A WebGPURenderer on an offscreen canvas of `width` × `height` device pixels, initialised. */
async function createRenderer(width, height, { backend = 'webgpu', ...parameters } = {}) {
  const renderer = new THREE.WebGPURenderer({ antialias: false, forceWebGL: backend === 'webgl', ...parameters });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  await renderer.init();
  const actual = renderer.backend.isWebGPUBackend ? 'webgpu' : 'webgl';
  if (actual !== backend) throw new Error(`asked for the ${backend} backend, got ${actual}`);
  return renderer;
}

/** One renderer per backend for the accuracy scenes (a new WebGPU device per scene costs seconds). */
const shared = new Map();
async function sharedRenderer(backend, width, height) {
  if (!shared.has(backend)) shared.set(backend, createRenderer(width, height, { backend }));
  const renderer = await shared.get(backend);
  renderer.setSize(width, height, false);
  return renderer;
}

/**
 * Any texture of a render target as RGBA 32-bit floats, rows bottom-up as the WebGL lab reads them
 * (the WebGPU backend's textures hold them top-down).
 */
async function readFloats(renderer, target, index = 0) {
  const { width, height } = target;
  if (typeof index === 'string') index = target.textures.findIndex((t) => t.name === index);
  const data = await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height, index);
  let floats;
  if (data instanceof Float32Array) floats = data;
  else if (data instanceof Uint16Array) floats = Float32Array.from(data, THREE.DataUtils.fromHalfFloat);
  else throw new TypeError(`readFloats: unexpected ${data.constructor.name}`);
  if (!renderer.backend.isWebGPUBackend) return floats;
  const rows = new Float32Array(floats.length);
  const row = width * 4;
  for (let y = 0; y < height; y++) rows.set(floats.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return rows;
}

/** The subsurface pass (MSAA with `samples`) and node over `scene` seen by `camera`, in a RenderPipeline. */
function subsurfacePipeline(renderer, scene, camera, { type = THREE.HalfFloatType, samples = 0, sss = {} } = {}) {
  const scenePass = pass(scene, camera, { type, samples });
  scenePass.setMRT(NODE.subsurfaceMRT());
  const node = NODE.subsurfaceScattering(scenePass, sss);
  const pipeline = new THREE.RenderPipeline(renderer);
  pipeline.outputColorTransform = false; // linear HDR out, as the WebGL lab's composer without OutputPass
  pipeline.outputNode = node;
  return { scenePass, node, pipeline };
}

/**
 * The scene pass, node and RenderPipeline of the last `flat` call on each backend, kept while the
 * next call there asks for the same node options (as lab.js's flat rig: a new node builds and
 * compiles its blur programs again; a kept one reads the call's scene and camera from the pass, as
 * the node does every frame).
 */
const flatRigs = new Map();

function flatRigFor(renderer, backend, sss) {
  const key = JSON.stringify(sss);
  const kept = flatRigs.get(backend);
  if (kept?.key === key) return kept;
  disposeFlatRig(backend);
  // The scene and camera are each call's (assigned there); these only make the pass.
  const rig = { key, ...subsurfacePipeline(renderer, new THREE.Scene(), new THREE.OrthographicCamera(), { type: THREE.FloatType, sss: { worldUnitInMm: 1, ...sss } }) };
  flatRigs.set(backend, rig);
  return rig;
}

function disposeFlatRig(backend) {
  const rig = flatRigs.get(backend);
  if (!rig) return;
  rig.node.dispose();
  rig.pipeline.dispose();
  rig.scenePass.dispose();
  flatRigs.delete(backend);
}

/** The analytic accuracy scene (flatScene.js) through the node: the diffuse light before the blur and after it. */
async function flat({ width = 256, height = 256, backend = 'webgpu', sss = {}, ...options }) {
  const renderer = await sharedRenderer(backend, width, height);
  const { scene, camera, material, map, plane } = flatScene({ width, height, ...options });
  const skin = NODE.subsurfaceMaterial(material, { widthMm: 1 });
  scene.traverse((object) => { if (object.material === material) object.material = skin; });
  const { scenePass, node, pipeline } = flatRigFor(renderer, backend, sss);
  Object.assign(scenePass, { scene, camera });
  pipeline.render();
  const before = await readFloats(renderer, scenePass.renderTarget, 'diffuse');
  const after = await readFloats(renderer, node._scatteredTarget);
  const result = { width, height, before, after, blur: node.plan.blur, plan: node.plan };
  skin.dispose();
  material.dispose();
  map.dispose();
  plane.geometry.dispose();
  return result;
}

/** 8-bit RGBA of a float read-back, as a canvas stores it (rounded, clamped). */
const toBytes = (floats) => Uint8Array.from(floats, (v) => Math.round(Math.min(Math.max(v, 0), 1) * 255));

/**
 * The demo's head through both renderers, tone mapped (ACES) and sRGB-encoded, as 8-bit RGBA rows
 * bottom-up: the WebGL pipeline in an EffectComposer with OutputPass, and the node in a
 * RenderPipeline on `backend`; with `sss: false` each renderer's plain frame instead (the baseline
 * difference between the two renderers). Shadows off: the renderers filter shadow maps differently.
 * `fovDeg` narrows the demo's 25° view onto the face (more pixels per mm: more visible scattering);
 * `light`: [azimuth, elevation] in degrees (demo/headScene.js's setLightDirection), and the light
 * sends transmittance on both; `view`: both pipelines' debug view.
 */
async function head({ width = 320, height = 180, backend = 'webgpu', sss = true, fovDeg, light, view = 'final' }) {
  const L = window.lab;
  const glRig = await headRig(width / height, fovDeg);
  if (light) setLightDirection(glRig, ...light);
  const gl = L.createRenderer(width, height);
  gl.toneMapping = L.THREE.ACESFilmicToneMapping;
  const composer = L.createComposer(gl);
  if (sss) {
    const pipeline = new L.SSS.SubsurfaceScattering({ scene: glRig.scene, camera: glRig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: light ? glRig.light : null });
    pipeline.debugView = view;
    pipeline.makeSubsurface(glRig.head.material, { widthMm: 1 });
    composer.addPass(pipeline);
  } else {
    composer.addPass(new L.RenderPass(glRig.scene, glRig.camera));
  }
  composer.addPass(new L.OutputPass());
  composer.render();
  const webgl = toBytes(await L.read(gl, composer.readBuffer));
  composer.dispose();
  gl.dispose();
  gl.forceContextLoss();

  const rig = await headRig(width / height, fovDeg);
  if (light) setLightDirection(rig, ...light);
  const renderer = await createRenderer(width, height, { backend });
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const target = new THREE.RenderTarget(width, height, { type: THREE.HalfFloatType });
  let disposeAll;
  if (sss) {
    rig.head.material = NODE.subsurfaceMaterial(rig.head.material, { widthMm: 1 });
    const built = subsurfacePipeline(renderer, rig.scene, rig.camera, { sss: { worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: light ? rig.light : null } });
    built.node.debugView = view;
    built.pipeline.outputColorTransform = true;
    renderer.setRenderTarget(target);
    built.pipeline.render();
    disposeAll = () => { built.node.dispose(); built.pipeline.dispose(); built.scenePass.dispose(); };
  } else {
    renderer.setRenderTarget(target);
    renderer.outputColorSpace = THREE.SRGBColorSpace;
    const pipeline = new THREE.RenderPipeline(renderer, pass(rig.scene, rig.camera));
    pipeline.render();
    disposeAll = () => pipeline.dispose();
  }
  renderer.setRenderTarget(null);
  const node = toBytes(await readFloats(renderer, target));
  disposeAll();
  target.dispose();
  renderer.dispose();
  return { width, height, webgl, node, isStandIn: rig.isStandIn };
}

/** A small lit scene: a box of `material` over a grey background, a directional and an ambient light. */
function boxScene(material) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0.25, 0.25, 0.25);
  const camera = new THREE.PerspectiveCamera(30, 16 / 9, 0.1, 50);
  camera.position.set(0, 0, 5);
  const mesh = new THREE.Mesh(new THREE.BoxGeometry(1.6, 1, 0.5), material);
  mesh.rotation.set(0.3, 0.5, 0);
  const light = new THREE.DirectionalLight(0xffffff, 3);
  light.position.set(1, 2, 3);
  scene.add(mesh, light, light.target, new THREE.AmbientLight(0xffffff, 0.4));
  return { scene, camera, mesh };
}

const memoryOf = (renderer) => ({ ...renderer.info.memory });

/**
 * renderer.info.memory before the node (the scene drawn plainly), while it runs (three frames, one
 * with the blur off) and after its dispose (with the pipeline, the scene pass and the subsurface
 * material, and the scene drawn plainly again).
 */
async function disposal({ backend = 'webgpu', width = 96, height = 54 }) {
  // One kernel, then the isotropic blur's groups (its multi-target, fraction table and materials) too.
  const renderer = await createRenderer(width, height, { backend });
  const material = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.6 });
  const { scene, camera, mesh } = boxScene(material);
  renderer.render(scene, camera);
  const before = memoryOf(renderer);
  const skin = NODE.subsurfaceMaterial(material, { widthMm: 5 });
  mesh.material = skin;
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, scene, camera, { sss: { worldUnitInMm: 100 } });
  // A frame per setting: the node plans once per frame (updateBefore, NodeUpdateType.FRAME), and
  // three's frame advances with the animation frame, not with each render call.
  const frame = async () => {
    pipeline.render();
    await new Promise(requestAnimationFrame);
  };
  await frame();
  const plans = [node.plan.groups];
  node.scattering = false;
  await frame();
  const skipped = !node.plan.blur;
  node.scattering = true;
  // Four groups, then three and two (each count its own multi-target and materials, the last
  // count's freed), then one kernel again (the group target freed).
  let during;
  for (const groups of [4, 3, 2, 1]) {
    node.kernelGroups = groups;
    await frame();
    plans.push(node.plan.groups);
    if (groups === 4) during = memoryOf(renderer);
  }
  const blurred = skipped && node.plan.blur && plans.join() === '1,4,3,2,1';
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  skin.dispose();
  mesh.material = material;
  renderer.render(scene, camera);
  const after = memoryOf(renderer);
  renderer.dispose();
  return { before, during, after, blurred };
}

/**
 * The same box drawn plainly (renderer.render, no subsurface pass) with three's material and with
 * its subsurface version: 8-bit RGBA of each.
 */
async function plainDraw({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await createRenderer(width, height, { backend });
  const target = new THREE.RenderTarget(width, height, { type: THREE.HalfFloatType });
  const material = new THREE.MeshPhysicalMaterial({ color: 0xffccaa, roughness: 0.6, clearcoat: 0.5 });
  const { scene, camera, mesh } = boxScene(material);
  const draw = async () => {
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    renderer.setRenderTarget(null);
    return toBytes(await readFloats(renderer, target));
  };
  const three = await draw();
  mesh.material = NODE.subsurfaceMaterial(material, { widthMm: 5 });
  const subsurface = await draw();
  target.dispose();
  renderer.dispose();
  return { three, subsurface };
}

/** The box through the node in each debug view it has, linear (no output transform), float RGBA. */
async function debugViews({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await createRenderer(width, height, { backend });
  const material = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.6 });
  const { scene, camera, mesh } = boxScene(material);
  mesh.material = NODE.subsurfaceMaterial(material, { widthMm: 5 });
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, scene, camera, { sss: { worldUnitInMm: 100 } });
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const views = {};
  for (const view of ['final', 'diffuse', 'specular', 'mask', 'depth']) {
    Object.assign(node, { debugView: view, debugDepthRange: 10 });
    renderer.setRenderTarget(target);
    pipeline.render();
    renderer.setRenderTarget(null);
    views[view] = await readFloats(renderer, target);
  }
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  target.dispose();
  renderer.dispose();
  return views;
}

/**
 * The box through the node with an ArrayCamera of two views (fov 20 and 40) and with scattering
 * off (issue 40: the node blurs one view, so it draws an ArrayCamera's views unscattered, said once):
 * the output of each (linear float) and the node's problems.
 */
async function arrayCamera({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await createRenderer(width, height, { backend });
  const material = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.6 });
  const { scene, camera, mesh } = boxScene(material);
  mesh.material = NODE.subsurfaceMaterial(material, { widthMm: 5 });
  const views = [20, 40].map((fov, i) => {
    const view = new THREE.PerspectiveCamera(fov, width / 2 / height, 0.1, 50);
    view.position.copy(camera.position);
    view.updateMatrixWorld();
    view.viewport = new THREE.Vector4(i * width / 2, 0, width / 2, height);
    return view;
  });
  const array = new THREE.ArrayCamera(views);
  array.position.copy(camera.position);
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const out = {};
  for (const scattering of [true, false]) {
    const { scenePass, node, pipeline } = subsurfacePipeline(renderer, scene, array, { sss: { worldUnitInMm: 100, scattering } });
    renderer.setRenderTarget(target);
    pipeline.render();
    renderer.setRenderTarget(null);
    out[scattering ? 'asked' : 'off'] = { image: await readFloats(renderer, target), problems: [...node.problems], blur: node.plan.blur };
    node.dispose();
    pipeline.dispose();
    scenePass.dispose();
  }
  // three's own frame of the views: the box's own material, no pipeline.
  const subsurface = mesh.material;
  mesh.material = material;
  renderer.setRenderTarget(target);
  renderer.render(scene, array);
  renderer.setRenderTarget(null);
  out.three = await readFloats(renderer, target);
  target.dispose();
  subsurface.dispose();
  renderer.dispose();
  return out;
}

/**
 * One of the WebGL lab's scenes (lab.js's SCENES, its defaults: 10 mm per unit) through the node,
 * its subsurface materials as node materials, the scene pass multisampled with `samples`, and the
 * scene's light for transmittance where `transmittance`: the diffuse attachment (float, before
 * the blur), whether the light depth pass ran, and the node's output in each of `views` (linear,
 * float). `lightZ` moves the light (+10: in front of the back-lit slab); `kernelGroups` the node's.
 */
async function labScene({
  backend = 'webgpu', width = 96, height = 54, scene: name = 'backlit', transmittance = true, samples = 0, lightZ, material = {}, views = [], kernelGroups = 1, ...scene
}) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene(name, { width, height, ...scene });
  if (lightZ !== undefined) built.light.position.z = lightZ;
  const skins = new Map(built.subsurface.map((plain) => [plain, NODE.subsurfaceMaterial(plain, { widthMm: 1, ...material })]));
  built.scene.traverse((object) => { if (skins.has(object.material)) object.material = skins.get(object.material); });
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, {
    type: THREE.FloatType, samples, sss: { worldUnitInMm: window.lab.DEFAULTS.worldUnitInMm, light: transmittance ? built.light : null, kernelGroups },
  });
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const render = () => {
    renderer.setRenderTarget(target);
    pipeline.render();
    renderer.setRenderTarget(null);
  };
  render();
  const result = { width, height, diffuse: await readFloats(renderer, scenePass.renderTarget, 'diffuse'), lightDepthRendered: node.lightDepth?.valid };
  for (const view of views) {
    Object.assign(node, { debugView: view, debugThicknessRangeMm: 10 });
    render();
    result[view] = await readFloats(renderer, target);
  }
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  target.dispose();
  for (const [plain, skin] of skins) {
    skin.dispose();
    plain.dispose();
  }
  return result;
}

/**
 * The WebGL light depth test's cards (lab.js's lightDepthCards; the clipped one in a
 * ClippingGroup) into the node's light depth map, 64 × 64: the depths at lab.cardDepths' points, and the shaped depth materials made, left after
 * one card's material is disposed, and after the map is.
 */
async function lightDepthCards({ backend = 'webgpu' }) {
  const renderer = await sharedRenderer(backend, 16, 16);
  const { scene, light, mapped } = window.lab.lightDepthCards();
  // WebGPURenderer clips by ClippingGroup, not by material.clippingPlanes: the clipped card goes
  // into one with its material's planes (the same cut, each renderer's way).
  const clipped = scene.children.find((object) => object.material?.clippingPlanes?.length);
  const group = new THREE.ClippingGroup();
  group.clippingPlanes = clipped.material.clippingPlanes;
  scene.add(group);
  group.add(clipped);
  const target = new NODE.LightDepthNodeTarget(light, { size: 64 });
  target.render(renderer, scene);
  const data = await renderer.readRenderTargetPixelsAsync(target.renderTarget, 0, 0, 64, 64);
  // Rows bottom-up, as the WebGL lab reads them (the WebGPU backend's are top-down).
  // Two channels per texel: depth, entry cosine.
  const rows = renderer.backend.isWebGPUBackend ? Float32Array.from({ length: 64 * 64 * 2 }, (_, i) => data[((63 - Math.floor(i / 128)) * 64 + (Math.floor(i / 2) % 64)) * 2 + (i % 2)]) : data;
  const variants = target._shaped.size;
  mapped.material.dispose();
  const afterOneDisposed = target._shaped.size;
  target.dispose();
  return { samples: window.lab.cardDepths(rows, 2), cosines: window.lab.cardCosines(rows, 2), variants, afterOneDisposed, left: target._shaped.size };
}

/** One of the WebGL lab's scenes drawn plainly by WebGPURenderer on `backend` (a scene pass, MSAA with `samples`), linear float RGBA. */
async function labScenePlain({ backend = 'webgpu', width = 96, height = 54, scene: name = 'mixed', samples = 0, ...scene }) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene(name, { width, height, ...scene });
  const scenePass = pass(built.scene, built.camera, { type: THREE.FloatType, samples });
  const pipeline = new THREE.RenderPipeline(renderer, scenePass);
  pipeline.outputColorTransform = false;
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  pipeline.render();
  renderer.setRenderTarget(null);
  const image = await readFloats(renderer, target);
  pipeline.dispose();
  scenePass.dispose();
  target.dispose();
  return image;
}

/** The head for the stability test (test/browser/webgpu/webgpuStability.test.js): the node, float, one dolly (dolly.js). */
let dollyRig = null;

async function dollyOpen({ width, height, fovDeg, lightAzimuthDeg = 30, backend = 'webgpu', sss = {} }) {
  const key = JSON.stringify([width, height, lightAzimuthDeg, backend, sss]);
  if (dollyRig?.key === key) { // the same node, zoomed: nothing compiles again
    dollyRig.rig.camera.fov = fovDeg;
    dollyRig.rig.camera.updateProjectionMatrix();
    return { isStandIn: dollyRig.rig.isStandIn };
  }
  dollyClose();
  const rig = await headRig(width / height, fovDeg);
  setLightDirection(rig, lightAzimuthDeg, 25);
  rig.camera.far = 2000; // the dolly goes far
  rig.camera.updateProjectionMatrix();
  const renderer = await createRenderer(width, height, { backend });
  rig.head.material = NODE.subsurfaceMaterial(rig.head.material, { widthMm: 1 });
  const built = subsurfacePipeline(renderer, rig.scene, rig.camera, { type: THREE.FloatType, sss: { worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: rig.light, ...sss } });
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  dollyRig = { key, rig, renderer, built, target, direction: dollyDirection(rig.camera), width, height };
  return { isStandIn: rig.isStandIn };
}

/** The node's plan's scale at `distance` (its own estimate: the head's box, widthMm 1). */
function dollyScaleAt(distance) {
  const { rig, direction, width, height } = dollyRig;
  placeOnDolly(rig.camera, direction, distance);
  return estimatePixelsPerMm([rig.head], rig.camera, { width, height }, () => 1 / HEAD_WORLD_UNIT_IN_MM);
}

/** Frames at each of `pixelsPerMm` (dolly.js's dollyDepartures over them) and each frame's plan. */
async function dollyFrames(scales) {
  const { rig, renderer, built, target, direction } = dollyRig;
  const frames = [];
  for (const pixelsPerMm of scales) {
    placeOnDolly(rig.camera, direction, distanceForScale(dollyScaleAt, pixelsPerMm));
    renderer.setRenderTarget(target);
    built.pipeline.render();
    renderer.setRenderTarget(null);
    const split = built.scenePass.renderTarget;
    const signal = scatteringSignal(await readFloats(renderer, target), await readFloats(renderer, split, NODE.ATTACHMENT_NAMES.COLOR), await readFloats(renderer, split, NODE.ATTACHMENT_NAMES.DIFFUSE));
    const { groupings, ...plan } = built.node.plan;
    frames.push({ ...signal, plan });
  }
  return { ...dollyDepartures(frames), plans: frames.map((f) => f.plan) };
}

function dollyClose() {
  if (!dollyRig) return;
  const { renderer, built, target } = dollyRig;
  built.node.dispose();
  built.pipeline.dispose();
  built.scenePass.dispose();
  target.dispose();
  renderer.dispose();
  dollyRig = null;
}

/**
 * The node's `light` assigned at any time (issue 36): the lab's back-lit slab with its directional
 * light and a spot light beside it; the diffuse attachment of a node made with each light, then of
 * one node made without a light after each assignment (none, the directional, the spot, none),
 * with `light` and `transmittance` as they read.
 */
async function lightAssigned({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene('backlit', { width, height, thicknessMm: 1 });
  const spot = new THREE.SpotLight(0xffffff, Math.PI * 113, 0, Math.PI / 12, 0.5, 2);
  spot.position.set(3, 2, -10);
  built.scene.add(spot, spot.target);
  const sun = built.light;
  const skin = NODE.subsurfaceMaterial(built.subsurface[0], { widthMm: 1, shrinkMm: 0.6 });
  built.scene.traverse((object) => { if (object.material === built.subsurface[0]) object.material = skin; });
  const frames = async (light, steps) => {
    const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, { type: THREE.FloatType, sss: { worldUnitInMm: 10, light } });
    const out = {};
    for (const [label, step] of steps(node)) {
      await new Promise((resolve) => { requestAnimationFrame(() => resolve()); }); // a frame each, as an app renders: the scene pass draws once a frame
      step();
      pipeline.render();
      out[label] = { diffuse: await readFloats(renderer, scenePass.renderTarget, 'diffuse'), light: node.light === sun ? 'sun' : node.light === spot ? 'spot' : node.light, transmittance: node.transmittance };
    }
    node.dispose();
    pipeline.dispose();
    scenePass.dispose();
    return out;
  };
  const made = { sun: (await frames(sun, () => [['made', () => {}]])).made, spot: (await frames(spot, () => [['made', () => {}]])).made };
  const assigned = await frames(null, (node) => [
    ['none', () => {}], ['sun', () => { node.light = sun; }], ['spot', () => { node.light = spot; }], ['null', () => { node.light = null; }], ['sun again', () => { node.light = sun; }],
  ]);
  skin.dispose();
  built.subsurface[0].dispose();
  return { made, assigned };
}

/**
 * The settings a light needs, set at once in either key order (issue 40): the lab's back-lit slab
 * through a node made without a light; `order` 'forward' or 'backward' assigns each step's settings
 * in that key order. Per step: the diffuse attachment, the node's output (linear float) and problems;
 * `made`: the diffuse attachment of a node made with the light.
 */
async function lightKeyOrder({ backend = 'webgpu', width = 48, height = 27, order = 'forward' }) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene('backlit', { width, height, thicknessMm: 1 });
  const sun = built.light;
  built.scene.add(new THREE.AmbientLight(0xffffff, 1)); // diffuse light in front: what a thickness view must not show
  const skin = NODE.subsurfaceMaterial(built.subsurface[0], { widthMm: 1, shrinkMm: 0.6 });
  built.scene.traverse((object) => { if (object.material === built.subsurface[0]) object.material = skin; });
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const frames = async (light, steps) => {
    const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, { type: THREE.FloatType, sss: { worldUnitInMm: 10, light } });
    const out = {};
    for (const [label, settings] of steps) {
      await new Promise((resolve) => { requestAnimationFrame(() => resolve()); }); // a frame each: the scene pass draws once a frame
      const entries = Object.entries(settings);
      Object.assign(node, Object.fromEntries(order === 'forward' ? entries : entries.reverse()));
      renderer.setRenderTarget(target);
      pipeline.render();
      renderer.setRenderTarget(null);
      out[label] = {
        diffuse: await readFloats(renderer, scenePass.renderTarget, 'diffuse'), output: await readFloats(renderer, target),
        problems: [...node.problems], transmittance: node.transmittance, debugView: node.debugView,
      };
    }
    node.dispose();
    pipeline.dispose();
    scenePass.dispose();
    return out;
  };
  const made = (await frames(sun, [['made', {}]])).made;
  const steps = await frames(null, [
    ['transmittance and the light', { transmittance: true, light: sun }],
    ['no light and the thickness view', { light: null, debugView: 'thickness' }],
    ['the light again', { light: sun }],
  ]);
  target.dispose();
  skin.dispose();
  built.subsurface[0].dispose();
  return { made, steps };
}

/**
 * The lab's back-lit slab through the node with its light's shadow camera near beyond the slab
 * (12 units; the light is 10 behind): the diffuse attachment (issue 36: the map's near and far are
 * fitted to the meshes, not taken from the shadow camera).
 */
async function nearLight({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene('backlit', { width, height, thicknessMm: 1 });
  built.light.shadow.camera.near = 12;
  built.light.shadow.camera.far = 30;
  const skin = NODE.subsurfaceMaterial(built.subsurface[0], { widthMm: 1, shrinkMm: 0.6 });
  built.scene.traverse((object) => { if (object.material === built.subsurface[0]) object.material = skin; });
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, { type: THREE.FloatType, sss: { worldUnitInMm: 10, light: built.light } });
  pipeline.render();
  const diffuse = await readFloats(renderer, scenePass.renderTarget, 'diffuse');
  const problems = [...node.problems];
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  skin.dispose();
  built.subsurface[0].dispose();
  return { diffuse, problems };
}

/**
 * A setting changed between two renders of one animation frame (issue 36): the lab's noisy slab
 * through the node, its output (linear float) blurred; then, in one task, scattering off, a render,
 * scattering on, a render; then, a frame later, scattering off.
 */
async function sameFrame({ backend = 'webgpu', width = 96, height = 54 }) {
  const renderer = await sharedRenderer(backend, width, height);
  const built = window.lab.buildScene('slab', { width, height, pattern: 'noise' });
  const skin = NODE.subsurfaceMaterial(built.subsurface[0], { widthMm: 1 });
  built.scene.traverse((object) => { if (object.material === built.subsurface[0]) object.material = skin; });
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, { type: THREE.FloatType, sss: { worldUnitInMm: 10 } });
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const render = () => {
    renderer.setRenderTarget(target);
    pipeline.render();
    renderer.setRenderTarget(null);
  };
  const nextFrame = () => new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
  render();
  const blurred = await readFloats(renderer, target);
  await nextFrame();
  node.scattering = false;
  render();
  node.scattering = true;
  render(); // the same animation frame
  const onAgain = await readFloats(renderer, target);
  await nextFrame();
  node.scattering = false;
  render();
  const unblurred = await readFloats(renderer, target);
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  target.dispose();
  skin.dispose();
  built.subsurface[0].dispose();
  return { blurred, onAgain, unblurred };
}

/**
 * The WebGL pipeline frame test's scene (test/browser/pipelineFrame.test.js) through the node: a
 * subsurface sphere (noise albedo) over an ordinary floor, a second one half hidden behind it, an
 * ordinary box in front; a directional light casting shadows; 192 × 108, float. Each variant is a
 * fresh node (`sss`: its options; `samples`: the scene pass's MSAA); `moved`: one frame with the
 * spheres higher and to the right first, so the subsurface box moves between frames (the blur's targets are not
 * cleared outside it). Returns each variant's output, its scattered light inside the box, the box
 * (x0, y0, x1, y1 from the top left), the plan, and the diffuse attachment's alpha of the first.
 */
async function boxFrames({ backend = 'webgpu', variants }) {
  const width = 192;
  const height = 108;
  const renderer = await sharedRenderer(backend, width, height);
  renderer.shadowMap.enabled = true;
  const { scene, camera, light, subsurface: spheres, map } = spheresScene(width / height);
  const three = spheres.map((m) => m.material);
  for (const m of spheres) m.material = NODE.subsurfaceMaterial(m.material);
  const home = spheres.map((m) => m.position.clone());
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const render = (pipeline) => {
    renderer.setRenderTarget(target);
    pipeline.render();
    renderer.setRenderTarget(null);
  };
  const out = {};
  for (const [name, { sss = {}, samples = 0, moved = false }] of Object.entries(variants)) {
    const built = subsurfacePipeline(renderer, scene, camera, { type: THREE.FloatType, samples, sss: { worldUnitInMm: 100, light, ...sss } });
    if (moved) {
      spheres.forEach((m) => { m.position.x += 0.4; m.position.y += 0.6; }); // up: the vertical pass's taps reach the rows left behind
      render(built.pipeline);
      spheres.forEach((m, i) => m.position.copy(home[i]));
      await new Promise((resolve) => { requestAnimationFrame(() => resolve()); }); // the light stage runs once a frame
    }
    render(built.pipeline);
    const [x0, y0, x1, y1] = built.node._uniforms.subsurfaceBox.value.toArray();
    const scattered = await readFloats(renderer, built.node._scatteredTarget);
    // Rows bottom-up (readFloats): the box's rows from the top are height − 1 − y.
    const inBox = scattered.map((v, i) => { const x = (i >> 2) % width; const y = height - 1 - Math.floor((i >> 2) / width); return x >= x0 && x < x1 && y >= y0 && y < y1 ? v : 0; });
    const { groupings, ...plan } = built.node.plan;
    out[name] = { output: await readFloats(renderer, target), scattered: inBox, box: [x0, y0, x1, y1], plan };
    if (name === Object.keys(variants)[0] && samples === 0) out[name].mask = (await readFloats(renderer, built.scenePass.renderTarget, 'diffuse')).filter((_, i) => i % 4 === 3);
    built.node.dispose();
    built.pipeline.dispose();
    built.scenePass.dispose();
    await new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
  }
  renderer.shadowMap.enabled = false;
  target.dispose();
  scene.traverse((object) => object.material?.dispose());
  for (const m of three) m.dispose();
  map.dispose();
  return { width, height, ...out };
}

/**
 * The lights of issue 43 on the node, the WebGL lights test's scene (test/browser/1-light-depth/
 * lights.test.js): a white slab `thicknessMm` thick (metres, 0.2 m wide) seen from the front at
 * 0.3 m, lit from behind only, `size` pixels square. `lights(THREE)` names the lights (added to the
 * scene), `steps(node, lights, parts)` the [label, action] pairs, each followed by a frame (an
 * animation frame apart: the scene pass draws once a frame) whose diffuse attachment (float) is
 * returned under its label with `node.light` (a light's name, 'castShadow', null or 'a list') and
 * the frame's problems. With `webgl`, the labels it lists are drawn by the WebGL pipeline too,
 * with the node's `light` of that step, into `webgl[label]`.
 */
async function slabLightFrames({ backend = 'webgpu', thicknessMm = 1, size = 48, lights: makeLights, steps, webgl = [] }) {
  const renderer = await sharedRenderer(backend, size, size);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
  camera.position.set(0, 0, 0.3);
  const plain = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0 });
  const skin = NODE.subsurfaceMaterial(plain, { widthMm: 1, shrinkMm: 0.6 });
  const slab = new THREE.Mesh(new THREE.BoxGeometry(0.2, 0.2, thicknessMm / 1000), skin);
  slab.name = 'slab';
  scene.add(slab);
  const lights = makeLights(THREE);
  for (const light of Object.values(lights)) scene.add(light, ...(light.target ? [light.target] : []));
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, scene, camera, { type: THREE.FloatType, sss: { worldUnitInMm: 1000 } });
  const nameOf = (light) => Object.entries(lights).find(([, l]) => l === light)?.[0] ?? (light === null || typeof light === 'string' ? light : 'a list');
  const out = { webgl: {} };
  for (const [label, action] of steps(node, lights, { scene, camera, slab, skin })) {
    await new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
    action();
    pipeline.render();
    out[label] = { diffuse: await readFloats(renderer, scenePass.renderTarget, 'diffuse'), light: nameOf(node.light), problems: [...node.problems], cubes: node.lightDepths.map((map) => map.isCube) };
    if (webgl.includes(label)) out.webgl[label] = await webglSlabFrame(scene, camera, slab, plain, node.light, size);
  }
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  skin.dispose();
  plain.dispose();
  slab.geometry.dispose();
  return out;
}

/** The WebGL pipeline's diffuse attachment (float) of the same scene with `light`, `plain` (three's material) on the slab. */
async function webglSlabFrame(scene, camera, slab, plain, light, size) {
  const L = window.lab;
  const skin = slab.material;
  slab.material = plain;
  const gl = L.createRenderer(size, size);
  const sss = new L.SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000, type: THREE.FloatType });
  sss.makeSubsurface(plain, { widthMm: 1, shrinkMm: 0.6 });
  const composer = L.createComposer(gl, { type: THREE.FloatType });
  composer.addPass(sss);
  composer.render();
  const diffuse = await L.read(gl, sss._scenePass.renderTarget, ATTACHMENTS.DIFFUSE);
  sss.dispose();
  composer.dispose();
  gl.dispose();
  gl.forceContextLoss();
  slab.material = skin;
  return diffuse;
}

/** The four lights of the list test: two directional, a spot, a point light aimed at the slab (its bounds fit 120°). */
const FOUR_LIGHTS = (T) => {
  const behind = new T.DirectionalLight(0xffffff, Math.PI);
  behind.position.set(0, 0, -2);
  const oblique = new T.DirectionalLight(0xffccaa, 2);
  oblique.position.set(1.2, 0.3, -1.5);
  const spot = new T.SpotLight(0xaaccff, 6 * Math.PI, 0, Math.PI / 10, 0.3, 2);
  spot.position.set(-0.1, 0.05, -1.2);
  const bulb = new T.PointLight(0xffeecc, 3 * Math.PI, 0, 2);
  bulb.position.set(0.05, -0.3, -0.8);
  for (const light of [behind, oblique]) Object.assign(light.shadow.camera, { left: -0.15, right: 0.15, bottom: -0.15, top: 0.15 });
  return { behind, oblique, spot, bulb };
};

/** Each of FOUR_LIGHTS alone, all four, two, then a list read back; 'all' also through the WebGL pipeline. */
const nodeLightList = ({ backend }) => slabLightFrames({
  backend, thicknessMm: 1.5, lights: FOUR_LIGHTS, webgl: ['all'],
  steps: (node, l) => [
    ['behind', () => { node.light = l.behind; }], ['oblique', () => { node.light = [l.oblique]; }],
    ['spot', () => { node.light = l.spot; }], ['bulb', () => { node.light = l.bulb; }],
    ['all', () => { node.light = [l.behind, l.oblique, l.spot, l.bulb]; }],
    ['two', () => { node.light = [l.spot, l.behind]; }],
  ],
});

/**
 * A spot light straight behind the 1 mm slab, 2 m away (intensity 4π, decay 2: irradiance π; the
 * slab well inside its cone); a point light there, among transmitting meshes (a box beyond it:
 * its map takes six faces), the slab turned to face +z, +x, −y and −z in turn (the camera before
 * it); then aimed (the box gone): the slab turned 45° to it, and a spot light in its place.
 */
const nodePointLight = ({ backend }) => slabLightFrames({
  backend, thicknessMm: 1,
  lights: (T) => {
    const bulb = new T.PointLight(0xffffff, Math.PI * 4, 0, 2);
    const spot = new T.SpotLight(0xffffff, Math.PI * 4, 0, Math.PI / 8, 0, 2);
    spot.position.set(0, 0, -2);
    bulb.visible = false;
    return { bulb, spot };
  },
  steps: (node, { bulb, spot }, { scene, camera, slab, skin }) => {
    const beyond = new THREE.Mesh(new THREE.BoxGeometry(0.1, 0.1, 0.1), skin);
    beyond.position.set(0, 0, -4); // behind the spot light
    scene.add(beyond);
    const facing = (n) => () => {
      const normal = new THREE.Vector3(...n);
      slab.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
      camera.up.set(0, n[1] === 0 ? 1 : 0, n[1] === 0 ? 0 : 1);
      camera.position.copy(normal).multiplyScalar(0.3);
      camera.lookAt(0, 0, 0);
      bulb.position.copy(normal).multiplyScalar(-2);
      beyond.position.copy(normal).multiplyScalar(-4);
    };
    const aimed = () => {
      scene.remove(beyond);
      slab.quaternion.identity();
      slab.rotation.y = Math.PI / 4;
      camera.up.set(0, 1, 0);
      camera.position.set(0, 0, 0.3);
      camera.lookAt(0, 0, 0);
      bulb.position.set(-0.5, 0, -0.5);
      bulb.intensity = 2;
    };
    return [
      ['spot behind', () => { node.light = spot; }],
      ['+z', () => { spot.visible = false; bulb.visible = true; node.light = bulb; facing([0, 0, 1])(); }], ['+x', facing([1, 0, 0])], ['-y', facing([0, -1, 0])], ['-z', facing([0, 0, -1])],
      ['aimed', aimed],
      ['spot', () => { // its cone edge outside the slab
        Object.assign(spot, { visible: true, intensity: 2, angle: Math.PI / 4 });
        spot.position.copy(bulb.position);
        bulb.visible = false;
        node.light = spot;
      }],
    ];
  },
});

/** `light: 'castShadow'` on the node: the casters listed, found, one fewer, five. */
const nodeCastShadow = ({ backend }) => slabLightFrames({
  backend, thicknessMm: 1.5,
  lights: (T) => {
    const { behind: sun, spot, bulb } = FOUR_LIGHTS(T);
    sun.castShadow = spot.castShadow = true; // the bulb casts none
    return { sun, spot, bulb };
  },
  steps: (node, l, { scene }) => {
    const extra = Array.from({ length: 3 }, () => Object.assign(new THREE.SpotLight(0xffffff, 0), { castShadow: true }));
    return [
      ['listed', () => { node.light = [l.sun, l.spot]; }],
      ['castShadow', () => { node.light = 'castShadow'; }],
      ['one casts', () => { l.spot.castShadow = false; }],
      ['sun', () => { node.light = l.sun; }],
      ['bulb casts', () => { l.bulb.castShadow = true; node.light = 'castShadow'; }],
      ['six cast', () => { l.spot.castShadow = true; scene.add(...extra); }],
      ['none cast', () => { for (const light of [l.sun, l.spot, l.bulb, ...extra]) light.castShadow = false; }],
    ];
  },
});

/**
 * A row of the WebGL scene graph matrix through the node: test/pages/sceneGraph.js's scenes (the
 * feature, and where the row has one the same picture drawn without it), drawn by three's own
 * RenderPipeline ('plain': the scene pass alone) and by the node with scattering and transmittance
 * off and on (its materials: the scene's 'skin' ones made subsurface), each the second of two
 * frames, read as floats. Returns the comparisons (sceneGraph.js's compare) and each frame's render
 * and draw calls, the light maps drawn, the node's plan, its meshes on the screen and problems.
 */
async function sceneGraphRow({ backend = 'webgpu', name }) {
  const [width, height] = [SCENE_GRAPH_WIDTH, SCENE_GRAPH_HEIGHT];
  const renderer = await sharedRenderer(backend, width, height);
  const target = new THREE.RenderTarget(width, height, { type: THREE.FloatType });
  const { feature, reference, referenceOptions } = SCENE_GRAPH_ROWS[name];
  const frame = async ({ scene, camera, light }, mode, options = {}) => {
    const made = new Map(); // one subsurface material per 'skin' material (clones keep sharing theirs)
    scene.traverse((object) => {
      if (object.material?.name !== 'skin') return;
      if (!made.has(object.material)) made.set(object.material, NODE.subsurfaceMaterial(object.material, { widthMm: SCENE_GRAPH_WIDTH_MM }));
      object.material = made.get(object.material);
    });
    const on = mode === 'on';
    const built = mode === 'plain' ? { scenePass: pass(scene, camera, { type: THREE.HalfFloatType }), pipeline: new THREE.RenderPipeline(renderer), node: null }
      : subsurfacePipeline(renderer, scene, camera, { sss: { light, worldUnitInMm: 1000, lightDepthSize: 256, scattering: on, transmittance: on, ...options.pipelineOptions } });
    const { scenePass, pipeline, node } = built;
    if (!node) Object.assign(pipeline, { outputColorTransform: false, outputNode: scenePass });
    let counts;
    for (let i = 0; i < 2; i++) {
      renderer.info.reset();
      renderer.setRenderTarget(target);
      pipeline.render();
      renderer.setRenderTarget(null);
      counts = { calls: renderer.info.render.frameCalls, draws: renderer.info.render.drawCalls };
      await new Promise((resolve) => { requestAnimationFrame(() => resolve()); }); // the light stage runs once a frame
    }
    const result = {
      pixels: await readFloats(renderer, target), ...counts,
      lightMaps: node ? node.lightDepths.filter((d) => d.valid).length : 0,
      plan: node ? { blur: node.plan.blur, samples: node.plan.samples } : null,
      onScreen: node ? node.frame.onScreen.length : 0,
      problems: node ? [...node.problems] : [],
    };
    node?.dispose();
    pipeline.dispose();
    scenePass.dispose();
    scene.traverse((object) => { object.geometry?.dispose(); object.material?.dispose?.(); object.material?.map?.dispose(); });
    for (const [material, subsurface] of made) { material.dispose(); subsurface.dispose(); }
    return result;
  };
  const plain = await frame(feature(), 'plain');
  const off = await frame(feature(), 'off');
  const on = await frame(feature(), 'on');
  const ref = reference ? await frame(reference(), 'on', referenceOptions) : null;
  target.dispose();
  const strip = ({ pixels, ...rest }) => rest;
  return {
    offVsPlain: compare(off.pixels, plain.pixels), onVsOff: compare(on.pixels, off.pixels), onVsReference: ref ? compare(on.pixels, ref.pixels) : null,
    plain: strip(plain), off: strip(off), on: strip(on), reference: ref ? strip(ref) : null,
  };
}

/**
 * The lab's two leaves (test/pages/leaves.js, straight behind a directional light) as node
 * materials bent by a position node of their own (the node's counterpart of a user's vertex hook:
 * the right one a clone of the left, tinted 0.5), at a `time` uniform set after the first frame;
 * and the same bends made in the geometry: the diffuse attachment of each.
 */
async function swayingLeaves({ backend = 'webgpu', width = 96, height = 54, time = 1.3 }) {
  const renderer = await sharedRenderer(backend, width, height);
  const { leafScene, leaf, white } = window.lab;
  const clock = uniform(0);
  const sway = (x) => 0.25 * Math.cos(1.7 * time + 2 * x);
  const left = NODE.subsurfaceMaterial(white(), { widthMm: 1 });
  left.positionNode = positionLocal.add(vec3(0, 0, cos(clock.mul(1.7).add(positionLocal.x.mul(2))).mul(0.25)));
  const right = left.clone();
  right.color.setScalar(0.5);
  const hooked = leafScene(leaf(left, -1.1, 0), leaf(right, 1.1, 0));
  const bent = (x, color) => {
    // Fitted into the light's view as the hooked leaves are (their unbent bounding sphere: a
    // position node may move them anywhere), through a position node that moves nothing.
    const mesh = leaf(NODE.subsurfaceMaterial(white({ color: new THREE.Color().setScalar(color) }), { widthMm: 1 }), x, 0);
    mesh.material.positionNode = positionLocal;
    mesh.geometry.computeBoundingSphere();
    const position = mesh.geometry.attributes.position;
    for (let i = 0; i < position.count; i++) position.setZ(i, position.getZ(i) + sway(position.getX(i)));
    mesh.geometry.computeBoundingBox();
    return mesh;
  };
  const truth = leafScene(bent(-1.1, 1), bent(1.1, 0.5));
  const diffuseOf = async (built, frames) => {
    const { scenePass, node, pipeline } = subsurfacePipeline(renderer, built.scene, built.camera, { type: THREE.FloatType, sss: { worldUnitInMm: 10, light: built.light } });
    for (let k = 0; k < frames; k++) {
      await new Promise((resolve) => { requestAnimationFrame(() => resolve()); }); // a frame each: the scene pass and the light stage run once a frame
      pipeline.render();
      clock.value = time; // after the first frame, as an app's clock moves
    }
    const diffuse = await readFloats(renderer, scenePass.renderTarget, 'diffuse');
    node.dispose();
    pipeline.dispose();
    scenePass.dispose();
    return diffuse;
  };
  const result = { width, height, hooked: await diffuseOf(hooked, 2), truth: await diffuseOf(truth, 1) };
  for (const built of [hooked, truth]) built.scene.traverse((object) => object.material?.dispose());
  return result;
}

window.wgpu = {
  THREE, NODE, pass, createRenderer, readFloats, subsurfacePipeline, flat, disposeFlatRig, head, disposal, plainDraw, debugViews, labScene, labScenePlain, lightDepthCards,
  dollyOpen, dollyFrames, dollyClose, lightAssigned, lightKeyOrder, sameFrame, nearLight, arrayCamera, swayingLeaves, nodeLightList, nodePointLight, nodeCastShadow, boxFrames, sceneGraphRow,
};
window.testReady = true;
