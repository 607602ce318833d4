/**
 * Separable blur kernels: per-channel weights and offsets (in kernel millimetres) for the two 1D passes.
 *
 * Layout (both methods): a Float32Array of 4·samples, one (weightR, weightG, weightB, offsetMm) per tap,
 * the centre tap (offset 0) first, then the other taps in ascending offset. Each channel's weights sum to 1.
 *
 * Two methods:
 * - 'reference': Jimenez 2012's artist-friendly strength/falloff kernel (REFERENCE §3), reproduced exactly.
 *   It samples the *radial* profile along the axis, which makes the 1D kernel too sharp.
 * - 'marginal': the correct separable approximation of a radial profile R(r): its marginal
 *   a(x) = ∫ R(√(x²+y²)) dy integrated over each tap's footprint, so edges along the blur axes are exact.
 * @module kernel
 */

import { checkNumber, checkOddInteger, checkOneOf, checkRgb, describeValue } from '../support/parameterChecks.js';
import { solveTailQuantile } from '../math/roots.js';
import { getProfile } from './presets.js';

/** Reference defaults (Jimenez 2012). */
export const REFERENCE_STRENGTH = Object.freeze([0.48, 0.41, 0.28]);
/** Reference defaults (Jimenez 2012). */
export const REFERENCE_FALLOFF = Object.freeze([1.0, 0.37, 0.3]);

const MIN_SAMPLES = 3;
const MAX_SAMPLES = 63;

// d'Eon Gaussians 2..6 with the red weights only: the reference's 1D profile (REFERENCE §3 step 2).
// The narrowest Gaussian (v = 0.0064) is left to the strength mix with the identity.
const REFERENCE_GAUSSIANS = [
  [0.0484, 0.1],
  [0.187, 0.118],
  [0.567, 0.113],
  [1.99, 0.358],
  [7.41, 0.078],
];

/** The reference's 1D profile at offset xMm for one channel (uses 3.14, not π: it cancels on normalising). */
function referenceProfile(xMm, falloff) {
  const y = xMm / (0.001 + falloff);
  let sum = 0;
  for (const [v, w] of REFERENCE_GAUSSIANS) sum += (w * Math.exp((-y * y) / (2 * v))) / (2 * 3.14 * v);
  return sum;
}

/**
 * Mixes a normalised kernel with the identity (REFERENCE §3 step 4): centre (1 − s) + s·w, others s·w.
 * @param {number[][]} weights per tap [r, g, b], centre tap at index 0
 * @param {number[]} strength
 */
function mixStrength(weights, strength) {
  weights.forEach((w, k) => {
    for (let c = 0; c < 3; c++) w[c] = k === 0 ? 1 - strength[c] + strength[c] * w[c] : strength[c] * w[c];
  });
}

/** Divides each channel by its sum. */
function normaliseChannels(weights) {
  for (let c = 0; c < 3; c++) {
    const sum = weights.reduce((s, w) => s + w[c], 0);
    for (const w of weights) w[c] /= sum;
  }
}

/** Packs taps (centre first) into the Float32Array layout. */
function pack(weights, offsets) {
  const out = new Float32Array(4 * weights.length);
  weights.forEach((w, k) => out.set([w[0], w[1], w[2], offsets[k]], 4 * k));
  return out;
}

/**
 * Jimenez 2012's kernel, exactly as REFERENCE §3 describes it.
 * @param {number} samples
 * @param {number[]} strength
 * @param {number[]} falloff
 * @returns {Float32Array}
 */
