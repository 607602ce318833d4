// three-separable-sss: screen-space separable subsurface scattering for three.js.
// What a user of the effect needs: the pipeline (one Pass in place of a RenderPass), its options'
// defaults and values, and the diffusion profiles. Importing has no side effects and works in
// plain Node (no DOM).
//   three-separable-sss/stages      the stages' parts, for a pipeline built by hand
//   three-separable-sss/internals   the plumbing the tests and the bench reach (unstable)

// The pipeline and its options.
export { SubsurfaceScattering } from './SubsurfaceScattering.js';
export {
  PIPELINE_DEFAULTS, MATERIAL_DEFAULTS, METHODS, FOLLOW_SURFACE_MODES, DEBUG_VIEWS,
} from './options.js';
export { MAX_PROFILES } from './profiles/profileSlots.js';

// The diffusion profiles: the presets by name, and the three families a profile is built from.
export { profiles, getProfile, transmittance } from './profiles/presets.js';
export { burleyProfile } from './profiles/burley.js';
export { dipoleProfile } from './profiles/dipole.js';
export { gaussianSumProfile } from './profiles/gaussianSum.js';
export { radialProfile } from './profiles/radialProfile.js';

// Types only (for TypeScript; the declarations are generated from this JSDoc).
/** @typedef {import('./options.js').SubsurfaceScatteringOptions} SubsurfaceScatteringOptions */
/** @typedef {import('./options.js').SubsurfaceMaterialOptions} SubsurfaceMaterialOptions */
/** @typedef {import('./SubsurfaceScattering.js').StageName} StageName */
/** @typedef {import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding} SubsurfaceBinding */
/** @typedef {import('./options.js').Method} Method */
/** @typedef {import('./options.js').FollowSurfaceMode} FollowSurfaceMode */
/** @typedef {import('./options.js').ProfileName} ProfileName */
/** @typedef {import('./4-compose/debugViews.js').DebugView} DebugView */
