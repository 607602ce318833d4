// Stage 3's plan for one frame, pure (test/node/3-blur/blurPlan.test.js): which blur runs, with how many
// taps, and how far it reaches on screen. BlurStage calls it with the settings it owns; the only
// input from outside is the scene's scale (pixels per profile mm, src/framePlan.js's
// estimatePixelsPerMm). BLUR_MODES is the dispatch on METHOD_TABLE's `blur` column (and the dense
// reference, which validates them): no method is compared by name anywhere else in the stage.
import { AUTO_REACH, AUTO_SAMPLES, METHOD_TABLE } from '../options.js';
import { AUTO_MAX_SAMPLES } from '../profiles/footprints.js';
import { MIN_KERNEL_PIXELS } from './samplingModel.js';
import { MAX_KERNEL_GROUPS, fadedGrouping, groupingStepEnd, kernelGroupsAt } from './kernelGroups.js';

// Stable under motion: where the plan would change discretely with the scale (the 'auto' groups
// and fixed-tap counts, the blur skipped), it ramps over a range of scales instead, so a slow zoom
// or dolly never changes the whole scattering in one frame. Each ramp lies below the change: the
// image there is at least as accurate as with the plan below it, and costs the plan above it.

/** The scales a plan change ramps over, as a ratio (a quarter octave: inside 'auto''s steps). */
export const PLAN_RAMP = 2 ** (1 / 4);

/**
 * The blur fades in over the reaches from MIN_KERNEL_PIXELS to this, pixels: the compose shows
 * plan.fade of the scattered light and the rest unblurred, so the skip below half a pixel is no step.
 */
export const FADE_IN_PIXELS = 1;

/** A faded grouping's share is stepped in 1/GROUP_SHARE_STEPS (each step refills the blur's fraction table). */
export const GROUP_SHARE_STEPS = 64;

/**
 * The share of a ramp ending at `end` over `ratio` of scales: 0 up to end / ratio, 1 from end on,
 * linear in log(x) between.
 * @param {number} x @param {number} end @param {number} ratio > 1 @returns {number}
 */
export function rampShare(x, end, ratio) {
  if (!(x > end / ratio)) return 0;
  return x >= end ? 1 : Math.log((x * ratio) / end) / Math.log(ratio);
}

/**
 * 'auto' taps of the fixed-tap methods: the fewest of AUTO_SAMPLES whose (samples - 3) / 2
 * single-pixel footprints per side reach AUTO_REACH of `radiusPx`, the on-screen radius holding
 * 99 % of the marginal's energy; the largest when none does.
 * @param {number} radiusPx
 * @returns {number}
 */
export function autoSampleCount(radiusPx) {
  return AUTO_SAMPLES.find((n) => (n - 3) / 2 >= AUTO_REACH * radiusPx) ?? AUTO_SAMPLES[AUTO_SAMPLES.length - 1];
}

/**
 * 'auto' fixed taps just below the radius where autoSampleCount takes the next count: both
 * kernels, the next one at `share` (rampShare over PLAN_RAMP), as one kernel of their taps
 * (blendKernels); null elsewhere, and where the two exceed the taps the blur is compiled for.
 * @param {number} radiusPx @returns {{ from: number, to: number, share: number }|null}
 */
export function autoTapBlend(radiusPx) {
  const from = autoSampleCount(radiusPx);
  const to = AUTO_SAMPLES[AUTO_SAMPLES.indexOf(from) + 1];
  if (to === undefined || from + to - 1 > AUTO_SAMPLES[AUTO_SAMPLES.length - 1]) return null;
  const share = rampShare(radiusPx, (from - 3) / 2 / AUTO_REACH, PLAN_RAMP);
  return share > 0 ? { from, to, share } : null;
}

/**
 * Two kernels of computeKernel's layout as one: every tap of both, `a`'s weights times 1 − share
 * and `b`'s times share, one centre. Without dropped taps the blur answers exactly
 * (1 − share) · a's blur + share · b's.
 * @param {Float32Array} a @param {Float32Array} b @param {number} share
 * @returns {Float32Array} (a.length + b.length) / 4 − 1 taps
 */
