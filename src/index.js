// three-separable-sss: screen-space separable subsurface scattering for three.js.
// Public exports only, by stage; importing has no side effects and works in plain Node (no DOM).

// The orchestrator: the whole frame as one Pass (in place of a RenderPass).
export { SubsurfaceScattering, MIN_KERNEL_PIXELS } from './SubsurfaceScattering.js';
export { METHODS, METHOD_TABLE, AUTO_SAMPLES, AUTO_REACH, FOLLOW_SURFACE_MODES, PIPELINE_DEFAULTS, MATERIAL_DEFAULTS } from './options.js';
export { planFrame, autoSampleCount, estimatePixelsPerMm } from './framePlan.js';

// Stage 1: linear depth seen from the light.
export { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';

// Stage 2: the scene split into the multi-target, the material hook, transmittance.
export { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
export { makeSubsurface, getSubsurface, MATERIAL_OUTPUTS } from './2-scene-split/subsurfaceMaterial.js';
export { ATTACHMENTS, DRAW_PHASES } from './2-scene-split/subsurfaceTarget.js';
export {
  transmittanceChunk, createTransmittanceUniforms, transmittanceUniformSlots,
} from './2-scene-split/transmittance.js';

// Stage 3: the separable blur and the dense 2D reference.
export { SubsurfaceBlurPass, footprintsOf, KERNEL_MODES } from './3-blur/SubsurfaceBlurPass.js';
export { DenseSubsurfacePass } from './3-blur/DenseSubsurfacePass.js';

// Stage 4: the compose, its debug views.
export { SubsurfaceComposePass, DEBUG_VIEWS, DEBUG_VIEW } from './4-compose/SubsurfaceComposePass.js';

// The maths: profiles, kernels and their GPU tables (pure, run in Node).
export { computeKernel, kernelRadiusMm, referenceKernel } from './profiles/kernel.js';
export { profiles, getProfile, transmittance } from './profiles/presets.js';
export { burleyProfile } from './profiles/burley.js';
export { dipoleProfile } from './profiles/dipole.js';
export { gaussianSumProfile } from './profiles/gaussianSum.js';
export { radialProfile } from './profiles/radialProfile.js';
export { ProfileLookup } from './profiles/ProfileLookup.js';
export { FootprintTable } from './profiles/FootprintTable.js';
export { footprintAllocation, footprintTable, FOOTPRINT_SCALES } from './profiles/footprints.js';
export { QuadrantEnergyLookup } from './profiles/QuadrantEnergyLookup.js';
export { pixelsPerMm, isPerspective } from './support/screenScale.js';

// Types only (for TypeScript; the declarations are generated from this JSDoc): the options' shapes
// and the string-literal unions of every enumerated option.
/** @typedef {import('./SubsurfaceScattering.js').SubsurfaceScatteringOptions} SubsurfaceScatteringOptions */
/** @typedef {import('./SubsurfaceScattering.js').SubsurfaceMaterialOptions} SubsurfaceMaterialOptions */
/** @typedef {import('./SubsurfaceScattering.js').StageName} StageName */
/** @typedef {import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding} SubsurfaceBinding */
/** @typedef {import('./options.js').Method} Method */
/** @typedef {import('./options.js').FollowSurfaceMode} FollowSurfaceMode */
/** @typedef {import('./options.js').ProfileName} ProfileName */
/** @typedef {import('./4-compose/debugViews.js').DebugView} DebugView */
