// The demo on three's WebGPURenderer (index.html?renderer=webgpu): the same head, scene and state
// as the WebGL page, drawn through three-separable-sss/webgpu's node in a RenderPipeline. It
// returns the parts demo/main.js's createPipeline returns, so the panel, the hash, the appliers
// (demo/appliers.js) and the test API drive it unchanged (the ear light preset's list of two lights
// included); what the node lacks (the divider's split, the 'marginal' and 'reference' methods, a
// second profile for the marble piece, per-pass GPU times) is left out and said so. Loaded only
// when asked for (a dynamic import): the WebGL page does not fetch three/webgpu.
import { ACESFilmicToneMapping } from 'three';
import { RenderPipeline, WebGPURenderer } from 'three/webgpu';
import { pass } from 'three/tsl';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { NODE_METHODS, subsurfaceMaterial, subsurfaceMRT, subsurfaceScattering } from '../src/webgpu/index.js';
import { computeKernel } from '../src/profiles/kernel.js';
import { AUTO_MAX_SAMPLES } from '../src/profiles/footprints.js';
import { createHeadScene, createMarblePiece, HEAD_WORLD_UNIT_IN_MM } from './headScene.js';
import { createFoliagePiece } from './foliage.js';

/** Why this browser cannot run WebGPU (no navigator.gpu, no adapter), or null when it can. */
export async function webgpuMissing() {
  if (!navigator.gpu) return 'this browser has no navigator.gpu';
  try {
    return (await navigator.gpu.requestAdapter()) ? null : 'the browser found no WebGPU adapter';
  } catch (error) {
    return `requesting a WebGPU adapter failed (${error.message})`;
  }
}

/** A WebGPURenderer on WebGPU (not its WebGL 2 fallback: the WebGL page is the better one there), in `container`. */
export async function createWebgpuRenderer(container) {
  const renderer = new WebGPURenderer({ antialias: false, powerPreference: 'high-performance' });
  await renderer.init();
  renderer.setSize(container.clientWidth, container.clientHeight);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping; // applied by the RenderPipeline's output, with sRGB
  container.appendChild(renderer.domElement);
  return renderer;
}

/** The node's settings under the WebGL pipeline's names, as the appliers assign them. */
const FORWARDED = ['scattering', 'profile', 'samples', 'kernelGroups', 'strength', 'followSurface', 'depthThresholdMm', 'light', 'lightDepthSize', 'transmittance', 'debugView', 'debugDepthRange'];

/**
 * The node dressed as the WebGL pipeline for demo/appliers.js: the settings it has forwarded,
 * makeSubsurface setting the node material's options, and what it lacks taking no effect
 * (`unsupported` lists what was asked for).
 */
function pipelineFacade(node, skin) {
  const facade = {
    node,
    scenePass: node.scenePass,
    stageTimer: null,
    /** @type {Set<string>} settings the node does not have, asked for since the page opened */
    unsupported: new Set(),
    /** The head's material takes its options; another (the marble piece, the leaves) would need a node material of its own, which the page has not. */
    makeSubsurface(material, { widthMm, translucency, shrinkMm, profile }) {
      if (material === skin) Object.assign(skin, { widthMm, translucency, shrinkMm });
      else facade.unsupported.add(profile ? `a second profile ('${profile}')` : `a second subsurface material ('${material.name}')`);
    },
    removeSubsurface() {},
    /** The kernel view's plot: the marginal kernel the node's footprints come from. */
    get kernel() {
      return computeKernel({ profile: node.profile, method: 'marginal', samples: node.samples === 'auto' ? AUTO_MAX_SAMPLES : node.samples });
    },
  };
  const forward = (name, set = (value) => { node[name] = value; }) => Object.defineProperty(facade, name, { get: () => node[name], set, enumerable: true });
  for (const name of FORWARDED) forward(name);
  forward('method', (method) => {
    if (NODE_METHODS.includes(method)) node.method = method;
    else facade.unsupported.add(`method '${method}'`);
  });
  // No divider (the node shows one image) and no 'reference' kernel to shape.
  Object.defineProperty(facade, 'split', { get: () => 0, set() {}, enumerable: true });
  Object.defineProperty(facade, 'falloff', { get: () => undefined, set() {}, enumerable: true });
  return facade;
}

/**
 * The scene around the head, the orbit controls and the node's RenderPipeline, in the shape of
 * main.js's createPipeline: `composer` renders the pipeline (it follows the renderer's size).
 * @param {import('three/webgpu').WebGPURenderer} renderer
 * @param {{ mesh: import('three').Mesh }} head
 */
export function createWebgpuPipeline(renderer, head) {
  const skin = subsurfaceMaterial(head.mesh.material);
  head.mesh.material = skin;
  const rig = createHeadScene(head.mesh);
  const { scene, camera, light } = rig;
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;
  const marble = createMarblePiece(); // three's own material here: the node holds one profile
  scene.add(marble);
  const foliage = createFoliagePiece(); // three's own material here too, unswayed: WebGPURenderer runs no onBeforeCompile
  scene.add(foliage.piece);

  const scenePass = pass(scene, camera);
  scenePass.setMRT(subsurfaceMRT());
  const node = subsurfaceScattering(scenePass, { worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light, samples: 'auto' });
  const pipeline = new RenderPipeline(renderer);
  pipeline.outputNode = node;
  const composer = { render: () => pipeline.render(), setSize() {}, setPixelRatio() {} };
  return { renderer, head, rig, camera, light, material: skin, marble, foliage, controls, sss: pipelineFacade(node, skin), composer, pipeline, outputPass: null };
}