export function blendKernels(a, b, share) {
  const out = new Float32Array(a.length + b.length - 4);
  for (let c = 0; c < 3; c++) out[c] = (1 - share) * a[c] + share * b[c];
  const add = (kernel, scale, at) => {
    for (let i = 4; i < kernel.length; i += 4) {
      for (let c = 0; c < 3; c++) out[at + i - 4 + c] = scale * kernel[i + c];
      out[at + i - 1] = kernel[i + 3];
    }
  };
  add(a, 1 - share, 4);
  add(b, share, a.length);
  return out;
}

/**
 * What the blur stage knows when it plans (all its own data).
 * @typedef {object} BlurSettings
 * @property {import('../options.js').Method} method
 * @property {number|'auto'} samples the taps asked for
 * @property {boolean} scattering the blur is switched on
 * @property {number} marginalRadiusMm the radius holding 99 % of the profile's marginal, mm
 * @property {boolean} [dense=false] the dense reference runs instead of the method's passes
 * @property {number} denseRadiusMm the dense reference's reach, mm
 * @property {Readonly<Record<number, number>>} kernelReachMm the fixed-tap kernel's outermost tap,
 *   mm, for each count the plan can choose (the count asked for, or every AUTO_SAMPLES for 'auto')
 * @property {'auto'|number} [kernelGroups=1] the isotropic blur's groups asked for (1: one kernel)
 * @property {ReadonlyArray<object>} [profiles] the frame's profiles, by slot (needed with groups)
 */

/**
 * The isotropic blur's groups for a frame whose largest on-screen scale is `pixelsPerMm`, per
 * slot, or null for one kernel: a count, that many in every slot; 'auto', one kernel where every
 * slot's profile is within kernelGroups.js's error budget with one group at that scale (a far
 * head), else MAX_KERNEL_GROUPS (fewer for a profile of fewer Gaussians). 'auto' goes no lower:
 * three groups measured about four's time (the groups' work is per tap, not per group), and one
 * count keeps one set of programs.
 * @param {BlurSettings} settings @param {number} pixelsPerMm
 */
export function frameGroupings(settings, pixelsPerMm) {
  const setting = settings.kernelGroups ?? 1;
  if (setting === 1) return null; // one kernel (also a planner that names no groups)
  const count = setting === 'auto' ? MAX_KERNEL_GROUPS : setting;
  const groupsAt = (scale) => settings.profiles.map((profile) => kernelGroupsAt(profile, scale, count));
  const oneKernelAt = (scale) => settings.profiles.every((profile) => kernelGroupsAt(profile, scale, 'auto').count === 1);
  if (setting !== 'auto' || !oneKernelAt(pixelsPerMm)) return groupsAt(pixelsPerMm);
  // Just below the step where one kernel leaves the budget, the groups fade in (fadedGrouping).
  const next = groupingStepEnd(pixelsPerMm) * (1 + 1e-9); // inside the next step
  if (oneKernelAt(next)) return null;
  const share = Math.round(rampShare(pixelsPerMm, next, PLAN_RAMP) * GROUP_SHARE_STEPS) / GROUP_SHARE_STEPS;
  return share > 0 ? groupsAt(next).map((grouping) => fadedGrouping(grouping, share)) : null;
}

/**
 * What each blur mode of METHOD_TABLE, and the dense reference, does:
 * - passes: the separable pair ('separable') or the dense 2D pass ('dense');
 * - autoSamples(radiusPx): the taps 'auto' takes for the on-screen radius of the marginal's 99 %;
 * - tapBlend(radiusPx) (fixed taps): 'auto''s ramp between two counts there (autoTapBlend), or null;
 * - reachMm(settings, samples): how far the blur reaches, mm (below half a pixel nothing moves);
 * - groupings(settings, pixelsPerMm): the isotropic blur's groups per slot (frameGroupings), or
 *   null where the mode blurs with one kernel (fixed taps) or is isotropic already (dense).
 */
export const BLUR_MODES = Object.freeze({
  footprint: Object.freeze({
    passes: 'separable',
    // Footprints choose their taps per pixel from the table (src/profiles/footprints.js): the frame
    // keeps the budget, the pixel takes what its scale needs.
    autoSamples: () => AUTO_MAX_SAMPLES,
    // The tail is sampled at least a pixel out: the reach is the marginal's 99 % radius.
    reachMm: (settings) => settings.marginalRadiusMm,
    groupings: frameGroupings,
  }),
  taps: Object.freeze({
    passes: 'separable',
    autoSamples: autoSampleCount,
    tapBlend: autoTapBlend,
    reachMm: (settings, samples) => reachOfTaps(settings, samples),
    groupings: () => null,
  }),
  dense: Object.freeze({
    passes: 'dense',
    autoSamples: () => AUTO_MAX_SAMPLES, // unused by the dense pass
    reachMm: (settings) => settings.denseRadiusMm,
    groupings: () => null,
  }),
});

