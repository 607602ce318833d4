// Stable under motion: where the plan would change discretely with the scale (the 'auto' groups
// and fixed-tap counts, the blur skipped, the resolution levels), it ramps over a range of scales
// instead, so a slow zoom or dolly never changes the whole scattering in one frame. The ramps of
// src/3-blur/blurPlan.js lie below their change (the image there is at least as accurate as with
// the plan below it, and costs the plan above it); the resolution's lie above it
// (src/3-blur/resolutionPlan.js: there the coarser level is the less accurate one).

/** The scales a plan change ramps over, as a ratio (a quarter octave: inside 'auto''s steps). */
export const PLAN_RAMP = 2 ** (1 / 4);

/**
 * The share of a ramp ending at `end` over `ratio` of scales: 0 up to end / ratio, 1 from end on,
 * linear in log(x) between.
 * @param {number} x @param {number} end @param {number} ratio > 1 @returns {number}
 */
export function rampShare(x, end, ratio) {
  if (!(x > end / ratio)) return 0;
  return x >= end ? 1 : Math.log((x * ratio) / end) / Math.log(ratio);
}