function referenceMethod(samples, strength, falloff) {
  // 1. offsets: uniform t in [-RANGE, RANGE], quadratic warp sign(t)·t²/RANGE (denser near the centre)
  const range = samples > 20 ? 3 : 2;
  const step = (2 * range) / (samples - 1);
  const offsets = [];
  for (let i = 0; i < samples; i++) {
    const t = -range + i * step;
    offsets.push((Math.sign(t) * t * t) / range);
  }
  // 2-3. weight = profile(offset) · area, area = half the distance to each neighbour
  let weights = offsets.map((o, i) => {
    const w0 = i > 0 ? Math.abs(o - offsets[i - 1]) : 0;
    const w1 = i < samples - 1 ? Math.abs(o - offsets[i + 1]) : 0;
    const area = (w0 + w1) / 2;
    return [0, 1, 2].map((c) => area * referenceProfile(o, falloff[c]));
  });
  // the centre tap moves to the front, the others keep their ascending order
  const mid = (samples - 1) / 2;
  const order = [mid, ...offsets.map((_, i) => i).filter((i) => i !== mid)];
  weights = order.map((i) => weights[i]);
  const sortedOffsets = order.map((i) => (i === mid ? 0 : offsets[i]));
  // 4. normalise per channel, then mix with the identity by strength
  normaliseChannels(weights);
  mixStrength(weights, strength);
  return pack(weights, sortedOffsets);
}

/**
 * Marginal kernel: taps where the profile's energy is, weights integrated over each tap's footprint.
 * @param {number} samples
 * @param {object} profile
 * @param {number[]} strength
 * @param {number} maxRadiusMm truncation radius (Infinity: none)
 * @param {'average'|'widest'} placement which CDF places the taps
 * @returns {Float32Array}
 */
function marginalMethod(samples, profile, strength, maxRadiusMm, placement) {
  const half = (samples - 1) / 2;
  // energy of each channel inside the truncation (1 when not truncated)
  const mass = Number.isFinite(maxRadiusMm) ? profile.marginalIntegral(-maxRadiusMm, maxRadiusMm) : [1, 1, 1];
  const radius997 = profile.radiusMm(0.997);
  const widest = radius997.indexOf(Math.max(...radius997));
  // Tap placement: quantiles of the channel-average marginal CDF by default. Each footprint then holds
  // 1/samples of the average energy, so no channel's tap can hold more than 3/samples of that channel
  // (ΔF_c ≤ Σ ΔF = 3 ΔF_avg): the largest lump, hence the largest step of the edge response, is bounded.
  // With the widest channel's CDF, narrow channels (skin blue) end up in one or two fat central taps.
  const channels = placement === 'widest' ? [widest] : [0, 1, 2];
  const tail = (x) => {
    const t = profile.marginalIntegral(x, maxRadiusMm);
    return channels.reduce((s, c) => s + t[c] / mass[c], 0) / channels.length;
  };
  const density = (x) => {
    const a = profile.marginal(x);
    return channels.reduce((s, c) => s + a[c] / mass[c], 0) / channels.length;
  };
  // positive tap positions: the (half + j + 0.5)/samples quantiles, i.e. tail = 0.5 − j/samples
  const positive = [];
  for (let j = 1; j <= half; j++) {
    const target = 0.5 - j / samples;
    const start = positive.length > 0 ? positive[positive.length - 1] * 2 : profile.lengthScaleMm;
    positive.push(solveTailQuantile(tail, density, target, start, maxRadiusMm));
  }
  // footprints: from the midpoint to the previous tap to the midpoint to the next; the last one runs to the
  // truncation radius (∞ by default), so the footprints tile the line and no energy is lost
  const bounds = positive.map((x, j) => (j + 1 < half ? 0.5 * (x + positive[j + 1]) : maxRadiusMm));
  const centreBound = 0.5 * positive[0];
  const centre = profile.marginalIntegral(-centreBound, centreBound);
  const side = positive.map((_, j) => profile.marginalIntegral(j === 0 ? centreBound : bounds[j - 1], bounds[j]));
  // symmetric profile: the tap at −x has the same weight as the tap at +x
  const weights = [centre.slice(), ...side.slice().reverse().map((w) => w.slice()), ...side.map((w) => w.slice())];
  const offsets = [0, ...positive.slice().reverse().map((x) => -x), ...positive];
  normaliseChannels(weights); // removes the quadrature's ~1e-12 and the truncated energy
  mixStrength(weights, strength);
  return pack(weights, offsets);
}

