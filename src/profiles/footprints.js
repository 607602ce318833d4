/**
 * Where the 'footprint' blur puts its taps. Per pixel the blur covers the pixels of one side of its
 * axis with contiguous footprints: the centre pixel alone, then BLOCKS footprints, then a last one
 * running to the end of the kernel. Each footprint is weighted by the exact energy of the profile's
 * marginal over its pixels and sampled once, between two texels, where it keeps the kernel's
 * variance (footprintSamplePosition). A footprint of one pixel is exact; a wider one answers a step
 * edge inside it with a step instead of the true ramp.
 *
 * For a footprint over pixels a..b sampled at t = q + f (q whole, 0 ≤ f < 1: texel q weighs 1 − f,
 * q + 1 weighs f), with E[i..j] the energy of pixels i..j and W = E[a..b], the worst step-edge
 * error (the edge at any pixel boundary inside it) is, per channel,
 *   max(E[a..q−1], |f·W − E[q+1..b]|, E[q+2..b])
 * (it only ever comes from the one footprint the edge falls in). The allocation minimises the
 * largest of these over all footprints and channels for the tap budget: a binary search on the
 * error bound, each step a greedy cover from the centre outwards (each footprint as wide as the
 * bound allows), which is optimal for a bound on contiguous segments. So the blur is pixel-exact
 * where the profile is steep and uses wide footprints where it is flat, for every channel at once.
 *
 * The allocation depends on the on-screen scale (pixels per profile mm), which varies per pixel:
 * FootprintTable computes it at FOOTPRINT_SCALES (log-spaced) and the shader takes the nearest row,
 * its edges in mm times the pixel's own scale (snapped, at least one pixel each).
 * @module profiles/footprints
 */

/** The scales the table is computed at: `perOctave` rows per doubling from `min` to `max` px per mm. */
export const FOOTPRINT_SCALES = Object.freeze({ min: 0.125, max: 128, perOctave: 8 });

/** Energy per side left out beyond the kernel's end: the last footprint runs that far. */
const TAIL = 1e-5;
/** The most pixels a side is allocated over (the last footprint takes whatever lies beyond). */
const MAX_PIXELS = 4096;

/**
 * Cumulative energy of one side in pixel units: P[j] = G(j + 1/2 px) − G(1/2 px) per channel, the
 * energy of pixels 1..j, from `G(xMm)` = ∫_0^x marginal (0 .. 1/2).
 * @param {(xMm: number) => number[]} G
 * @param {number} pxPerMm
 * @returns {{ P: Float64Array[], R: number }} per channel, and the pixels covered
 */
function sideEnergy(G, pxPerMm) {
  const g0 = G(0.5 / pxPerMm);
  const rows = [[0, 0, 0]];
  let R = 0;
  while (R < MAX_PIXELS) {
    R++;
    const g = G((R + 0.5) / pxPerMm);
    rows.push(g.map((v, c) => v - g0[c]));
    if (Math.max(...g.map((v) => 0.5 - v)) < TAIL) break;
  }
  return { P: [0, 1, 2].map((c) => Float64Array.from(rows, (r) => r[c])), R };
}

/** Energy of pixels i..j of channel c (0 when j < i). */
const energy = (P, c, i, j) => (j < i ? 0 : P[c][j] - P[c][i - 1]);

/**
 * Where the footprint over pixels a..b is sampled, pixels: the tap reads texels q and q + 1 with
 * weights 1 − f and f (t = q + f), whose second moment (1 − f)q² + f(q + 1)² is set to the
 * footprint's own, T = Σ e_j j² / Σ e_j over all channels: q = ⌊√T⌋, f = (T − q²) / (2q + 1). So the
 * footprints together keep the kernel's variance (within 0.3 % for skin's red at 5-10 px/mm; the
 * middle overshot it by up to 65 %, the plain centroid undershot by 5 %), which is what its
 * low-frequency transfer 1 − 2π²σ²f² and a point's spread depend on.
 */
