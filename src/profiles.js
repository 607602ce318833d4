/**
 * Diffusion profiles: how much of the light entering a surface at one point leaves it at distance r.
 *
 * Every profile works per RGB channel, takes distances in millimetres and is normalised so that each
 * channel carries unit energy over the plane (the colour/albedo is applied by the material, not here).
 *
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
 * Closed forms are used wherever they exist (Gaussian sums: erf; Burley and the dipole: exponentials
 * and modified Bessel functions K0/K1); the strip energy of non-Gaussian profiles goes through the generic
 * numerical path `stripIntegral` (adaptive Gauss-Legendre, relative error well below 1e-7).
 *
 * The first section holds the float64 special functions and quadrature these need.
 * @module profiles
 */

import { checkNumber, checkRgb, checkOneOf, describeValue } from './parameterChecks.js';

const TWO_PI = 2 * Math.PI;
const SQRT_PI = Math.sqrt(Math.PI);

// ---------------------------------------------------------------------------------------------------
// Special functions
// ---------------------------------------------------------------------------------------------------

/** erf by its everywhere-convergent series of positive terms (A&S 7.1.6), no cancellation; |x| < 2.5. */
function erfSeries(x) {
  // erf(x) = 2/√π · e^{-x²} · Σ_n (2x²)^n x / (1·3·…·(2n+1))
  const x2 = 2 * x * x;
  let term = x;
  let sum = x;
  for (let n = 1; n < 200; n++) {
    term *= x2 / (2 * n + 1);
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return (2 / SQRT_PI) * Math.exp(-x * x) * sum;
}

/** erfc by its continued fraction (A&S 7.1.14) evaluated with the modified Lentz method; x ≥ 2.5. */
function erfcContinuedFraction(x) {
  // erfc(x) = e^{-x²}/√π · 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + …))))
  const tiny = 1e-300;
  let f = x;
  let C = x;
  let D = 0;
  for (let n = 1; n < 500; n++) {
    const a = n / 2;
    D = x + a * D;
    D = D === 0 ? tiny : 1 / D;
    C = x + a / C;
    if (C === 0) C = tiny;
    const delta = C * D;
    f *= delta;
    if (Math.abs(delta - 1) < 1e-16) break;
  }
  return Math.exp(-x * x) / (SQRT_PI * f);
}

/**
 * Error function, float64 accurate (|error| < 1e-15 absolute, checked against mpmath in the tests).
 * @param {number} x
 * @returns {number}
 */
export function erf(x) {
  if (Number.isNaN(x)) return NaN;
  const ax = Math.abs(x);
  // erf is odd: evaluate on |x| (the series' stopping test assumes positive terms)
  const value = ax < 2.5 ? erfSeries(ax) : ax === Infinity ? 1 : 1 - erfcContinuedFraction(ax);
  return x < 0 ? -value : value;
}

/**
 * Complementary error function 1 − erf(x), with full relative accuracy in the upper tail.
 * @param {number} x
 * @returns {number}
 */
export function erfc(x) {
  if (Number.isNaN(x)) return NaN;
  if (x === Infinity) return 0;
  if (x === -Infinity) return 2;
  if (Math.abs(x) < 2.5) return x < 0 ? 1 + erfSeries(-x) : 1 - erfSeries(x);
  return x > 0 ? erfcContinuedFraction(x) : 2 - erfcContinuedFraction(-x);
}

/**
 * Probability that a zero-mean normal variable of variance v lies in [a, b] (a ≤ b, infinities allowed).
 * Uses erfc on the side of the tail so that far strips keep their relative accuracy.
 * @param {number} a
 * @param {number} b
 * @param {number} varianceMm2
 * @returns {number}
 */
export function normalIntervalProbability(a, b, varianceMm2) {
  const k = 1 / Math.sqrt(2 * varianceMm2);
  const alpha = a * k;
  const beta = b * k;
  if (alpha >= 0) return 0.5 * (erfc(alpha) - erfc(beta));
  if (beta <= 0) return 0.5 * (erfc(-beta) - erfc(-alpha));
  return 0.5 * (erf(beta) - erf(alpha));
}

/**
 * Modified Bessel function of the second kind K_nu(z), nu = 0 or 1, z > 0.
 * From the integral K_nu(z) = ∫_0^∞ e^{-z cosh t} cosh(nu t) dt (A&S 9.6.24) with the trapezoid rule,
 * which converges geometrically fast for this analytic, doubly-exponentially decaying integrand; the
 * step shrinks as 1/√z so the peak of width ~1/√z stays resolved. Relative error ~1e-15.
 * @param {0|1} nu
 * @param {number} z
 * @returns {number}
 */
export function besselK(nu, z) {
  if (!(z > 0)) return z === 0 ? Infinity : NaN;
  if (z > 740) return 0; // e^{-z} underflows
  const h = Math.min(0.1, 0.5 / Math.sqrt(z));
  // scaled integrand e^{-z (cosh t - 1)} avoids underflow of the terms; e^{-z} is applied at the end
  const tPeak = nu === 1 && z < 1 ? Math.acosh(1 / z) : 0;
  let sum = 0.5; // t = 0 term, cosh(0) = 1, half weight
  for (let k = 1; k < 100000; k++) {
    const t = k * h;
    const s = Math.sinh(t / 2);
    const term = Math.exp(-2 * z * s * s) * (nu === 0 ? 1 : Math.cosh(t));
    sum += term;
    if (t > tPeak && term < 1e-18 * sum) break;
  }
  return sum * h * Math.exp(-z);
}

// ---------------------------------------------------------------------------------------------------
// Quadrature
// ---------------------------------------------------------------------------------------------------

const gaussLegendreCache = new Map();

/**
 * n-point Gauss-Legendre nodes and weights on [-1, 1], by Newton iteration on P_n (computed once, cached).
 * @param {number} n
 * @returns {{nodes: Float64Array, weights: Float64Array}}
 */
export function gaussLegendre(n) {
  let rule = gaussLegendreCache.get(n);
  if (rule) return rule;
  const nodes = new Float64Array(n);
  const weights = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    let x = Math.cos((Math.PI * (i + 0.75)) / (n + 0.5));
    let dp = 1;
    for (let iter = 0; iter < 100; iter++) {
      let p0 = 1;
      let p1 = x;
      for (let k = 2; k <= n; k++) {
        const p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp;
      x -= dx;
      if (Math.abs(dx) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2 / ((1 - x * x) * dp * dp);
  }
  rule = { nodes, weights };
  gaussLegendreCache.set(n, rule);
  return rule;
}

const PANEL_POINTS = 10;

function glPanel(f, a, b, dim) {
  const { nodes, weights } = gaussLegendre(PANEL_POINTS);
  const c = 0.5 * (a + b);
  const h = 0.5 * (b - a);
  const out = new Array(dim).fill(0);
  for (let i = 0; i < PANEL_POINTS; i++) {
    const v = f(c + h * nodes[i]);
    for (let d = 0; d < dim; d++) out[d] += weights[i] * h * v[d];
  }
  return out;
}

/**
 * Adaptive Gauss-Legendre quadrature of a vector-valued function over a finite interval: a 10-point
 * panel is accepted when it agrees with the sum of its two halves within the tolerance, otherwise both
 * halves are refined with half the tolerance each (so the accepted errors add up to at most the tolerance).
 * @param {(x: number) => ArrayLike<number>} f integrand returning `dim` values
 * @param {number} a
 * @param {number} b
 * @param {{dim?: number, absTol?: number, relTol?: number, maxDepth?: number}} [options]
 * @returns {number[]} the `dim` integrals
 */
export function integrateAdaptive(f, a, b, { dim = 3, absTol = 1e-15, relTol = 1e-12, maxDepth = 40 } = {}) {
  if (a === b) return new Array(dim).fill(0);
  const whole = glPanel(f, a, b, dim);
  const tol = whole.map((v) => Math.max(absTol, relTol * Math.abs(v)));
  const recurse = (lo, hi, est, tolerance, depth) => {
    const mid = 0.5 * (lo + hi);
    const left = glPanel(f, lo, mid, dim);
    const right = glPanel(f, mid, hi, dim);
    const sum = left.map((v, d) => v + right[d]);
    let converged = true;
    for (let d = 0; d < dim; d++) if (Math.abs(sum[d] - est[d]) > tolerance[d]) converged = false;
    if (converged || depth >= maxDepth) return sum;
    const half = tolerance.map((t) => t / 2);
    const l = recurse(lo, mid, left, half, depth + 1);
    const r = recurse(mid, hi, right, half, depth + 1);
    return l.map((v, d) => v + r[d]);
  };
  return recurse(a, b, whole, tol, 0);
}

/**
 * ∫_a^∞ f(r) dr for an integrand that decays at least exponentially, through r = a + L·u²/(1 − u²),
 * u ∈ [0, 1): the u² also removes a square-root singularity of f's derivative at r = a.
 * @param {(r: number) => ArrayLike<number>} f
 * @param {number} a
 * @param {number} lengthScale L, the integrand's decay length (only affects efficiency)
 * @param {object} [options] as integrateAdaptive
 * @returns {number[]}
 */
export function integrateToInfinity(f, a, lengthScale, options = {}) {
  const dim = options.dim ?? 3;
  const zeros = new Array(dim).fill(0);
  const g = (u) => {
    const q = 1 - u * u;
    const r = a + (lengthScale * u * u) / q;
    if (r === Infinity) return zeros;
    const v = f(r);
    const jac = (2 * lengthScale * u) / (q * q);
    const out = new Array(dim);
    for (let d = 0; d < dim; d++) out[d] = v[d] === 0 ? 0 : v[d] * jac;
    return out;
  };
  return integrateAdaptive(g, 0, 1, options);
}

/** ∫_a^b f(r) dr with r = a + (b − a)u², which smooths a square-root behaviour at r = a. */
function integrateSqrtLeft(f, a, b, options = {}) {
  const dim = options.dim ?? 3;
  const w = b - a;
  const g = (u) => {
    const v = f(a + w * u * u);
    const jac = 2 * w * u;
    const out = new Array(dim);
    for (let d = 0; d < dim; d++) out[d] = v[d] * jac;
    return out;
  };
  return integrateAdaptive(g, 0, 1, options);
}

const clampUnit = (v) => (v < -1 ? -1 : v > 1 ? 1 : v);

/**
 * Energy of a radial profile over the strip x0 < x < x1 (the generic numerical path for marginalIntegral):
 *   ∫∫_{x0<x<x1} R dA = ∫_0^∞ R(r) · r · Θ(r) dr,  Θ(r) = 2 (acos(clamp(x0/r)) − acos(clamp(x1/r))),
 * Θ(r) being the angle of the circle of radius r that lies inside the strip. Θ is constant below
 * min(|x0|, |x1|) and has square-root kinks at |x0| and |x1|, so the integral is split there and each
 * piece is integrated with a u² substitution at its left end (adaptive Gauss-Legendre). R's 1/r
 * singularity (Burley) is harmless: the integrand carries R·r. Relative error < 1e-9 in the tests.
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
  // Θ is constant on (0, first): evaluate it inside and integrate R·r over the disk
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
 * Solves f(x) = target for a decreasing f on [lo, hi] by bisection to double precision.
 * @param {(x: number) => number} f
 * @param {number} target
 * @param {number} lo
 * @param {number} hi
 * @returns {number}
 */
function solveDecreasing(f, target, lo, hi) {
  while (f(hi) > target) hi *= 2;
  for (let i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
    const mid = 0.5 * (lo + hi);
    if (f(mid) > target) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// ---------------------------------------------------------------------------------------------------
// Profile constructors
// ---------------------------------------------------------------------------------------------------

const rgbOf = (value) => (typeof value === 'number' ? [value, value, value] : value);

function checkFraction(fraction) {
  return checkNumber('fraction', fraction, { min: 0, max: 1, minExclusive: true, maxExclusive: true });
}

/**
 * Fills the parts of a profile that have no closed form with the generic numerical paths, and freezes it.
 * `R` and `lengthScaleMm` are required; `marginal`, `marginalIntegral`, `transmittance`, `cdf` and
 * `radiusMm` are derived when missing:
 * - marginal: a(x) = 2∫_0^∞ R(|x| cosh t) |x| cosh t dt (r = |x| cosh t removes the 1/√(r²−x²) singularity)
 * - marginalIntegral: stripIntegral
 * - transmittance: ∫_d^∞ R(r) 2πr dr, cdf = 1 − transmittance
 * - radiusMm: bisection on the cdf.
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

/**
 * d'Eon & Luebke 2007 (GPU Gems 3, ch. 14) six-Gaussian skin fit: variances in mm², RGB weights.
 * Each channel already sums to 1.
 * @type {ReadonlyArray<Readonly<{varianceMm2: number, weights: ReadonlyArray<number>}>>}
 */
export const DEON_SKIN_GAUSSIANS = Object.freeze(
  [
    { varianceMm2: 0.0064, weights: [0.233, 0.455, 0.649] },
    { varianceMm2: 0.0484, weights: [0.1, 0.336, 0.344] },
    { varianceMm2: 0.187, weights: [0.118, 0.198, 0.0] },
    { varianceMm2: 0.567, weights: [0.113, 0.007, 0.007] },
    { varianceMm2: 1.99, weights: [0.358, 0.004, 0.0] },
    { varianceMm2: 7.41, weights: [0.078, 0.0, 0.0] },
  ].map((g) => Object.freeze({ varianceMm2: g.varianceMm2, weights: Object.freeze(g.weights) })),
);

/**
 * Jimenez 2009 four-Gaussian fit of marble (REFERENCE §2). The published table has a leading (0, 0, 0)
 * weight row that belongs to a zero-variance (delta) term with no energy: it is dropped, and the four
 * variances pair with the four remaining rows. The published green and blue weights sum to 0.9999, so
 * gaussianSumProfile renormalises each channel to sum exactly 1.
 * @type {ReadonlyArray<Readonly<{varianceMm2: number, weights: ReadonlyArray<number>}>>}
 */
export const MARBLE_GAUSSIANS = Object.freeze(
  [
    { varianceMm2: 0.0362, weights: [0.0545, 0.1245, 0.2177] },
    { varianceMm2: 0.1145, weights: [0.2437, 0.2435, 0.189] },
    { varianceMm2: 0.4556, weights: [0.3105, 0.3158, 0.3742] },
    { varianceMm2: 3.4833, weights: [0.3913, 0.3161, 0.219] },
  ].map((g) => Object.freeze({ varianceMm2: g.varianceMm2, weights: Object.freeze(g.weights) })),
);

/**
 * Burley's radius holding 99.7 % of the energy in units of the scatter distance: s·r for u = 0.003
 * from the closed-form inverse below (REFERENCE §2 quotes 16.56).
 */
function burleyScaledRadius(fraction) {
  // Christensen & Burley 2015: with u = 1 − CDF, G = 1 + 4u(2u + √(1 + 4u²)),
  // s·r = 3 ln((1 + G^{-1/3} + G^{1/3}) / (4u))
  const u = 1 - fraction;
  const G = 1 + 4 * u * (2 * u + Math.sqrt(1 + 4 * u * u));
  const g3 = Math.cbrt(G);
  return 3 * Math.log((1 + 1 / g3 + g3) / (4 * u));
}

/**
 * Burley normalised diffusion (Christensen & Burley 2015), per channel with scatter distance l = 1/s:
 *   R(r) = (e^{−r/l} + e^{−r/3l}) / (8π l r)             (the albedo factor A is dropped: unit energy)
 *   a(x) = (K0(|x|/l) + K0(|x|/3l)) / (4π l)             since ∫ e^{−s√(x²+y²)}/√(x²+y²) dy = 2 K0(s|x|)
 *   T(d) = (e^{−d/l} + 3 e^{−d/3l}) / 4,  CDF = 1 − T,  radius from the closed-form inverse.
 * The marginal is infinite at x = 0 (logarithmic singularity, integrable).
 *
 * Give either the scatter distances directly, or an albedo and a mean free path with one of the fits
 * s = 1.85 − A + 7|A − 0.8|³ ('searchlight', light entering perpendicular) or
 * s = 1.9 − A + 3.5 (A − 0.8)² ('diffuse'), and l = meanFreePath / s.
 * @param {{scatterDistanceMm?: number[], albedo?: number[], meanFreePathMm?: number|number[],
 *   fit?: 'searchlight'|'diffuse', name?: string}} options
 * @returns {Readonly<object>} the profile
 */
export function burleyProfile(options = {}) {
  let l;
  if (options.scatterDistanceMm !== undefined) {
    l = checkRgb('scatterDistanceMm', options.scatterDistanceMm, { min: 0, minExclusive: true, unit: 'mm' });
  } else {
    const albedo = checkRgb('albedo', options.albedo, { min: 0, max: 1 });
    const mfp = checkRgb('meanFreePathMm', rgbOf(options.meanFreePathMm), { min: 0, minExclusive: true, unit: 'mm' });
    const fit = checkOneOf('fit', options.fit ?? 'searchlight', ['searchlight', 'diffuse']);
    const scale = albedo.map((A) =>
      fit === 'searchlight' ? 1.85 - A + 7 * Math.abs(A - 0.8) ** 3 : 1.9 - A + 3.5 * (A - 0.8) ** 2,
    );
    l = mfp.map((d, c) => d / scale[c]);
  }
  const perChannel = (fn) => [fn(l[0]), fn(l[1]), fn(l[2])];
  const transmittance = (dMm) => {
    const d = Math.abs(dMm);
    return perChannel((lc) => 0.25 * (Math.exp(-d / lc) + 3 * Math.exp(-d / (3 * lc))));
  };
  const cdf = (rMm) => perChannel((lc) => -0.25 * (Math.expm1(-rMm / lc) + 3 * Math.expm1(-rMm / (3 * lc))));
  const radiusMm = (fraction = 0.997) => {
    checkFraction(fraction);
    const k = burleyScaledRadius(fraction);
    return perChannel((lc) => k * lc);
  };
  return radialProfile({
    name: options.name ?? 'burley',
    scatterDistanceMm: l,
    lengthScaleMm: Math.max(...l) * burleyScaledRadius(0.5),
    R: (rMm) => perChannel((lc) => (Math.exp(-rMm / lc) + Math.exp(-rMm / (3 * lc))) / (8 * Math.PI * lc * rMm)),
    marginal: (xMm) => {
      const ax = Math.abs(xMm);
      if (ax === 0) return [Infinity, Infinity, Infinity];
      return perChannel((lc) => (besselK(0, ax / lc) + besselK(0, ax / (3 * lc))) / (4 * Math.PI * lc));
    },
    transmittance,
    cdf,
    radiusMm,
  });
}

/**
 * Classical dipole diffuse reflectance of Jensen, Marschner, Levoy & Hanrahan 2001 ("A practical model
 * for subsurface light transport", eq. 4-5), per channel, normalised to unit energy:
 *   σt' = σa + σs', α' = σs'/σt', σtr = √(3 σa σt'), z_r = 1/σt', z_v = z_r (1 + 4A/3),
 *   A = (1 + F_dr)/(1 − F_dr), F_dr = −1.440/η² + 0.710/η + 0.668 + 0.0636 η,
 *   d_r,v = √(r² + z_r,v²),
 *   R_d(r) = α'/(4π) Σ_{z ∈ {z_r, z_v}} z (σtr d + 1) e^{−σtr d} / d³.
 * The integrals are closed form (substituting ρ² = r² + z², ρ dρ = r dr, and (σρ+1)e^{−σρ}/ρ² = −d/dρ(e^{−σρ}/ρ)):
 *   energy outside radius r: (α'/2) Σ z e^{−σtr d(r)} / d(r);  total R_d = (α'/2)(e^{−σtr z_r} + e^{−σtr z_v});
 *   marginal: ∫ (σD+1)e^{−σD}/D³ dy = 2σ K1(σρ)/ρ with ρ = √(x² + z²).
 * The total is used to normalise (exact, no numerical normalisation needed).
 * @param {{sigmaSPrimeMm: number[], sigmaAMm: number[], eta: number, name?: string}} options
 *   reduced scattering and absorption coefficients in 1/mm, relative index of refraction
 * @returns {Readonly<object>} the profile
 */
export function dipoleProfile({ sigmaSPrimeMm, sigmaAMm, eta, name = 'dipole' } = {}) {
  const sigmaS = checkRgb('sigmaSPrimeMm', sigmaSPrimeMm, { min: 0, minExclusive: true, unit: '1/mm' });
  const sigmaA = checkRgb('sigmaAMm', sigmaAMm, { min: 0, minExclusive: true, unit: '1/mm' });
  checkNumber('eta', eta, { min: 1, max: 3 });
  const Fdr = -1.44 / (eta * eta) + 0.71 / eta + 0.668 + 0.0636 * eta;
  const A = (1 + Fdr) / (1 - Fdr);
  const ch = [0, 1, 2].map((c) => {
    const sigmaTPrime = sigmaA[c] + sigmaS[c];
    const alphaPrime = sigmaS[c] / sigmaTPrime;
    const sigmaTr = Math.sqrt(3 * sigmaA[c] * sigmaTPrime);
    const zr = 1 / sigmaTPrime;
    const zv = zr * (1 + (4 * A) / 3);
    const total = 0.5 * alphaPrime * (Math.exp(-sigmaTr * zr) + Math.exp(-sigmaTr * zv));
    return { alphaPrime, sigmaTr, zr, zv, total };
  });
  const R = (rMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(rMm * rMm + z * z);
        return (z * (sigmaTr * d + 1) * Math.exp(-sigmaTr * d)) / (d * d * d);
      };
      return ((alphaPrime / (4 * Math.PI)) * (term(zr) + term(zv))) / total;
    });
  const transmittance = (dMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(dMm * dMm + z * z);
        return (z * Math.exp(-sigmaTr * d)) / d;
      };
      return (0.5 * alphaPrime * (term(zr) + term(zv))) / total;
    });
  // 1 − T without cancellation: e^{−σz} − z e^{−σd}/d = −e^{−σz} expm1(−log1p(Δ/z) − σΔ), Δ = d − z = r²/(d + z)
  const cdf = (rMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(rMm * rMm + z * z);
        const delta = (rMm * rMm) / (d + z);
        return -Math.exp(-sigmaTr * z) * Math.expm1(-Math.log1p(delta / z) - sigmaTr * delta);
      };
      return rMm === Infinity ? 1 : (0.5 * alphaPrime * (term(zr) + term(zv))) / total;
    });
  const marginal = (xMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const rho = Math.sqrt(xMm * xMm + z * z);
        return (z * besselK(1, sigmaTr * rho)) / rho;
      };
      return ((alphaPrime * sigmaTr) / (2 * Math.PI)) * (term(zr) + term(zv)) / total;
    });
  const lengthScaleMm = Math.max(...ch.map(({ sigmaTr, zv }) => Math.max(1 / sigmaTr, zv)));
  const radiusMm = (fraction = 0.997) => {
    checkFraction(fraction);
    return [0, 1, 2].map((c) => solveDecreasing((r) => transmittance(r)[c], 1 - fraction, 0, lengthScaleMm));
  };
  return radialProfile({ name, R, marginal, transmittance, cdf, radiusMm, lengthScaleMm });
}

