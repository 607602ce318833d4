// three-separable-sss/webgpu: the subsurface scattering for three.js's WebGPURenderer (WebGPU and
// its WebGL 2 backend) as TSL nodes for RenderPipeline. Public exports only, by stage; importing
// has no side effects and works in plain Node. Needs three r187 or later (./threeVersion.js).
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

// Stages 3 and 4: the separable blur and the compose, as one node.
export { SubsurfaceScatteringNode, subsurfaceScattering } from './SubsurfaceScatteringNode.js';
export { NODE_DEFAULTS, NODE_METHODS } from './nodeOptions.js';

// The three releases this entry supports (its own floor: r187).
export { WEBGPU_THREE, WEBGPU_THREE_RANGE } from './threeVersion.js';

// The renderer-free side, shared with the WebGL entry.
export { profiles, getProfile } from '../profiles/presets.js';
export { FOLLOW_SURFACE_MODES } from '../options.js';
