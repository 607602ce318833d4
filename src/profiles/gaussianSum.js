// d'Eon & Luebke 2007's family: sums of normalised 2D Gaussians, closed form throughout.
import { checkNumber, checkRgb, describeValue } from '../support/parameterChecks.js';
import { normalIntervalProbability } from '../math/specialFunctions.js';
import { solveDecreasing } from '../math/roots.js';
import { radialProfile, checkFraction } from './radialProfile.js';

const TWO_PI = 2 * Math.PI;

/**
 * A sum of normalised 2D Gaussians G(v, r) = exp(−r²/2v)/(2πv) with RGB weights (d'Eon & Luebke 2007).
 * Everything is closed form: the marginal of a 2D Gaussian is the 1D Gaussian of the same variance,
 * its strip energy an erf difference, and the energy outside radius d is exp(−d²/2v).
 * @param {string} name
 * @param {Array<{varianceMm2: number, weights: number[]}>} gaussians
 * @param {{normalize?: boolean}} [options] normalize (default true) rescales each channel's weights to sum to 1
 * @returns {Readonly<object>} the profile
 */
export function gaussianSumProfile(name, gaussians, { normalize = true } = {}) {
  if (!Array.isArray(gaussians) || gaussians.length === 0) {
    throw new TypeError(`gaussians must be a non-empty array of { varianceMm2, weights }, got ${describeValue(gaussians)}`);
  }
  const terms = gaussians.map((g, i) => ({
    varianceMm2: checkNumber(`gaussians[${i}].varianceMm2`, g.varianceMm2, { min: 0, minExclusive: true, unit: 'mm²' }),
    weights: checkRgb(`gaussians[${i}].weights`, g.weights, { min: 0 }),
  }));
  const sums = [0, 1, 2].map((c) => terms.reduce((s, g) => s + g.weights[c], 0));
  sums.forEach((s, c) => {
    if (!(s > 0)) throw new RangeError(`gaussians: channel ${c} has no weight`);
  });
  const normalised = Object.freeze(
    terms.map((g) =>
      Object.freeze({
        varianceMm2: g.varianceMm2,
        weights: Object.freeze(normalize ? g.weights.map((w, c) => w / sums[c]) : g.weights),
      }),
    ),
  );
  const sum = (fn) => {
    const out = [0, 0, 0];
    for (const g of normalised) {
      const k = fn(g.varianceMm2);
      for (let c = 0; c < 3; c++) out[c] += g.weights[c] * k;
    }
    return out;
  };
  const transmittance = (dMm) => sum((v) => Math.exp((-dMm * dMm) / (2 * v)));
  const radiusMm = (fraction = 0.997) => {
    checkFraction(fraction);
    const sigmaMax = Math.sqrt(Math.max(...normalised.map((g) => g.varianceMm2)));
    return [0, 1, 2].map((c) => solveDecreasing((r) => transmittance(r)[c], 1 - fraction, 0, sigmaMax));
  };
  // median radius of the widest channel: scales the numerical paths when they are used for comparison
  const lengthScaleMm = Math.max(...radiusMm(0.5));
  return radialProfile({
    name,
    gaussians: normalised,
    lengthScaleMm,
    R: (rMm) => sum((v) => Math.exp((-rMm * rMm) / (2 * v)) / (TWO_PI * v)),
    marginal: (xMm) => sum((v) => Math.exp((-xMm * xMm) / (2 * v)) / Math.sqrt(TWO_PI * v)),
    marginalIntegral: (x0Mm, x1Mm) => sum((v) => normalIntervalProbability(x0Mm, x1Mm, v)),
    transmittance,
    cdf: (rMm) => sum((v) => -Math.expm1((-rMm * rMm) / (2 * v))),
    radiusMm,
  });
}