/**
 * Scatter distances of the `skinBurley` preset, chosen so that each channel's 99.7 % radius equals the
 * d'Eon skin profile's: l_c = skin.radiusMm(0.997)_c / 16.5644 (Burley's 99.7 % radius is 16.5644 l).
 * Computed with this module (skin 99.7 % radii 6.9494, 1.6083, 0.98327 mm), rounded to 5 digits; the
 * unit tests recompute them. Matching only this radius leaves the shapes different: Burley's sharp
 * centre and exponential tail versus the Gaussians' rounded ones.
 */
export const SKIN_BURLEY_SCATTER_DISTANCE_MM = Object.freeze([0.41954, 0.097094, 0.059361]);

/**
 * Whole milk, from the table of measured scattering coefficients in Jensen et al. 2001 ("A practical
 * model for subsurface light transport", SIGGRAPH; σs', σa per RGB for marble, skin, milk, ketchup, ...):
 * σs' = (2.55, 3.21, 3.77)/mm, σa = (0.0011, 0.0024, 0.014)/mm, η = 1.3.
 * Caveat: recalled, not re-read from the paper here (REFERENCE.md names the table, not its numbers);
 * check them against the paper before relying on milk quantitatively.
 */
export const WHOLE_MILK_COEFFICIENTS = Object.freeze({
  sigmaSPrimeMm: Object.freeze([2.55, 3.21, 3.77]),
  sigmaAMm: Object.freeze([0.0011, 0.0024, 0.014]),
  eta: 1.3,
});

