// Stage 3's resolution plan, pure (test/node/3-blur/resolutionPlan.test.js), for both renderers:
// at which resolution each of the profile's Gaussians is blurred this frame. A Gaussian of σ pixels
// blurred at level L (1/2^L of the resolution: downsampled in blocks of s = 2^L pixels, blurred
// there, joined back by a bilinear, depth-aware upsample) answers a step edge within
// levelStepError(σ, L) of the full-resolution blur; the error falls as (s / σ)², so the wide
// Gaussians lose nothing measurable at a coarse level while costing 1/4^L of the pixels.
// 'auto' sends each Gaussian to the coarsest level (up to MAX_LEVEL) within LEVEL_STEP_ERROR at the
// frame's largest on-screen scale, from the scale where that shortens the full-resolution kernel's
// reach enough to pay for the downsample and the join (LEVEL_GAIN); a fixed resolution blurs the whole profile at
// its level. Each level's part is its Gaussians' share of the profile, blurred separably as one
// kernel: the parts sum to the profile, and each 2D part is exactly separable per Gaussian, so the
// split also removes part of the one-kernel blur's separable error (src/3-blur/kernelGroups.js).
// Stable under motion (src/3-blur/planRamp.js): a Gaussian moves between levels over PLAN_RAMP of
// scales above the scale where the coarser level starts to hold the bound, its share stepped in
// 1/LEVEL_SHARE_STEPS; the split as a whole fades in over PLAN_RAMP above its scale. docs/ARCHITECTURE.md,
// "Stage 3: resolution by need", says why.
import { erf } from '../math/specialFunctions.js';
import { solveDecreasing } from '../math/roots.js';
import { gaussianSumOf } from '../profiles/gaussianFit.js';
import { PLAN_RAMP, rampShare } from './planRamp.js';

/** The accepted `resolution` values: 'auto', or the whole blur at 1, 1/2 or 1/4 of the resolution. */
export const RESOLUTIONS = Object.freeze(['auto', 1, 0.5, 0.25]);

/** The coarsest level: 1/4 of the resolution along each axis, 1/16 of the pixels. */
export const MAX_LEVEL = 2;

/**
 * 'auto': the most a Gaussian's step-edge response may differ, at its level, from its full
 * resolution blur, a fraction of the step (levelStepError).
 */
export const LEVEL_STEP_ERROR = 0.005;

/**
 * 'auto' splits the profile only from the scale where the Gaussians its levels would leave at full
 * resolution reach at least this fraction less far than the whole profile (their 99 % marginal
 * radius; splitScale), fading the split in over PLAN_RAMP of scale above it: below, the downsample
 * and the join cost about what the shorter kernel saves.
 */
export const LEVEL_GAIN = 0.4;

/**
 * What the downsample (a box of one coarse pixel), the coarse blur's pixel areas and the bilinear
 * upsample add to a blur's variance, about 1/12 + 1/12 + 1/6 coarse pixels²; a coarse level's blur
 * is narrowed by this much (levelNarrowing) so that the level keeps the profile's variance. Of
 * levelStepError's candidates (0, 1/12 … 1/3) it halves the error at both levels.
 */
export const LEVEL_VARIANCE = 1 / 4;

/** A Gaussian's share of a level is stepped in 1/LEVEL_SHARE_STEPS (each step refills a part's table). */
export const LEVEL_SHARE_STEPS = 64;

/** The standard normal's cumulative distribution. */
const normalCdf = (x) => 0.5 * (1 + erf(x / Math.SQRT2));

/**
 * The level of a `resolution` setting: 0 for 1, 1 for 0.5, 2 for 0.25 (null for 'auto').
 * @param {'auto'|number} resolution
 */
export const levelOf = (resolution) => (resolution === 'auto' ? null : Math.round(Math.log2(1 / resolution)));