export function footprintSamplePosition(P, a, b) {
  let moment = 0;
  let total = 0;
  for (let j = a; j <= b; j++) {
    const e = energy(P, 0, j, j) + energy(P, 1, j, j) + energy(P, 2, j, j);
    moment += e * j * j;
    total += e;
  }
  if (!(total > 0)) return (a + b) / 2;
  const T = moment / total;
  const q = Math.floor(Math.sqrt(T));
  return q + Math.min((T - q * q) / (2 * q + 1), 1 - 1e-9);
}

/** The worst step-edge error of the footprint over pixels a..b sampled at `t` (header formula). */
export function footprintError(P, a, b, t = footprintSamplePosition(P, a, b)) {
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
 * The fewest footprints over pixels 1..R with every error ≤ bound, each as wide as it may be (its
 * end found by doubling then bisection: a footprint's error grows with its width).
 */
function greedyCover(P, R, bound) {
  const ends = [];
  for (let a = 1; a <= R;) {
    let good = a; // a one-pixel footprint is exact
    let step = 1;
    while (good + step <= R && footprintError(P, a, good + step) <= bound) {
      good += step;
      step *= 2;
    }
    for (let bad = Math.min(good + step, R + 1); bad - good > 1;) {
      const mid = (good + bad) >> 1;
      if (footprintError(P, a, mid) <= bound) good = mid;
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
  const { P, R } = sideEnergy(G, pxPerMm);
  let lo = 0;
  let hi = 0.5;
  let best = greedyCover(P, R, hi);
  for (let i = 0; i < 32; i++) {
    const bound = (lo + hi) / 2;
    const ends = greedyCover(P, R, bound);
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
    offsetsPx.push(footprintSamplePosition(P, a, b));
    stepError = Math.max(stepError, footprintError(P, a, b));
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
 * same arithmetic as shaders/3-blur/subsurfaceBlur.frag.glsl.
 * @param {number} pxPerMm
 */
export function footprintRowOf(pxPerMm) {
  const row = Math.floor(Math.log2(pxPerMm / FOOTPRINT_SCALES.min) * FOOTPRINT_SCALES.perOctave + 0.5);
  return Math.min(Math.max(row, 0), FOOTPRINT_ROWS - 1);
}

/**
 * The allocation at every table scale, in profile mm, two numbers per footprint: texel k of row r
 * holds (outer edge, sample offset) of footprint k, the last footprint's edge being Infinity
 * (it runs to the kernel's end). Rows at scales where fewer footprints suffice repeat single pixels
 * beyond the kernel (the shader snaps each edge to at least one pixel past the previous one).
 * @param {(xMm: number) => number[]} G
 * @param {number} samples
 * @returns {{ data: Float32Array, columns: number, rows: number, stepError: Float64Array }}
 *   data: RG pairs, `columns` = (samples − 1) / 2 texels per row
 */
export function footprintTable(G, samples) {
  const columns = (samples - 1) / 2;
  const data = new Float32Array(2 * columns * FOOTPRINT_ROWS);
  const stepError = new Float64Array(FOOTPRINT_ROWS);
  for (let row = 0; row < FOOTPRINT_ROWS; row++) {
    const s = footprintRowScale(row);
    const a = footprintAllocation(G, samples, s);
    for (let k = 0; k < columns; k++) {
      const i = 2 * (row * columns + k);
      if (k < a.offsetsPx.length) {
        data[i] = k < a.edgesPx.length ? a.edgesPx[k] / s : Infinity;
        data[i + 1] = a.offsetsPx[k] / s;
      } else {
        // Budget left over: single pixels past the kernel's end, sampled at their centres.
        data[i] = 0;
        data[i + 1] = 0;
      }
    }
    stepError[row] = a.stepError;
  }
  return { data, columns, rows: FOOTPRINT_ROWS, stepError };
}