/**
 * The built-in profiles (built on import: pure computation, no side effects):
 * - skin: d'Eon & Luebke six Gaussians
 * - skinBurley: Burley with SKIN_BURLEY_SCATTER_DISTANCE_MM (same 99.7 % radii as skin)
 * - marble: Jimenez 2009 four-Gaussian marble fit
 * - milk: Jensen 2001 dipole of whole milk
 */
export const profiles = Object.freeze({
  skin: gaussianSumProfile('skin', DEON_SKIN_GAUSSIANS),
  skinBurley: burleyProfile({ name: 'skinBurley', scatterDistanceMm: [...SKIN_BURLEY_SCATTER_DISTANCE_MM] }),
  marble: gaussianSumProfile('marble', MARBLE_GAUSSIANS),
  milk: dipoleProfile({ name: 'milk', ...WHOLE_MILK_COEFFICIENTS }),
});

/**
 * The reference transmittance of Jimenez et al. 2010 (REFERENCE §5) for skin:
 *   T(s) = Σ_i w_i exp(−s²/v_i) over the six d'Eon Gaussians.
 * This is NOT the exact integral of the profile (that is profiles.skin.transmittance, with exp(−s²/2v));
 * the two agree at s_exact = √2 · s. Kept because the reference's artist-tuned scale assumes it.
 * @param {number} sMm scaled thickness in mm
 * @returns {number[]} [r, g, b]
 */