/**
 * The worst difference, a fraction of the step, between a unit step edge blurred by a Gaussian of
 * `sigmaPx` pixels at full resolution and at `level`, along one axis (a blur along the other axis
 * treats both alike), over every position of the edge in a block and every pixel. Full resolution:
 * each pixel weighed by the Gaussian's energy over it, Φ((k − e + ½) / σ) for an edge before pixel
 * e. At the level: blocks of s = 2^L pixels averaged (a block's value is its share of pixels past
 * the edge), blurred at the block scale with each block's exact energy, then read at each pixel's
 * centre by bilinear interpolation between the two nearest blocks' centres; the level's Gaussian
 * narrowed by LEVEL_VARIANCE coarse pixels² (the resampling adds about that much).
 * @param {number} sigmaPx the Gaussian's standard deviation, full-resolution pixels
 * @param {number} level 0..MAX_LEVEL
 * @returns {number}
 */
export function levelStepError(sigmaPx, level) {
  if (level === 0) return 0;
  const s = 2 ** level;
  const reach = Math.ceil(8 * sigmaPx) + 4 * s;
  // The level's Gaussian in coarse pixels, narrowed as the blur narrows it (levelNarrowing).
  const coarseSigma = Math.sqrt(Math.max((sigmaPx / s) ** 2 * narrowingSquared(sigmaPx / s), 1e-12));
  let worst = 0;
  for (let e = 0; e < s; e++) {
    // The edge before pixel e of block 0: the block's share of pixels past it; blocks after it are 1, before 0.
    const edgeShare = (s - e) / s;
    const coarse = (I) => normalCdf((I - 0.5) / coarseSigma) + edgeShare * (normalCdf((0.5 - I) / coarseSigma) - normalCdf((-I - 0.5) / coarseSigma));
    for (let k = e - reach; k <= e + reach; k++) {
      const u = (k + 0.5) / s - 0.5;
      const below = Math.floor(u);
      const f = u - below;
      const up = (1 - f) * coarse(below) + f * coarse(below + 1);
      worst = Math.max(worst, Math.abs(up - normalCdf((k - e + 0.5) / sigmaPx)));
    }
  }
  return worst;
}

/** The factor² a coarse level's blur of standard deviation `sigmaCoarse` coarse pixels is narrowed by: it loses LEVEL_VARIANCE, at most 3/4 of it. */
const narrowingSquared = (sigmaCoarse) => Math.max(1 - LEVEL_VARIANCE / (sigmaCoarse * sigmaCoarse), 0.25);

/**
 * The factor a coarse level's pass multiplies its scale (pixels per profile mm) by, for a part of
 * variance `varianceMm2` (its widest channel's, mm²) at `pixelsPerMm` of the level: the blur
 * narrowed by LEVEL_VARIANCE pixels², at most halved. The shader's (shaders/3-blur/levels.glsl).
 * @param {number} varianceMm2 @param {number} pixelsPerMm
 */
export const levelNarrowing = (varianceMm2, pixelsPerMm) => Math.sqrt(narrowingSquared(Math.sqrt(varianceMm2) * pixelsPerMm));

const minSigmas = new Map();

/**
 * The narrowest Gaussian, full-resolution pixels of standard deviation, blurred at `level` within
 * `bound` (levelStepError falls as σ grows: a bisection).
 * @param {number} level 1..MAX_LEVEL @param {number} [bound=LEVEL_STEP_ERROR]
 */
export function minSigmaPx(level, bound = LEVEL_STEP_ERROR) {
  const key = `${level}/${bound}`;
  if (!minSigmas.has(key)) {
    let lo = 0.25;
    let hi = 4096;
    for (let i = 0; i < 40; i++) {
      const mid = Math.sqrt(lo * hi);
      if (levelStepError(mid, level) <= bound) hi = mid;
      else lo = mid;
    }
    minSigmas.set(key, hi);
  }
  return minSigmas.get(key);
}

/**
 * The shares of a Gaussian of `sigmaPx` pixels at each level 0..MAX_LEVEL for 'auto': all at the
 * finest level until a coarser one holds the bound at minSigmaPx, then moving to it over PLAN_RAMP
 * of scale (linear in log σ).
 * @param {number} sigmaPx @param {number} [maxLevel=MAX_LEVEL]
 * @returns {number[]} MAX_LEVEL + 1 shares summing to 1
 */
