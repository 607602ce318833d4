/**
 * Where the 'footprint' blur puts its taps: each side of the axis is covered by contiguous
 * footprints (the centre pixel alone, then the rest, the last running to the kernel's end), each
 * weighted by the marginal's exact energy over its pixels and sampled once, between two texels.
 * A one-pixel footprint is exact; a wider one answers a step edge inside it with a step, not a ramp.
 *
 * For a footprint over pixels a..b sampled at t = q + f (texel q weighs 1 − f, q + 1 weighs f),
 * E[i..j] the energy of pixels i..j and W = E[a..b], the worst step-edge error is, per channel,
 *   max(E[a..q−1], |f·W − E[q+1..b]|, E[q+2..b]).
 * The allocation minimises the largest over all footprints and channels for the tap budget: a
 * binary search on the bound, each step a greedy cover from the centre out (optimal for a bound on
 * contiguous segments). So the blur is pixel-exact where the profile is steep, wide where it is flat.
 *
 * The allocation depends on the on-screen scale (px per profile mm): the table holds it at
 * FOOTPRINT_SCALES and the shader takes the nearest row, scaled by the pixel's own scale.
 * @module profiles/footprints
 */

/** The scales the table is computed at: `perOctave` rows per doubling from `min` to `max` px per mm. */
export const FOOTPRINT_SCALES = Object.freeze({ min: 0.125, max: 128, perOctave: 8 });

/**
 * samples 'auto': at each scale the fewest taps whose worst step-edge error is at most this (a
 * fraction of the step). At 0.2 % the grating transfer stays within 0.03 of the analytic one
 * (simulated, skin and skinBurley, 0.5-16 px/mm, gratings of 4 px per cycle and more).
 */
export const AUTO_STEP_ERROR = 0.002;

/** The most taps 'auto' uses (beyond it, at extreme close-ups, the error grows past AUTO_STEP_ERROR). */
export const AUTO_MAX_SAMPLES = 63;

/** Energy per side left out beyond the kernel's end: the last footprint runs that far. */
const TAIL = 1e-5;
/** The most pixels a side is allocated over (the last footprint takes whatever lies beyond). */
const MAX_PIXELS = 4096;

/**
 * Cumulative energy of one side: P[c][j], pixels 1..j of channel c; over all channels S0[j] = Σ e_i
 * and S2[j] = Σ e_i i² (i ≤ j), for the sample positions.
 * @param {(xMm: number) => number[]} G
 * @param {number} pxPerMm
 * @returns {{ P: Float64Array[], S0: Float64Array, S2: Float64Array, R: number }} R: the pixels covered
 */
function sideEnergy(G, pxPerMm) {
  const g0 = G(0.5 / pxPerMm);
  const P = [0, 1, 2].map(() => new Float64Array(MAX_PIXELS + 1));
  const S0 = new Float64Array(MAX_PIXELS + 1);
  const S2 = new Float64Array(MAX_PIXELS + 1);
  let R = 0;
  while (R < MAX_PIXELS) {
    R++;
    const g = G((R + 0.5) / pxPerMm);
    let e = 0;
    for (let c = 0; c < 3; c++) {
      P[c][R] = g[c] - g0[c];
      e += P[c][R] - P[c][R - 1];
    }
    S0[R] = S0[R - 1] + e;
    S2[R] = S2[R - 1] + e * R * R;
    if (Math.max(0.5 - g[0], 0.5 - g[1], 0.5 - g[2]) < TAIL) break;
  }
  return { P, S0, S2, R };
}

/** Energy of pixels i..j of channel c (0 when j < i). */
const energy = (P, c, i, j) => (j < i ? 0 : P[c][j] - P[c][i - 1]);

/**
 * Where the footprint over pixels a..b is sampled, px: the tap's second moment (1 − f)q² + f(q + 1)²
 * equals the footprint's, T = Σ e_j j² / Σ e_j, so the footprints keep the kernel's variance, on
 * which its low-frequency transfer 1 − 2π²σ²f² depends (the middle overshoots it, the centroid
 * undershoots).
 */
export function footprintSamplePosition({ S0, S2 }, a, b) {
  const total = S0[b] - S0[a - 1];
  if (!(total > 0)) return (a + b) / 2;
  const T = (S2[b] - S2[a - 1]) / total;
  const q = Math.min(Math.max(Math.floor(Math.sqrt(T)), a), b);
  return q + Math.min(Math.max((T - q * q) / (2 * q + 1), 0), 1 - 1e-9);
}

/** The worst step-edge error of the footprint over pixels a..b sampled at `t` (header formula). */
export function footprintError(side, a, b, t = footprintSamplePosition(side, a, b)) {
  const { P } = side;
  const q = Math.floor(t);
  const f = t - q;
  let worst = 0;
  for (let c = 0; c < 3; c++) {
    const W = energy(P, c, a, b);
    worst = Math.max(worst, energy(P, c, a, q - 1), Math.abs(f * W - energy(P, c, q + 1, b)), energy(P, c, q + 2, b));
  }
  return worst;
}

/**
 * The fewest footprints over pixels 1..R with every error ≤ bound, each as wide as it may be
 * (doubling then bisection: the error grows with the width).
 */
function greedyCover(side, R, bound) {
  const ends = [];
  for (let a = 1; a <= R;) {
    let good = a; // a one-pixel footprint is exact
    let step = 1;
    while (good + step <= R && footprintError(side, a, good + step) <= bound) {
      good += step;
      step *= 2;
    }
    for (let bad = Math.min(good + step, R + 1); bad - good > 1;) {
      const mid = (good + bad) >> 1;
      if (footprintError(side, a, mid) <= bound) good = mid;
      else bad = mid;
    }
    ends.push(good);
    a = good + 1;
  }
  return ends;
}

