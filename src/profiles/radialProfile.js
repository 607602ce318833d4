/**
 * Diffusion profiles: how much of the light entering a surface at one point leaves it at distance r,
 * per RGB channel, in millimetres, unit energy per channel (the material applies the albedo).
 * A profile object has:
 * - `name`                          string
 * - `R(rMm)`                        radial profile [r,g,b] in 1/mm², ∫∫ R dA = 1 per channel
 * - `marginal(xMm)`                 a(x) = ∫ R(√(x²+y²)) dy in 1/mm, ∫ a dx = 1
 * - `marginalIntegral(x0Mm, x1Mm)`  ∫_{x0}^{x1} a(x) dx (energy of the strip x0 < x < x1), infinities allowed
 * - `transmittance(dMm)`            T(d) = ∫∫ R(√(r²+d²)) dA = energy outside the disk of radius d
 * - `cdf(rMm)`                      energy inside the disk of radius r = 1 − T(r), computed without cancellation
 * - `radiusMm(fraction = 0.997)`    radius of the disk holding `fraction` of the energy, [r,g,b]
 * - `lengthScaleMm`                 a typical radius (largest channel's median radius), used to scale quadratures
 * - `gaussians`                     Gaussian-sum profiles only: [{ varianceMm2, weights: [r,g,b] }]
 *
 * `radialProfile` derives the parts a closed-form family (gaussianSum.js, burley.js, dipole.js) lacks.
 * @module profiles/radialProfile
 */

import { checkNumber, describeValue } from '../support/parameterChecks.js';
import { integrateAdaptive, integrateToInfinity, integrateSqrtLeft } from '../math/quadrature.js';
import { solveDecreasing } from '../math/roots.js';

const TWO_PI = 2 * Math.PI;

const clampUnit = (v) => (v < -1 ? -1 : v > 1 ? 1 : v);

/** Checks an energy fraction in (0, 1), e.g. radiusMm's argument. */
export function checkFraction(fraction) {
  return checkNumber('fraction', fraction, { min: 0, max: 1, minExclusive: true, maxExclusive: true });
}

/**
 * Energy of a radial profile over the strip x0 < x < x1: ∫_0^∞ R(r) · r · Θ(r) dr, Θ(r) the angle of
 * the circle of radius r inside the strip. Θ is constant below min(|x0|, |x1|) and has square-root
 * kinks at |x0| and |x1|: the integral is split there, each piece with a u² substitution at its left
 * end. R's 1/r singularity (Burley) is harmless: the integrand carries R·r.
 * @param {(rMm: number) => ArrayLike<number>} R radial profile (RGB)
 * @param {number} x0Mm lower bound (may be -Infinity)
 * @param {number} x1Mm upper bound (may be Infinity)
 * @param {{lengthScaleMm: number, cdf?: (rMm: number) => ArrayLike<number>, absTol?: number, relTol?: number}} options
 *   lengthScaleMm scales the tail mapping; cdf, when given, integrates the inner disk exactly
 * @returns {number[]} [r, g, b]
 */
export function stripIntegral(R, x0Mm, x1Mm, { lengthScaleMm, cdf, absTol = 1e-15, relTol = 1e-11 } = {}) {
  if (x1Mm < x0Mm) return stripIntegral(R, x1Mm, x0Mm, { lengthScaleMm, cdf, absTol, relTol }).map((v) => -v);
  if (x1Mm === x0Mm) return [0, 0, 0];
  const options = { dim: 3, absTol, relTol };
  const theta = (r) => 2 * (Math.acos(clampUnit(x0Mm / r)) - Math.acos(clampUnit(x1Mm / r)));
  const integrand = (r) => {
    const v = R(r);
    const k = r * theta(r);
    return [v[0] * k, v[1] * k, v[2] * k];
  };
  const breaks = [...new Set([Math.abs(x0Mm), Math.abs(x1Mm)])]
    .filter((b) => Number.isFinite(b) && b > 0)
    .sort((a, b) => a - b);
  const first = breaks.length > 0 ? breaks[0] : Infinity;
  // Θ is constant on (0, first)
  const thetaInner = theta(first === Infinity ? 1 : first / 2);
  let total;
  if (cdf) {
    const e = cdf(first);
    total = [0, 1, 2].map((c) => (thetaInner / TWO_PI) * e[c]);
  } else {
    const rr = (r) => {
      const v = R(r);
      return [v[0] * r * thetaInner, v[1] * r * thetaInner, v[2] * r * thetaInner];
    };
    total = first === Infinity ? integrateToInfinity(rr, 0, lengthScaleMm, options) : integrateAdaptive(rr, 0, first, options);
  }
  if (first === Infinity) return total;
  for (let i = 0; i < breaks.length; i++) {
    const a = breaks[i];
    const part =
      i + 1 < breaks.length
        ? integrateSqrtLeft(integrand, a, breaks[i + 1], options)
        : integrateToInfinity(integrand, a, lengthScaleMm, options);
    total = total.map((v, c) => v + part[c]);
  }
  return total;
}

/**
 * Fills the parts of a profile without closed form numerically, and freezes it. The marginal
 * substitutes r = |x| cosh t, which removes the 1/√(r²−x²) singularity.
 * @param {{name: string, R: (rMm: number) => number[], lengthScaleMm: number,
 *   marginal?: Function, marginalIntegral?: Function, transmittance?: Function, cdf?: Function,
 *   radiusMm?: Function, gaussians?: Array}} parts
 * @returns {Readonly<object>} the profile
 */
export function radialProfile(parts) {
  const { name, R, lengthScaleMm } = parts;
  if (typeof R !== 'function') throw new TypeError(`radialProfile: R must be a function, got ${describeValue(R)}`);
  checkNumber('lengthScaleMm', lengthScaleMm, { min: 0, minExclusive: true, unit: 'mm' });
  const transmittance =
    parts.transmittance ??
    ((dMm) =>
      integrateToInfinity(
        (r) => R(r).map((v) => v * TWO_PI * r),
        Math.abs(dMm),
        lengthScaleMm,
      ));
  const cdf = parts.cdf ?? ((rMm) => transmittance(rMm).map((t) => 1 - t));
  const marginal =
    parts.marginal ??
    ((xMm) => {
      const ax = Math.abs(xMm);
      if (ax === 0) return integrateToInfinity((r) => R(r).map((v) => 2 * v), 0, lengthScaleMm);
      return integrateToInfinity(
        (t) => {
          const r = ax * Math.cosh(t);
          return r === Infinity ? [0, 0, 0] : R(r).map((v) => 2 * v * r);
        },
        0,
        1,
      );
    });
  const marginalIntegral =
    parts.marginalIntegral ?? ((x0Mm, x1Mm) => stripIntegral(R, x0Mm, x1Mm, { lengthScaleMm, cdf }));
  const radiusMm =
    parts.radiusMm ??
    ((fraction = 0.997) => {
      checkFraction(fraction);
      return [0, 1, 2].map((c) => solveDecreasing((r) => transmittance(r)[c], 1 - fraction, 0, lengthScaleMm));
    });
  const profile = { name, R, marginal, marginalIntegral, transmittance, cdf, radiusMm, lengthScaleMm };
  if (parts.gaussians) profile.gaussians = parts.gaussians;
  if (parts.scatterDistanceMm) profile.scatterDistanceMm = Object.freeze([...parts.scatterDistanceMm]);
  return Object.freeze(profile);
}