/**
 * Computes a separable SSS kernel.
 *
 * - method 'reference' (default when no profile is given): REFERENCE §3 with `strength` (default
 *   0.48, 0.41, 0.28) and `falloff` (default 1.0, 0.37, 0.3).
 * - method 'marginal' (default when a profile is given): tap x_i at the (i + 0.5)/samples quantile of the
 *   marginal CDF (channel average, or the widest channel with `placement: 'widest'`), weight = the marginal's
 *   energy over the tap's footprint per channel; optional `strength` (default 1, 1, 1) mixes with the
 *   identity like the reference; optional `maxRadiusMm` truncates the profile (weights renormalised).
 *
 * @param {object} [options]
 * @param {number} [options.samples=17] odd, 3..63
 * @param {number[]} [options.strength] RGB in [0, 1]
 * @param {number[]} [options.falloff] RGB in (0, 10]; used by method 'reference' (validated, ignored by 'marginal')
 * @param {string|object} [options.profile='skin'] profile name or object (see profiles.getProfile); used by
 *   method 'marginal' (validated, ignored by 'reference', whose profile is built in)
 * @param {'reference'|'marginal'} [options.method] default 'marginal' when a profile is given, else 'reference'
 * @param {number} [options.maxRadiusMm] > 0, method 'marginal' only (ignored by 'reference')
 * @param {'average'|'widest'} [options.placement='average'] method 'marginal' only (ignored by 'reference')
 * @returns {Float32Array} 4·samples values: (weightR, weightG, weightB, offsetMm) per tap, centre first
 */
export function computeKernel(options = {}) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError(`computeKernel options must be an object, got ${describeValue(options)}`);
  }
  const { samples = 17, strength, falloff, profile, maxRadiusMm, placement = 'average' } = options;
  checkOddInteger('samples', samples, MIN_SAMPLES, MAX_SAMPLES);
  const method = checkOneOf('method', options.method ?? (profile !== undefined ? 'marginal' : 'reference'), [
    'reference',
    'marginal',
  ]);
  // Every option given is validated, but each method only uses its own: one options object (profile,
  // falloff, ...) can then serve both methods, e.g. when a caller switches method at run time.
  const f = checkRgb('falloff', falloff ?? REFERENCE_FALLOFF, { min: 0, max: 10, minExclusive: true });
  const resolvedProfile = getProfile(profile ?? 'skin');
  const radius =
    maxRadiusMm === undefined ? Infinity : checkNumber('maxRadiusMm', maxRadiusMm, { min: 0, minExclusive: true, unit: 'mm' });
  checkOneOf('placement', placement, ['average', 'widest']);
  if (method === 'reference') {
    const s = checkRgb('strength', strength ?? REFERENCE_STRENGTH, { min: 0, max: 1 });
    return referenceMethod(samples, s, f);
  }
  const s = checkRgb('strength', strength ?? [1, 1, 1], { min: 0, max: 1 });
  return marginalMethod(samples, resolvedProfile, s, radius, placement);
}

/**
 * The largest |offset| of a kernel, in kernel millimetres.
 * @param {Float32Array|number[]} kernel as returned by computeKernel
 * @returns {number}
 */
export function kernelRadiusMm(kernel) {
  if (!kernel || typeof kernel.length !== 'number' || kernel.length === 0 || kernel.length % 4 !== 0) {
    throw new TypeError(`kernel must be an array of 4·samples numbers, got ${describeValue(kernel)}`);
  }
  let r = 0;
  for (let k = 3; k < kernel.length; k += 4) r = Math.max(r, Math.abs(kernel[k]));
  return r;
}

/**
 * The reference kernel (REFERENCE §3) with the default strength and falloff.
 * @param {number} [samples=17] odd, 3..63
 * @returns {Float32Array}
 */
export function referenceKernel(samples = 17) {
  return computeKernel({ samples, method: 'reference' });
}