export function levelShares(sigmaPx, maxLevel = MAX_LEVEL) {
  const coarser = (level) => (level > maxLevel ? 0 : Math.min(Math.max(Math.log(sigmaPx / minSigmaPx(level)) / Math.log(PLAN_RAMP), 0), 1));
  return Array.from({ length: MAX_LEVEL + 1 }, (_, level) => (level === 0 ? 1 : coarser(level)) - coarser(level + 1));
}

/**
 * The radius holding 99 % of the marginal's energy of a sum of Gaussians with per-channel weights
 * `weights[i][c]` (normalised per channel), mm: the widest channel's (as ProfileLookup's
 * marginalRadiusMm for a whole profile).
 */
function partRadiusMm(gaussians, weights) {
  let radius = 0;
  for (let c = 0; c < 3; c++) {
    const total = weights.reduce((sum, w) => sum + w[c], 0);
    if (!(total > 1e-9)) continue;
    const tail = (x) => weights.reduce((sum, w, i) => sum + (w[c] / total) * (1 - erf(x / Math.sqrt(2 * gaussians[i].varianceMm2))), 0);
    radius = Math.max(radius, solveDecreasing(tail, 0.01, 0, 1));
  }
  return radius;
}

/**
 * How much less far the Gaussians 'auto' would leave at full resolution reach than the whole
 * profile at `pixelsPerMm` (1 − their 99 % radius / the whole's); it grows with the scale.
 */
function splitGain(gaussians, pixelsPerMm) {
  const near = gaussians.map((g) => {
    const share = levelShares(Math.sqrt(g.varianceMm2) * pixelsPerMm)[0];
    return g.weights.map((w) => w * share);
  });
  return 1 - partRadiusMm(gaussians, near) / partRadiusMm(gaussians, gaussians.map((g) => g.weights));
}

const splitScales = new WeakMap();

/**
 * The scale, pixels per profile mm, from which 'auto' splits `profile` (LEVEL_GAIN): a bisection
 * on the scale, once per profile.
 * @param {object} profile @returns {number}
 */
export function splitScale(profile) {
  if (!splitScales.has(profile)) {
    const { gaussians } = gaussianSumOf(profile);
    let lo = 1 / 64;
    let hi = 4096;
    if (splitGain(gaussians, hi) < LEVEL_GAIN) lo = hi = Infinity;
    for (let i = 0; i < 60 && hi / lo > 1 + 1e-9; i++) {
      const mid = Math.sqrt(lo * hi);
      if (splitGain(gaussians, mid) >= LEVEL_GAIN) hi = mid;
      else lo = mid;
    }
    splitScales.set(profile, hi);
  }
  return splitScales.get(profile);
}

/**
 * One level's part of the profile.
 * @typedef {object} LevelPart
 * @property {number} level 0 (full resolution) .. MAX_LEVEL
 * @property {number[]} members each Gaussian's share in this part (gaussianSumOf's order)
 * @property {number[]} energies the part's share of the profile's energy, per channel
 * @property {boolean} whole the part is the whole profile (its own tables, exact)
 * @property {[number, number]} span the first and last Gaussian with a share (its allocation's set)
 */

/**
 * The resolution plan of one frame.
 * @typedef {object} LevelPlan
 * @property {ReadonlyArray<LevelPart>} parts one per level that holds light this frame, finest first
 * @property {ReadonlyArray<{ varianceMm2: number, weights: number[] }>} gaussians the profile's (gaussianSumOf)
 * @property {string} key the parts' shares: equal keys, equal plans
 */

/**
 * Which Gaussians of `profile` are blurred at which level in a frame whose largest on-screen scale
 * is `pixelsPerMm` (see the header), or null where the whole profile is blurred at full
 * resolution (the one-kernel blur as without levels).
 * @param {object} profile
 * @param {number} pixelsPerMm
 * @param {'auto'|number} resolution one of RESOLUTIONS
 * @returns {LevelPlan|null}
 */