function reachOfTaps(settings, samples) {
  const reach = settings.kernelReachMm[samples];
  if (reach === undefined) throw new RangeError(`planBlur: no kernel reach for ${samples} taps (kernelReachMm has ${Object.keys(settings.kernelReachMm).join(', ')})`);
  return reach;
}

/**
 * Refuses `count` profiles in one frame for a method that blurs fewer (METHOD_TABLE's `profiles`),
 * or for the dense reference, which holds one profile's table: a RangeError naming the method (or
 * the reference), the materials' `profile` and the methods that would do.
 * @param {import('../options.js').Method} method
 * @param {number} count
 * @param {boolean} [dense=false] the dense reference runs instead of the method
 */
export function checkProfileCount(method, count, dense = false) {
  if (dense && count > 1) throw new RangeError(`SubsurfaceScattering: the dense reference blurs 1 profile per frame and the materials use ${count} (their \`profile\`); use one profile`);
  const most = METHOD_TABLE[method].profiles;
  if (count <= most) return;
  const methods = Object.keys(METHOD_TABLE).filter((m) => METHOD_TABLE[m].profiles >= count).map((m) => `'${m}'`).join(' or ');
  throw new RangeError(`SubsurfaceScattering: method '${method}' blurs ${most} profile per frame and the materials use ${count} (their \`profile\`); use method ${methods}, or one profile`);
}

/** The BLUR_MODES entry of a method, or the dense reference's. @param {import('../options.js').Method} method @param {boolean} [dense=false] */
export function blurModeOf(method, dense = false) {
  return dense ? BLUR_MODES.dense : BLUR_MODES[METHOD_TABLE[method].blur];
}

/**
 * The plan of one frame's stage 3.
 * @typedef {object} BlurPlan
 * @property {number} samples the taps this frame (the budget for 'footprint'; both kernels' with tapBlend)
 * @property {{ from: number, to: number, share: number }|null} tapBlend 'auto' fixed taps between two
 *   counts: the kernel is blendKernels of theirs (autoTapBlend)
 * @property {number} kernelPixels the largest on-screen reach of the kernel, pixels
 * @property {boolean} blur whether the blur stage runs (not below half a pixel, not switched off)
 * @property {number} fade the share of the blurred light the compose shows, the rest unblurred:
 *   rampShare of kernelPixels up to FADE_IN_PIXELS (0 where the blur does not run)
 * @property {'separable'|'dense'} passes which passes run
 * @property {number} groups the isotropic blur's groups holding light this frame (1: one kernel)
 * @property {ReadonlyArray<object>|null} groupings their kernelGroups per slot (null: one kernel)
 */

/**
 * @param {BlurSettings} settings
 * @param {number} pixelsPerMm the largest on-screen size of a profile millimetre over the
 *   subsurface surfaces drawn (0 when none is)
 * @returns {BlurPlan}
 */
export function planBlur(settings, pixelsPerMm) {
  const mode = blurModeOf(settings.method, settings.dense);
  const radiusPx = settings.marginalRadiusMm * pixelsPerMm;
  const tapBlend = settings.samples === 'auto' ? mode.tapBlend?.(radiusPx) ?? null : null;
  const counts = tapBlend ? [tapBlend.from, tapBlend.to] : [settings.samples === 'auto' ? mode.autoSamples(radiusPx) : settings.samples];
  const kernelPixels = Math.max(...counts.map((n) => mode.reachMm(settings, n))) * pixelsPerMm;
  const groupings = mode.groupings(settings, pixelsPerMm);
  const fade = settings.scattering ? rampShare(kernelPixels, FADE_IN_PIXELS, FADE_IN_PIXELS / MIN_KERNEL_PIXELS) : 0;
  return {
    samples: tapBlend ? tapBlend.from + tapBlend.to - 1 : counts[0], tapBlend, kernelPixels, blur: fade > 0, fade, passes: mode.passes,
    groups: groupings ? Math.max(...groupings.map((g) => g.count)) : 1, groupings,
  };
}
