// The browser side of the WebGPURenderer tests (test/browser/webgpu*.test.js): the library's
// `three-separable-sss/webgpu` node on WebGPU or on WebGPURenderer's WebGL 2 backend
// (`backend: 'webgl'`, forceWebGL), on the scenes the WebGL path's tests use, read back as floats.
// Nothing here is part of the library.
import * as THREE from 'three/webgpu';
import { pass } from 'three/tsl';
import * as NODE from '/src/webgpu/index.js';
import { flatScene } from './flatScene.js';

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
  const renderer = await createRenderer(width, height, { backend });
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
  renderer.dispose();
  return result;
}

window.wgpu = { THREE, NODE, pass, createRenderer, readFloats, subsurfacePipeline, flat };
window.testReady = true;
