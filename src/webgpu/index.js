// three-separable-sss/webgpu: the subsurface scattering for three.js's WebGPURenderer (WebGPU and
// its WebGL 2 backend) as TSL nodes for RenderPipeline, with the WebGL pipeline's settings and
// profiles. Importing has no side effects and works in plain Node. Needs three r187 or later.
//
//   import { pass } from 'three/tsl';
//   const skin = subsurfaceMaterial(new THREE.MeshStandardMaterial({ map }), { widthMm: 1 });
//   const scenePass = pass(scene, camera);
//   scenePass.setMRT(subsurfaceMRT());
//   pipeline.outputNode = subsurfaceScattering(scenePass, { worldUnitInMm: 1000, light });

// Stage 1: linear depth seen from the light, for transmittance (the node makes one for its `light`).
export { LightDepthNodeTarget } from './1-light-depth/LightDepthNodeTarget.js';

// Stage 2: the diffuse/specular split (node materials) and the MRT it writes into.
export {
  subsurfaceMaterial, subsurfaceMRT, SubsurfaceStandardNodeMaterial, SubsurfacePhysicalNodeMaterial,
} from './2-scene-split/subsurfaceNodeMaterial.js';
export { ATTACHMENT_NAMES } from './2-scene-split/attachments.js';

// Stages 3 and 4 (and 1 for its `light`): the separable blur and the compose, as one node.
export { SubsurfaceScatteringNode, subsurfaceScattering, NODE_METHODS } from './SubsurfaceScatteringNode.js';

// The renderer-free side, shared with the WebGL entry: the settings' defaults and values, the profiles.
export { NODE_DEFAULTS, FOLLOW_SURFACE_MODES, DEBUG_VIEWS } from '../options.js';
export { profiles, getProfile } from '../profiles/presets.js';