export function planLevels(profile, pixelsPerMm, resolution) {
  const { gaussians } = gaussianSumOf(profile);
  const n = gaussians.length;
  const fixed = levelOf(resolution);
  let shares; // shares[i][level]
  if (fixed !== null) {
    shares = gaussians.map(() => Array.from({ length: MAX_LEVEL + 1 }, (_, level) => (level === fixed ? 1 : 0)));
  } else {
    const worth = rampShare(pixelsPerMm, splitScale(profile) * PLAN_RAMP, PLAN_RAMP);
    const step = (x) => Math.round(x * LEVEL_SHARE_STEPS) / LEVEL_SHARE_STEPS;
    shares = gaussians.map((g) => {
      const coarse = levelShares(Math.sqrt(g.varianceMm2) * pixelsPerMm).map((share, level) => (level === 0 ? 0 : step(worth * share)));
      coarse[0] = 1 - coarse.reduce((sum, share) => sum + share, 0);
      return coarse;
    });
  }
  if (shares.every((levels) => levels[0] === 1)) return null;
  const parts = [];
  for (let level = 0; level <= MAX_LEVEL; level++) {
    const members = shares.map((levels) => levels[level]);
    if (!members.some((m) => m > 0)) continue;
    const energies = [0, 1, 2].map((c) => members.reduce((sum, m, i) => sum + m * gaussians[i].weights[c], 0));
    const first = members.findIndex((m) => m > 0);
    const last = n - 1 - [...members].reverse().findIndex((m) => m > 0);
    parts.push(Object.freeze({ level, members: Object.freeze(members), energies: Object.freeze(energies), whole: members.every((m) => m === 1), span: Object.freeze([first, last]) }));
  }
  return Object.freeze({ parts: Object.freeze(parts), gaussians, key: JSON.stringify(parts.map((p) => [p.level, p.members])) });
}

/**
 * Weights per channel for a part of Gaussians `gaussians` with shares `members`: each channel
 * normalised to 1 over the part; a channel the part holds (almost) nothing of takes the shape of
 * the channel it holds most of (its light is weighed by its energy, about 0: the shape only keeps
 * the blur's loop as long as the part's).
 * @returns {number[][]} [i][c]
 */
export function partWeights(gaussians, members) {
  const energies = [0, 1, 2].map((c) => members.reduce((sum, m, i) => sum + m * gaussians[i].weights[c], 0));
  const most = energies.indexOf(Math.max(...energies));
  return gaussians.map((g, i) => [0, 1, 2].map((c) => {
    const channel = energies[c] > PART_ENERGY_FLOOR ? c : most;
    return (members[i] * g.weights[channel]) / energies[channel];
  }));
}

/** A part's channel below this share of the profile's energy takes another channel's shape (partWeights). */
export const PART_ENERGY_FLOOR = 1e-6;

/**
 * The marginal's integral G(x) = ∫_0^x of a level's part, normalised per channel, at the texels of a
 * ProfileLookup (texel i at x = (i / (width − 1))² · rangeMm): a coarse level's part from its
 * Gaussians in closed form; the full-resolution part as the whole profile's G (`wholeRow`, the
 * lookup's own row: exact for any profile) less the coarse parts' Gaussians, so the parts sum to
 * the exact profile, kept non-decreasing (a fitted profile's coarse Gaussians may overshoot its
 * tail by the fit's error).
 * @param {LevelPlan} plan @param {LevelPart} part
 * @param {Float32Array} wholeRow the whole profile's G, RGBA per texel (ProfileLookup row 1)
 * @param {number} rangeMm the lookup's marginalRangeMm
 * @returns {Float32Array} RGBA per texel (a = 1)
 */
