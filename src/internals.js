// three-separable-sss/internals: the plumbing behind the effect, for pipelines built by hand, the
// bench and the tests. UNSTABLE: these names follow the stages' code and may change in any
// release (the main entry, src/index.js, is the stable API). Importing has no side effects and
// works in plain Node, like the main entry.

// The options' schema and the blur's plan.
export {
  METHOD_TABLE, AUTO_SAMPLES, AUTO_REACH, PIPELINE_SCHEMA, MATERIAL_SCHEMA, PIPELINE_OPTIONS, MATERIAL_OPTIONS,
  checkPipelineOptions, checkMaterialOptions,
} from './options.js';
export { planBlur, autoSampleCount, BLUR_MODES } from './3-blur/blurPlan.js';
export { planFrame, estimatePixelsPerMm, nearestViewDepth } from './framePlan.js';
export { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';
export { BlurStage, useDenseReference } from './3-blur/BlurStage.js';

// Stage 2's draw phases and stage 3's modes.
export { DRAW_PHASES } from './2-scene-split/subsurfaceTarget.js';
export { footprintsOf, KERNEL_MODES } from './3-blur/SubsurfaceBlurPass.js';

// The profiles' GPU tables and their footprint allocation.
export { FootprintTable } from './profiles/FootprintTable.js';
export { footprintAllocation, footprintTable, FOOTPRINT_SCALES } from './profiles/footprints.js';
export { QuadrantEnergyLookup } from './profiles/QuadrantEnergyLookup.js';
export { isPerspective } from './support/screenScale.js';
