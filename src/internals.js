// three-separable-sss/internals: the plumbing behind the effect that the tests and the bench
// reach. UNSTABLE: these names follow the stages' code and may change in any release (the main
// entry and ./stages are the API). Importing has no side effects and works in plain Node.

// The settings' schema and the blur's plan.
export {
  METHOD_TABLE, AUTO_SAMPLES, AUTO_REACH, PIPELINE_SCHEMA, MATERIAL_SCHEMA, NODE_SCHEMA, PIPELINE_OPTIONS, MATERIAL_OPTIONS,
  checkPipelineOptions, checkMaterialOptions,
} from './options.js';
export { planBlur, autoSampleCount, BLUR_MODES } from './3-blur/blurPlan.js';
export { estimatePixelsPerMm, nearestViewDepth } from './framePlan.js';
export { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';
export { BlurStage } from './3-blur/BlurStage.js';
export { useDenseReference } from './3-blur/denseReference.js';
export { DenseSubsurfacePass } from './3-blur/DenseSubsurfacePass.js';

// Stage 2's draw phases and stage 3's modes.
export { DRAW_PHASES } from './2-scene-split/subsurfaceTarget.js';
export { footprintsOf, KERNEL_MODES } from './3-blur/SubsurfaceBlurPass.js';

// The profiles' GPU tables and their footprint allocation.
export { FootprintTable } from './profiles/FootprintTable.js';
export { footprintAllocation, footprintTable, FOOTPRINT_SCALES } from './profiles/footprints.js';
export { QuadrantEnergyLookup } from './profiles/QuadrantEnergyLookup.js';
export { isPerspective } from './support/screenScale.js';
export { DEBUG_VIEW } from './4-compose/debugViews.js';

// The three releases each entry supports.
export { SUPPORTED_THREE, SUPPORTED_THREE_RANGE, WEBGPU_THREE, WEBGPU_THREE_RANGE } from './support/threeVersion.js';
