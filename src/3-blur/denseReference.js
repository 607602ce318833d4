// The dense 2D reference in a pipeline, for validation only (the tests and the bench reach it
// through three-separable-sss/internals): a module of its own, so the product's bundle holds
// neither the pass nor its shader.
import { DenseSubsurfacePass } from './DenseSubsurfacePass.js';

/**
 * Has `pipeline` blur with the dense 2D reference, a brute-force 2D convolution with its one
 * profile whose cost grows with the square of the on-screen radius, instead of its separable
 * passes; `enabled` false puts the passes back. A RangeError (nothing changed) while its materials
 * use several profiles.
 * @param {{ _blur: import('./BlurStage.js').BlurStage }} pipeline a SubsurfaceScattering
 * @param {boolean} [enabled=true]
 * @returns {DenseSubsurfacePass|null} the dense pass (its coverage, radius), or null when disabled
 */
export function useDenseReference(pipeline, enabled = true) {
  if (typeof enabled !== 'boolean') throw new TypeError(`useDenseReference: enabled must be a boolean, got ${typeof enabled}`);
  pipeline._blur.setDenseReference(enabled, DenseSubsurfacePass);
  return enabled ? pipeline._blur.densePass : null;
}
