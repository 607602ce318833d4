// The browser side of the WebGPURenderer tests (test/browser/webgpu*.test.js): the library's
// `three-separable-sss/webgpu` node on WebGPU or on WebGPURenderer's WebGL 2 backend
// (`backend: 'webgl'`, forceWebGL), on the scenes the WebGL path's tests use, read back as floats.
// Nothing here is part of the library.
import * as THREE from 'three/webgpu';
import { pass } from 'three/tsl';
import * as NODE from '/src/webgpu/index.js';
import { flatScene } from './flatScene.js';
import { loadHead } from '/demo/headModel.js';
import { createHeadScene, FACE_CENTRE, HEAD_WORLD_UNIT_IN_MM } from '/demo/headScene.js';
import './lab.js'; // window.lab: the WebGL pipeline's side of the comparisons

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

/** Any texture of a render target as RGBA 32-bit floats, rows as the backend stores them. */
async function readFloats(renderer, target, index = 0) {
  const { width, height } = target;
  if (typeof index === 'string') index = target.textures.findIndex((t) => t.name === index);
  const data = await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height, index);
  if (data instanceof Float32Array) return data;
  if (data instanceof Uint16Array) return Float32Array.from(data, THREE.DataUtils.fromHalfFloat);
  throw new TypeError(`readFloats: unexpected ${data.constructor.name}`);
}

/** The subsurface pass and node over `scene` seen by `camera`, in a RenderPipeline. */
function subsurfacePipeline(renderer, scene, camera, { type = THREE.HalfFloatType, sss = {} } = {}) {
  const scenePass = pass(scene, camera, { type });
  scenePass.setMRT(NODE.subsurfaceMRT());
  const node = NODE.subsurfaceScattering(scenePass, sss);
  const pipeline = new THREE.RenderPipeline(renderer);
  pipeline.outputColorTransform = false; // linear HDR out, as the WebGL lab's composer without OutputPass
  pipeline.outputNode = node;
  return { scenePass, node, pipeline };
}

/** The analytic accuracy scene (flatScene.js) through the node: the diffuse light before the blur and after it. */
async function flat({ width = 256, height = 256, backend = 'webgpu', sss = {}, ...options }) {
  const renderer = await sharedRenderer(backend, width, height);
  const { scene, camera, material, map } = flatScene({ width, height, ...options });
  const skin = NODE.subsurfaceMaterial(material, { widthMm: 1 });
  scene.traverse((object) => { if (object.material === material) object.material = skin; });
  const { scenePass, node, pipeline } = subsurfacePipeline(renderer, scene, camera, { type: THREE.FloatType, sss: { worldUnitInMm: 1, ...sss } });
  pipeline.render();
  const before = await readFloats(renderer, scenePass.renderTarget, 'diffuse');
  const after = await readFloats(renderer, node._scatteredTarget);
  const result = { width, height, before, after, blur: node.plan.blur, plan: node.plan };
  node.dispose();
  pipeline.dispose();
  scenePass.dispose();
  skin.dispose();
  material.dispose();
  map.dispose();
  return result;
}

let headPromise = null;

/** A fresh head scene framing the face (a clone of the mesh and its material: each renderer converts its own). */
async function headRig(aspect) {
  headPromise ??= loadHead({ base: '/' });
  const loaded = await headPromise;
  const mesh = loaded.mesh.clone();
  mesh.material = loaded.mesh.material.clone();
  const rig = createHeadScene(mesh);
  rig.camera.aspect = aspect;
  rig.camera.updateProjectionMatrix();
  rig.camera.lookAt(FACE_CENTRE);
  rig.camera.updateMatrixWorld();
  return { ...rig, isStandIn: loaded.isStandIn };
}

/** 8-bit RGBA of a float read-back, as a canvas stores it (rounded, clamped), rows flipped when asked. */
function toBytes(floats, width, height, flipRows) {
  const bytes = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    const from = (flipRows ? height - 1 - y : y) * width * 4;
    for (let i = 0; i < width * 4; i++) bytes[y * width * 4 + i] = Math.round(Math.min(Math.max(floats[from + i], 0), 1) * 255);
  }
  return bytes;
}

/**
 * The demo's head through both renderers, tone mapped (ACES) and sRGB-encoded, as 8-bit RGBA rows
 * bottom-up: the WebGL pipeline in an EffectComposer with OutputPass, and the node in a
 * RenderPipeline on `backend`; with `sss: false` each renderer's plain frame instead (the baseline
 * difference between the two renderers). Shadows off: the renderers filter shadow maps differently.
 */
async function head({ width = 320, height = 180, backend = 'webgpu', sss = true }) {
  const L = window.lab;
  const glRig = await headRig(width / height);
  const gl = L.createRenderer(width, height);
  gl.toneMapping = L.THREE.ACESFilmicToneMapping;
  const composer = L.createComposer(gl);
  if (sss) {
    const pipeline = new L.SSS.SubsurfaceScattering({ scene: glRig.scene, camera: glRig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: null });
    pipeline.makeSubsurface(glRig.head.material, { widthMm: 1 });
    composer.addPass(pipeline);
  } else {
    composer.addPass(new L.RenderPass(glRig.scene, glRig.camera));
  }
  composer.addPass(new L.OutputPass());
  composer.render();
  const webgl = toBytes(await L.read(gl, composer.readBuffer), width, height, false);
  composer.dispose();
  gl.dispose();
  gl.forceContextLoss();

  const rig = await headRig(width / height);
  const renderer = await createRenderer(width, height, { backend });
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const target = new THREE.RenderTarget(width, height, { type: THREE.HalfFloatType });
  let disposeAll;
  if (sss) {
    rig.head.material = NODE.subsurfaceMaterial(rig.head.material, { widthMm: 1 });
    const built = subsurfacePipeline(renderer, rig.scene, rig.camera, { sss: { worldUnitInMm: HEAD_WORLD_UNIT_IN_MM } });
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
  const node = toBytes(await readFloats(renderer, target), width, height, backend === 'webgpu');
  disposeAll();
  target.dispose();
  renderer.dispose();
  return { width, height, webgl, node, isStandIn: rig.isStandIn };
}

window.wgpu = { THREE, NODE, pass, createRenderer, readFloats, subsurfacePipeline, flat, head };
window.testReady = true;
