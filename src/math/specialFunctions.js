/**
 * Float64 special functions for the profiles: erf, erfc (Gaussian strips) and K0, K1 (Burley's and
 * the dipole's marginals), each checked against mpmath in the tests.
 * @module math/specialFunctions
 */

const SQRT_PI = Math.sqrt(Math.PI);

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
 * Error function, |error| < 1e-15.
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
 * Probability that a zero-mean normal of variance v lies in [a, b] (infinities allowed); erfc on
 * the tail's side keeps far strips' relative accuracy.
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
 * Modified Bessel function K_nu(z), nu = 0 or 1, z > 0: the trapezoid rule on A&S 9.6.24,
 * geometrically convergent for this doubly-exponential integrand; the step shrinks as 1/√z to
 * resolve the peak. Relative error ~1e-15.
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
