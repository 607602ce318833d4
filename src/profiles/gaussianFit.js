// Any radial profile as a sum of 2D Gaussians (d'Eon & Luebke 2007), so the isotropic blur
// (src/3-blur/kernelGroups.js) can split it into exactly separable groups. Burley and dipole are fit
// here: G(x) = ∫_0^x marginal, by non-negative weights on Gaussians of fixed widths. The blur uses
// the fit only to share each footprint's exact energy between groups, so its error never reaches
// the transfer along the screen axes. `stepError`: the worst |fit − G| per channel.
import { erf } from '../math/specialFunctions.js';

/** The fit's σ: from 0.03 × the narrowest channel's median radius to 8 × the widest's, by 2.2. */
const SIGMA_RANGE = Object.freeze({ belowNarrowest: 0.03, aboveWidest: 8, ratio: 2.2 });
/** Where G is matched: square-root spaced, dense near 0 where Burley is steepest. */
const FIT_POINTS = 400;
/** The weight of the unit-energy row of the least squares. */
const UNIT_ENERGY_WEIGHT = 100;

/**
 * Non-negative least squares, min |A w − b|² subject to w ≥ 0 (Lawson & Hanson 1974's active set).
 * @param {number[][]} A rows @param {number[]} b @returns {number[]} w
 */
export function nonNegativeLeastSquares(A, b) {
  const n = A[0].length;
  const w = new Array(n).fill(0);
  const passive = new Set();
  const gradient = () => A[0].map((_, j) => A.reduce((s, row, i) => s + row[j] * (b[i] - row.reduce((t, a, k) => t + a * w[k], 0)), 0));
  for (let outer = 0; outer < 3 * n; outer++) {
    const g = gradient();
    let best = -1;
    for (let j = 0; j < n; j++) if (!passive.has(j) && g[j] > 1e-14 && (best < 0 || g[j] > g[best])) best = j;
    if (best < 0) break;
    passive.add(best);
    for (let inner = 0; inner < 3 * n; inner++) {
      const z = leastSquaresOn(A, b, [...passive]);
      const negative = [...passive].filter((j) => z[j] <= 0);
      if (negative.length === 0) { w.splice(0, n, ...z); break; }
      const alpha = Math.min(...negative.map((j) => w[j] / (w[j] - z[j])));
      for (let j = 0; j < n; j++) w[j] += alpha * (z[j] - w[j]);
      for (const j of [...passive]) if (w[j] <= 1e-15) { passive.delete(j); w[j] = 0; }
    }
  }
  return w;
}

/** Unconstrained least squares on the columns `columns` (normal equations, Gauss elimination); 0 elsewhere. */
function leastSquaresOn(A, b, columns) {
  const m = columns.length;
  const M = columns.map((j) => [...columns.map((k) => A.reduce((s, row) => s + row[j] * row[k], 0)), A.reduce((s, row, i) => s + row[j] * b[i], 0)]);
  for (let i = 0; i < m; i++) {
    let p = i;
    for (let k = i + 1; k < m; k++) if (Math.abs(M[k][i]) > Math.abs(M[p][i])) p = k;
    [M[i], M[p]] = [M[p], M[i]];
    for (let k = 0; k < m; k++) {
      if (k === i || M[i][i] === 0) continue;
      const f = M[k][i] / M[i][i];
      for (let j = i; j <= m; j++) M[k][j] -= f * M[i][j];
    }
  }
  const z = new Array(A[0].length).fill(0);
  columns.forEach((j, i) => { z[j] = M[i][i] === 0 ? 0 : M[i][m] / M[i][i]; });
  return z;
}

/** 0.5 erf(x / √(2v)): a normalised Gaussian's marginal energy from 0 to x. */
const halfEnergy = (xMm, varianceMm2) => 0.5 * erf(xMm / Math.sqrt(2 * varianceMm2));

/** profile → its fit (a few ms). */
const fits = new WeakMap();

/**
 * The profile as a Gaussian sum: its own `gaussians` (exact), else the fit.
 * @param {object} profile a profile (see src/profiles/radialProfile.js)
 * @returns {{ gaussians: ReadonlyArray<{ varianceMm2: number, weights: number[] }>, stepError: number[], exact: boolean }}
 *   the Gaussians by increasing variance, RGB weights (each channel sums to 1 within 1e-3)
 */
export function gaussianSumOf(profile) {
  if (profile.gaussians) return { gaussians: [...profile.gaussians].sort((a, b) => a.varianceMm2 - b.varianceMm2), stepError: [0, 0, 0], exact: true };
  if (!fits.has(profile)) fits.set(profile, fitGaussians(profile));
  return fits.get(profile);
}

function fitGaussians(profile) {
  const medians = profile.radiusMm(0.5);
  const reach = Math.max(...profile.radiusMm(0.9999));
  const sigmas = [];
  const last = SIGMA_RANGE.aboveWidest * Math.max(...medians);
  for (let s = SIGMA_RANGE.belowNarrowest * Math.min(...medians); s < last * SIGMA_RANGE.ratio; s *= SIGMA_RANGE.ratio) sigmas.push(s);
  const variances = sigmas.map((s) => s * s);
  const xs = Array.from({ length: FIT_POINTS }, (_, j) => ((j + 1) / FIT_POINTS) ** 2 * reach);
  const energies = xs.map((x) => profile.marginalIntegral(0, x));
  const weights = [0, 1, 2].map((c) => {
    const A = [...xs.map((x) => variances.map((v) => halfEnergy(x, v))), variances.map(() => UNIT_ENERGY_WEIGHT)];
    const b = [...energies.map((e) => e[c]), UNIT_ENERGY_WEIGHT];
    return nonNegativeLeastSquares(A, b);
  });
  const gaussians = variances
    .map((varianceMm2, i) => ({ varianceMm2, weights: [0, 1, 2].map((c) => weights[c][i]) }))
    .filter((g) => g.weights.some((w) => w > 0));
  const stepError = [0, 1, 2].map((c) => Math.max(...xs.map((x, j) => Math.abs(gaussians.reduce((s, g) => s + g.weights[c] * halfEnergy(x, g.varianceMm2), 0) - energies[j][c]))));
  return Object.freeze({ gaussians: Object.freeze(gaussians.map(Object.freeze)), stepError, exact: false });
}
