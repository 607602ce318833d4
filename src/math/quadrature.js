/**
 * Float64 quadrature for the profiles' numerical paths and the energy tables: adaptive
 * Gauss-Legendre, and substitutions for semi-infinite or square-root-ended intervals.
 * @module math/quadrature
 */

const gaussLegendreCache = new Map();

/**
 * n-point Gauss-Legendre nodes and weights on [-1, 1], by Newton iteration on P_n (cached).
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
 * Adaptive Gauss-Legendre of a vector-valued function: a panel is accepted when it agrees with its
 * two halves, else each half is refined with half the tolerance, so the errors add up to at most it.
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
export function integrateSqrtLeft(f, a, b, options = {}) {
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