export function transmittance(sMm) {
  checkNumber('sMm', sMm, { min: 0, unit: 'mm' });
  const out = [0, 0, 0];
  for (const { varianceMm2, weights } of DEON_SKIN_GAUSSIANS) {
    const k = Math.exp((-sMm * sMm) / varianceMm2);
    for (let c = 0; c < 3; c++) out[c] += weights[c] * k;
  }
  return out;
}

const PROFILE_NAMES = Object.freeze(['skin', 'skinBurley', 'marble', 'milk']);
const PROFILE_METHODS = ['R', 'marginal', 'marginalIntegral', 'transmittance', 'radiusMm'];

/**
 * Resolves a profile name or checks a profile object.
 * @param {'skin'|'skinBurley'|'marble'|'milk'|object} nameOrProfile
 * @returns {Readonly<object>} the profile
 * @throws {TypeError} for anything else, naming the accepted names
 */
export function getProfile(nameOrProfile) {
  if (typeof nameOrProfile === 'string' && PROFILE_NAMES.includes(nameOrProfile)) return profiles[nameOrProfile];
  if (
    nameOrProfile !== null &&
    typeof nameOrProfile === 'object' &&
    PROFILE_METHODS.every((m) => typeof nameOrProfile[m] === 'function')
  ) {
    return nameOrProfile;
  }
  throw new TypeError(
    `profile must be one of ${PROFILE_NAMES.map((n) => `'${n}'`).join(', ')} or a profile object ` +
      `(with ${PROFILE_METHODS.join(', ')}), got ${describeValue(nameOrProfile)}`,
  );
}