/**
 * The allocation for one scale.
 * @param {(xMm: number) => number[]} G ∫_0^x of the profile's marginal, per channel
 * @param {number} samples taps per direction (odd): `(samples − 1) / 2` footprints per side
 * @param {number} pxPerMm pixels per profile millimetre
 * @returns {{ edgesPx: number[], offsetsPx: number[], stepError: number }} the outer pixel of each
 *   footprint but the last, where each footprint (the last included) is sampled, and the worst
 *   step-edge error (per channel, as a fraction of a unit step)
 */
export function footprintAllocation(G, samples, pxPerMm) {
  const budget = (samples - 1) / 2;
  const side = sideEnergy(G, pxPerMm);
  const { R } = side;
  let lo = 0;
  let hi = 0.5;
  let best = greedyCover(side, R, hi);
  for (let i = 0; i < 32; i++) {
    const bound = (lo + hi) / 2;
    const ends = greedyCover(side, R, bound);
    if (ends.length <= budget) {
      hi = bound;
      best = ends;
    } else {
      lo = bound;
    }
  }
  const offsetsPx = [];
  let stepError = 0;
  best.forEach((b, i) => {
    const a = i === 0 ? 1 : best[i - 1] + 1;
    offsetsPx.push(footprintSamplePosition(side, a, b));
    stepError = Math.max(stepError, footprintError(side, a, b));
  });
  return { edgesPx: best.slice(0, -1), offsetsPx, stepError };
}

/** The scale of row `row` of the table, px per mm. */
export function footprintRowScale(row) {
  return FOOTPRINT_SCALES.min * 2 ** (row / FOOTPRINT_SCALES.perOctave);
}

/** The table's rows: one per FOOTPRINT_SCALES step. */
export const FOOTPRINT_ROWS = Math.round(Math.log2(FOOTPRINT_SCALES.max / FOOTPRINT_SCALES.min) * FOOTPRINT_SCALES.perOctave) + 1;

/**
 * The row the shader reads for a pixel of scale `pxPerMm` (nearest in log scale, clamped): the
 * same arithmetic as shaders/3-blur/blurTaps.glsl.
 * @param {number} pxPerMm
 */
export function footprintRowOf(pxPerMm) {
  const row = Math.floor(Math.log2(pxPerMm / FOOTPRINT_SCALES.min) * FOOTPRINT_SCALES.perOctave + 0.5);
  return Math.min(Math.max(row, 0), FOOTPRINT_ROWS - 1);
}

/**
 * The fewest taps (odd) whose allocation at `pxPerMm` keeps the worst step-edge error within
 * `maxError`, and that allocation (AUTO_MAX_SAMPLES's when none does).
 * @param {(xMm: number) => number[]} G
 * @param {number} pxPerMm
 * @param {number} [maxError=AUTO_STEP_ERROR]
 * @returns {{ samples: number, allocation: ReturnType<typeof footprintAllocation> }}
 */
export function autoFootprintAllocation(G, pxPerMm, maxError = AUTO_STEP_ERROR) {
  // The error falls as taps are added: bisect on the odd counts 3..AUTO_MAX_SAMPLES.
  let lo = 0; // half-counts h: samples 2h + 1; h = 0 is no footprint at all
  let hi = (AUTO_MAX_SAMPLES - 1) / 2;
  let best = footprintAllocation(G, AUTO_MAX_SAMPLES, pxPerMm);
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    const allocation = footprintAllocation(G, 2 * mid + 1, pxPerMm);
    if (allocation.stepError <= maxError) {
      hi = mid;
      best = allocation;
    } else {
      lo = mid;
    }
  }
  return { samples: 2 * hi + 1, allocation: best };
}

/**
 * The allocation at every table scale, in profile mm: texel k of row r holds (outer edge, sample
 * offset) of footprint k; the last footprint's edge is Infinity (the kernel's end).
 * @param {(xMm: number) => number[]} G
 * @param {number|'auto'} samples a fixed budget, or 'auto': per row the fewest taps within AUTO_STEP_ERROR
 * @returns {{ data: Float32Array, columns: number, rows: number, stepError: Float64Array, samples: Int32Array }}
 *   data: RG pairs, `columns` footprints per row ((samples − 1) / 2, AUTO_MAX_SAMPLES's for 'auto');
 *   stepError and samples per row
 */
export function footprintTable(G, samples) {
  const auto = samples === 'auto';
  const columns = ((auto ? AUTO_MAX_SAMPLES : samples) - 1) / 2;
  const data = new Float32Array(2 * columns * FOOTPRINT_ROWS);
  const stepError = new Float64Array(FOOTPRINT_ROWS);
  const used = new Int32Array(FOOTPRINT_ROWS);
  for (let row = 0; row < FOOTPRINT_ROWS; row++) {
    const s = footprintRowScale(row);
    const chosen = auto ? autoFootprintAllocation(G, s) : { samples, allocation: footprintAllocation(G, samples, s) };
    const a = chosen.allocation;
    a.offsetsPx.forEach((offset, k) => {
      const i = 2 * (row * columns + k);
      data[i] = k < a.edgesPx.length ? a.edgesPx[k] / s : Infinity;
      data[i + 1] = offset / s;
    });
    stepError[row] = a.stepError;
    used[row] = chosen.samples;
  }
  return { data, columns, rows: FOOTPRINT_ROWS, stepError, samples: used };
}