export function partMarginalRow(plan, part, wholeRow, rangeMm) {
  const width = wholeRow.length / 4;
  const { gaussians } = plan;
  const halfErf = gaussians.map((g) => 1 / Math.sqrt(2 * g.varianceMm2));
  const closedForm = (weights, x) => [0, 1, 2].map((c) => weights.reduce((sum, w, i) => sum + w[c] * 0.5 * erf(x * halfErf[i]), 0));
  const out = new Float32Array(width * 4);
  const own = partWeights(gaussians, part.members);
  const coarse = part.level === 0 ? plan.parts.filter((p) => p.level > 0) : [];
  const ownEnergies = part.level === 0 ? [0, 1, 2].map((c) => 1 - coarse.reduce((sum, p) => sum + p.energies[c], 0)) : part.energies;
  const most = ownEnergies.indexOf(Math.max(...ownEnergies));
  for (let t = 0; t < width; t++) {
    const x = (t / (width - 1)) ** 2 * rangeMm;
    let g;
    if (part.level > 0) {
      g = closedForm(own, x);
    } else {
      // Unnormalised: the whole's less each coarse part's energy share of its Gaussians.
      const rest = [0, 1, 2].map((c) => coarse.reduce((sum, p) => sum + p.members.reduce((s, m, i) => s + m * gaussians[i].weights[c] * 0.5 * erf(x * halfErf[i]), 0), 0));
      g = [0, 1, 2].map((c) => {
        const channel = ownEnergies[c] > PART_ENERGY_FLOOR ? c : most;
        return (wholeRow[t * 4 + channel] - rest[channel]) / ownEnergies[channel];
      });
    }
    for (let c = 0; c < 3; c++) out[t * 4 + c] = Math.min(Math.max(g[c], t > 0 ? out[(t - 1) * 4 + c] : 0), 0.5);
    out[t * 4 + 3] = 1;
  }
  return out;
}

/**
 * The radius holding 99 % of a part's marginal (both sides), mm, from its G row (partMarginalRow):
 * the widest channel's, interpolated between texels.
 * @param {Float32Array} row @param {number} rangeMm
 */
export function rowRadiusMm(row, rangeMm) {
  const width = row.length / 4;
  const xOf = (t) => (t / (width - 1)) ** 2 * rangeMm;
  let radius = 0;
  for (let c = 0; c < 3; c++) {
    // 2 (0.5 − G) ≤ 0.01: G ≥ 0.495.
    let t = 0;
    while (t < width && row[t * 4 + c] < 0.495) t++;
    if (t === 0) continue;
    if (t === width) { radius = Math.max(radius, rangeMm); continue; }
    const [a, b] = [row[(t - 1) * 4 + c], row[t * 4 + c]];
    const f = b > a ? (0.495 - a) / (b - a) : 1;
    radius = Math.max(radius, xOf(t - 1) + f * (xOf(t) - xOf(t - 1)));
  }
  return radius;
}

/**
 * The Gaussians `first`..`last` of a plan as a profile (gaussianSumProfile's parts: partWeights
 * of full members): what a level's footprints are allocated for, whatever shares of them the
 * level holds this frame.
 * @param {LevelPlan} plan @param {[number, number]} span
 * @returns {{ varianceMm2: number, weights: number[] }[]}
 */
export function spanGaussians(plan, [first, last]) {
  const members = plan.gaussians.map((_, i) => (i >= first && i <= last ? 1 : 0));
  const weights = partWeights(plan.gaussians, members);
  return plan.gaussians.map((g, i) => ({ varianceMm2: g.varianceMm2, weights: weights[i] })).filter((_, i) => members[i] === 1);
}

/**
 * A part's variance, mm²: the second moment of its channel of most energy, what a coarse level
 * narrows its blur for (levelNarrowing).
 * @param {LevelPlan} plan @param {LevelPart} part
 */
export function partVarianceMm2(plan, part) {
  const c = part.energies.indexOf(Math.max(...part.energies));
  return part.members.reduce((sum, m, i) => sum + m * plan.gaussians[i].weights[c] * plan.gaussians[i].varianceMm2, 0) / part.energies[c];
}
