// three-separable-sss: screen-space separable subsurface scattering for three.js.
// The stable API, by stage; importing has no side effects and works in plain Node (no DOM).
// Plumbing for hand-built pipelines, the bench and the tests: three-separable-sss/internals.
import { movedClass, movedConstant, movedFunction } from './support/deprecation.js';
import * as internals from './internals.js';

// The orchestrator: the whole frame as one Pass (in place of a RenderPass), and its options.
export { SubsurfaceScattering } from './SubsurfaceScattering.js';
export { METHODS, FOLLOW_SURFACE_MODES, PIPELINE_DEFAULTS, MATERIAL_DEFAULTS } from './options.js';
export { MAX_PROFILES } from './profiles/profileSlots.js';

// Stage 1: linear depth seen from the light.
export { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';

// Stage 2: the scene split into the multi-target, the material hook, transmittance.
export { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
export { makeSubsurface, getSubsurface, MATERIAL_OUTPUTS } from './2-scene-split/subsurfaceMaterial.js';
export { ATTACHMENTS } from './2-scene-split/subsurfaceTarget.js';
export { transmittanceChunk, createTransmittanceUniforms, transmittanceUniformSlots } from './2-scene-split/transmittance.js';

// Stage 3: the separable blur and the dense 2D reference.
export { SubsurfaceBlurPass } from './3-blur/SubsurfaceBlurPass.js';
export { DenseSubsurfacePass } from './3-blur/DenseSubsurfacePass.js';

// Stage 4: the compose, its debug views.
export { SubsurfaceComposePass, DEBUG_VIEWS, DEBUG_VIEW } from './4-compose/SubsurfaceComposePass.js';

// The maths: profiles, kernels, the profiles' GPU table, the on-screen scale (pure, run in Node).
export { computeKernel, kernelRadiusMm, referenceKernel } from './profiles/kernel.js';
export { profiles, getProfile, transmittance } from './profiles/presets.js';
export { burleyProfile } from './profiles/burley.js';
export { dipoleProfile } from './profiles/dipole.js';
export { gaussianSumProfile } from './profiles/gaussianSum.js';
export { radialProfile } from './profiles/radialProfile.js';
export { ProfileLookup } from './profiles/ProfileLookup.js';
export { pixelsPerMm } from './support/screenScale.js';

// Version 0.2's names that moved to three-separable-sss/internals: deprecated, kept for one minor
// version; each says so once, when first used.
export const planFrame = movedFunction('planFrame', internals.planFrame);
export const autoSampleCount = movedFunction('autoSampleCount', internals.autoSampleCount);
export const estimatePixelsPerMm = movedFunction('estimatePixelsPerMm', internals.estimatePixelsPerMm);
export const isPerspective = movedFunction('isPerspective', internals.isPerspective);
export const footprintsOf = movedFunction('footprintsOf', internals.footprintsOf);
export const footprintAllocation = movedFunction('footprintAllocation', internals.footprintAllocation);
export const footprintTable = movedFunction('footprintTable', internals.footprintTable);
export const METHOD_TABLE = movedConstant('METHOD_TABLE', internals.METHOD_TABLE);
export const AUTO_SAMPLES = movedConstant('AUTO_SAMPLES', internals.AUTO_SAMPLES);
export const KERNEL_MODES = movedConstant('KERNEL_MODES', internals.KERNEL_MODES);
export const DRAW_PHASES = movedConstant('DRAW_PHASES', internals.DRAW_PHASES);
export const FOOTPRINT_SCALES = movedConstant('FOOTPRINT_SCALES', internals.FOOTPRINT_SCALES);
export const QuadrantEnergyLookup = movedClass('QuadrantEnergyLookup', internals.QuadrantEnergyLookup);
export const FootprintTable = movedClass('FootprintTable', internals.FootprintTable);
/** @deprecated import from three-separable-sss/internals */
export const AUTO_REACH = internals.AUTO_REACH; // a number: read without a warning (it cannot say it moved)
/** @deprecated import from three-separable-sss/internals */
export const MIN_KERNEL_PIXELS = internals.MIN_KERNEL_PIXELS; // a number, likewise

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
