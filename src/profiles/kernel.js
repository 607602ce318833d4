/**
 * Separable blur kernels: a Float32Array of 4·samples, (weightR, weightG, weightB, offsetMm) per tap,
 * centre tap first, then ascending offset; each channel's weights sum to 1.
 * - 'reference': Jimenez 2012's strength/falloff kernel (REFERENCE §3), exactly. It samples the
 *   *radial* profile along the axis, which makes the 1D kernel too sharp.
 * - 'marginal': the radial profile's marginal a(x) = ∫ R(√(x²+y²)) dy integrated over each tap's
 *   footprint, so edges along the blur axes are exact.
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

// d'Eon Gaussians 2..6, red weights only: the reference's 1D profile (REFERENCE §3 step 2); the
// narrowest (v = 0.0064) is left to the strength mix with the identity.
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
 * Mixes a normalised kernel with the identity (REFERENCE §3 step 4).
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
 * Jimenez 2012's kernel (REFERENCE §3).
 * @param {number} samples
 * @param {number[]} strength
 * @param {number[]} falloff
 * @returns {Float32Array}
 */
function referenceMethod(samples, strength, falloff) {
  // 1. offsets: quadratic warp of a uniform t, denser near the centre
  const range = samples > 20 ? 3 : 2;
  const step = (2 * range) / (samples - 1);
  const offsets = [];
  for (let i = 0; i < samples; i++) {
    const t = -range + i * step;
    offsets.push((Math.sign(t) * t * t) / range);
  }
  // 2-3. weight = profile(offset) · half the distance to each neighbour
  let weights = offsets.map((o, i) => {
    const w0 = i > 0 ? Math.abs(o - offsets[i - 1]) : 0;
    const w1 = i < samples - 1 ? Math.abs(o - offsets[i + 1]) : 0;
    const area = (w0 + w1) / 2;
    return [0, 1, 2].map((c) => area * referenceProfile(o, falloff[c]));
  });
  const mid = (samples - 1) / 2;
  const order = [mid, ...offsets.map((_, i) => i).filter((i) => i !== mid)];
  weights = order.map((i) => weights[i]);
  const sortedOffsets = order.map((i) => (i === mid ? 0 : offsets[i]));
  // 4. normalise per channel, then mix with the identity
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
  const mass = Number.isFinite(maxRadiusMm) ? profile.marginalIntegral(-maxRadiusMm, maxRadiusMm) : [1, 1, 1];
  const radius997 = profile.radiusMm(0.997);
  const widest = radius997.indexOf(Math.max(...radius997));
  // Taps at quantiles of the channel-average marginal CDF: no channel's tap then holds more than
  // 3/samples of it (ΔF_c ≤ Σ ΔF = 3 ΔF_avg), which bounds the largest step of the edge response.
  // The widest channel's CDF puts narrow channels (skin blue) in one or two fat central taps.
  const channels = placement === 'widest' ? [widest] : [0, 1, 2];
  const tail = (x) => {
    const t = profile.marginalIntegral(x, maxRadiusMm);
    return channels.reduce((s, c) => s + t[c] / mass[c], 0) / channels.length;
  };
  const density = (x) => {
    const a = profile.marginal(x);
    return channels.reduce((s, c) => s + a[c] / mass[c], 0) / channels.length;
  };
  // positive taps: the (half + j + 0.5)/samples quantiles, i.e. tail = 0.5 − j/samples
  const positive = [];
  for (let j = 1; j <= half; j++) {
    const target = 0.5 - j / samples;
    const start = positive.length > 0 ? positive[positive.length - 1] * 2 : profile.lengthScaleMm;
    positive.push(solveTailQuantile(tail, density, target, start, maxRadiusMm));
  }
  // footprints run midpoint to midpoint, the last to the truncation radius: they tile the line
  const bounds = positive.map((x, j) => (j + 1 < half ? 0.5 * (x + positive[j + 1]) : maxRadiusMm));
  const centreBound = 0.5 * positive[0];
  const centre = profile.marginalIntegral(-centreBound, centreBound);
  const side = positive.map((_, j) => profile.marginalIntegral(j === 0 ? centreBound : bounds[j - 1], bounds[j]));
  const weights = [centre.slice(), ...side.slice().reverse().map((w) => w.slice()), ...side.map((w) => w.slice())];
  const offsets = [0, ...positive.slice().reverse().map((x) => -x), ...positive];
  normaliseChannels(weights); // removes the quadrature's ~1e-12 and the truncated energy
  mixStrength(weights, strength);
  return pack(weights, offsets);
}

/**
 * Computes a separable SSS kernel. Every option given is validated; each method uses only its own.
 * @param {object} [options]
 * @param {number} [options.samples=17] odd, 3..63
 * @param {number[]} [options.strength] RGB in [0, 1]; default REFERENCE_STRENGTH ('reference'), 1 ('marginal')
 * @param {number[]} [options.falloff] RGB in (0, 10]; 'reference' only
 * @param {string|object} [options.profile='skin'] name or profile object (getProfile); 'marginal' only
 * @param {'reference'|'marginal'} [options.method] default 'marginal' when a profile is given, else 'reference'
 * @param {number} [options.maxRadiusMm] > 0, truncates the profile (weights renormalised); 'marginal' only
 * @param {'average'|'widest'} [options.placement='average'] which CDF places the taps; 'marginal' only
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
  // Each method ignores the other's options, so one options object serves both.
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
