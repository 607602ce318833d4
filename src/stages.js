// three-separable-sss/stages: the parts the pipeline is made of, one stage per folder, for a
// pipeline built by hand (each pass is a three.js Pass; SubsurfaceScattering shows the order).
// Stable within a minor version, like the main entry. Importing has no side effects.

// Stage 1: linear depth seen from the light, for transmittance.
export { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';

// Stage 2: the scene split into the multi-target, the material hook, transmittance.
export { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
export { makeSubsurface, getSubsurface, MATERIAL_OUTPUTS } from './2-scene-split/subsurfaceMaterial.js';
export { ATTACHMENTS } from './2-scene-split/subsurfaceTarget.js';
export { transmittanceChunk, createTransmittanceUniforms, transmittanceUniformSlots } from './2-scene-split/transmittance.js';

// Stage 3: the separable blur, its kernel and the on-screen scale it is planned from.
export { SubsurfaceBlurPass } from './3-blur/SubsurfaceBlurPass.js';
export { computeKernel, kernelRadiusMm, referenceKernel } from './profiles/kernel.js';
export { ProfileLookup } from './profiles/ProfileLookup.js';
export { pixelsPerMm } from './support/screenScale.js';

// Stage 4: the compose.
export { SubsurfaceComposePass } from './4-compose/SubsurfaceComposePass.js';
