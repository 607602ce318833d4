/**
 * Float64 root finding on monotone functions: profile radii, table ranges, tap quantiles.
 * @module math/roots
 */

/**
 * Solves f(x) = target for a decreasing f by bisection, hi doubled first until f(hi) ≤ target.
 * @param {(x: number) => number} f
 * @param {number} target
 * @param {number} lo
 * @param {number} hi a first upper bracket guess (> lo)
 * @param {number} [limit=1e9] the largest hi tried
 * @returns {number}
 */
export function solveDecreasing(f, target, lo, hi, limit = 1e9) {
  while (f(hi) > target && hi < limit) hi *= 2;
  for (let i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
    const mid = 0.5 * (lo + hi);
    if (f(mid) > target) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/**
 * The first point of the grid start·factorⁿ at which f is below `tail`: a coarse, always-finite
 * table range, which only has to lie past where f stops mattering.
 * @param {(x: number) => number} f decreasing (at least eventually)
 * @param {number} tail
 * @param {{ start?: number, factor?: number, limit?: number }} [grid] default 0.25 mm, ×1.25, 1e5 mm
 * @returns {number}
 */
export function firstBelow(f, tail, { start = 0.25, factor = 1.25, limit = 1e5 } = {}) {
  let x = start;
  while (f(x) >= tail && x < limit) x *= factor;
  return x;
}

/**
 * Finds x ≥ 0 with G(x) = target for a decreasing tail G (G(0) = 0.5) by Newton safeguarded with
 * bisection.
 * @param {(x: number) => number} G
 * @param {(x: number) => number} g the density (−G')
 * @param {number} target in (0, 0.5)
 * @param {number} hiStart a first upper bracket guess
 * @param {number} limit the largest admissible x (the truncation radius, or Infinity)
 * @returns {number}
 */
export function solveTailQuantile(G, g, target, hiStart, limit) {
  let lo = 0;
  let hi = Math.min(hiStart, limit);
  while (G(hi) > target && hi < limit) hi = Math.min(hi * 2, limit);
  let x = 0.5 * (lo + hi);
  for (let iter = 0; iter < 200; iter++) {
    const value = G(x) - target;
    if (value === 0) return x;
    if (value > 0) lo = x;
    else hi = x;
    if (hi - lo <= 1e-14 * hi) break;
    const density = g(x);
    let next = x + value / density; // Newton: G(x + dx) ≈ G(x) − g(x) dx
    if (!(next > lo && next < hi) || !Number.isFinite(next)) next = 0.5 * (lo + hi);
    if (Math.abs(next - x) <= 1e-15 * hi) return next;
    x = next;
  }
  return 0.5 * (lo + hi);
}
