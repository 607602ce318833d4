// three-separable-sss: screen-space separable subsurface scattering for three.js.
// Public exports only; importing has no side effects and works in plain Node (no DOM).
export { computeKernel, kernelRadiusMm, referenceKernel } from './kernel.js';
export { profiles, getProfile, burleyProfile, dipoleProfile, transmittance } from './profiles.js';
export { LightDepthTarget } from './LightDepthTarget.js';
export { ProfileLookup } from './ProfileLookup.js';
export {
  makeSubsurface, getSubsurface, transmittanceChunk, createTransmittanceUniforms, transmittanceUniformSlots,
} from './subsurfaceMaterial.js';
export { SubsurfaceScenePass } from './SubsurfaceScenePass.js';
export { SubsurfaceBlurPass, footprintsOf, FOLLOW_SURFACE_MODES, KERNEL_MODES } from './SubsurfaceBlurPass.js';
export { SubsurfaceComposePass, DEBUG_VIEWS } from './SubsurfaceComposePass.js';
export { SubsurfaceScattering, MIN_KERNEL_PIXELS, METHODS, AUTO_SAMPLES, AUTO_REACH } from './SubsurfaceScattering.js';
export { QuadrantEnergyLookup } from './QuadrantEnergyLookup.js';
export { DenseSubsurfacePass } from './DenseSubsurfacePass.js';
