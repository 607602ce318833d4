// Measuring a grating's transfer in a rendered image (pure, runs in Node): the amplitude of each
// frequency by least squares of c0 + Σ aₖ cos + bₖ sin along the grating, after over before the
// blur. Shared by the analytic accuracy suite (test/browser/3-blur/accuracy.test.js) and the bench's
// transfer plot (bench/transfer/run.js), which render with test/pages/lab.js's `flat`.

/** Solves the small dense system A y = b (Gaussian elimination with partial pivoting). */
function solve(A, b) {
  const n = b.length;
  const M = A.map((row, i) => [...row, b[i]]);
  for (let i = 0; i < n; i++) {
    let p = i;
    for (let k = i + 1; k < n; k++) if (Math.abs(M[k][i]) > Math.abs(M[p][i])) p = k;
    [M[i], M[p]] = [M[p], M[i]];
    for (let k = i + 1; k < n; k++) {
      const m = M[k][i] / M[i][i];
      for (let j = i; j <= n; j++) M[k][j] -= m * M[i][j];
    }
  }
  const y = new Array(n).fill(0);
  for (let i = n - 1; i >= 0; i--) {
    let s = M[i][n];
    for (let j = i + 1; j < n; j++) s -= M[i][j] * y[j];
    y[i] = s / M[i][i];
  }
  return y;
}

/**
 * Amplitude of each frequency in channel c of an image: least squares of c0 + Σ aₖ cos + bₖ sin
 * over the pixels at least `margins` (x, y) from the image's border, u the coordinate along the grating (mm).
 */
function amplitudes(image, { width, height }, c, frequencies, s, angleDeg, [marginX, marginY]) {
  const cos = Math.cos((angleDeg * Math.PI) / 180);
  const sin = Math.sin((angleDeg * Math.PI) / 180);
  const n = 1 + 2 * frequencies.length;
  const A = Array.from({ length: n }, () => new Array(n).fill(0));
  const b = new Array(n).fill(0);
  const basis = new Array(n);
  for (let y = marginY; y < height - marginY; y++) {
    for (let x = marginX; x < width - marginX; x++) {
      const u = (((x + 0.5 - width / 2) * cos) + ((y + 0.5 - height / 2) * sin)) / s;
      basis[0] = 1;
      frequencies.forEach((f, k) => {
        basis[1 + 2 * k] = Math.cos(2 * Math.PI * f * u);
        basis[2 + 2 * k] = Math.sin(2 * Math.PI * f * u);
      });
      const v = image[(y * width + x) * 4 + c];
      for (let i = 0; i < n; i++) {
        b[i] += basis[i] * v;
        for (let j = 0; j < n; j++) A[i][j] += basis[i] * basis[j];
      }
    }
  }
  const coef = solve(A, b);
  return frequencies.map((_, k) => Math.hypot(coef[1 + 2 * k], coef[2 + 2 * k]));
}

/** The grating frequencies (cycles/mm) the suite and the plot use. */
export const FREQUENCIES = [0.05, 0.1, 0.25, 0.4, 0.7, 1.0, 1.5];
/** The frequencies a scale (px/mm) can show with at least 4 pixels per cycle (at most 1.5 cycles/mm). */
export const frequenciesAt = (s) => FREQUENCIES.filter((f) => f <= 0.25 * s + 1e-9).slice(-5);

/** A side shorter than this is a strip across an axis-aligned grating (see measuredTransfer). */
const STRIP_MAX = 96;

/**
 * Pixels kept from the border along a side of `size` pixels (at least STRIP_MAX): the kernel's
 * reach (red skin: 99.9 % within 9 mm), at least 8, at most all but the central 80.
 */
export const gratingMargin = (s, size) => Math.min(Math.max(8, Math.ceil(9 * s)), Math.floor(size / 2) - 40);

/**
 * The measured transfer of each channel at each frequency: amplitude after over before. A side
 * under STRIP_MAX pixels is a strip across a grating along the other side (0° for a wide strip, 90°
 * for a tall one) and keeps no margin: every row (or column) of it is the centre's when the blur
 * is separable, its taps across falling on the same value and kept or dropped alike (the accuracy
 * suite's strips, test/browser/3-blur/accuracyCases.js). A strip at another angle, or an image
 * with both sides under STRIP_MAX, is a RangeError.
 * @param {{ before: Float32Array, after: Float32Array, width: number, height: number }} r RGBA floats
 * @param {number[]} frequencies cycles/mm @param {number} s px/mm @param {number} angleDeg the grating's direction
 * @returns {number[][]} [channel][frequency]
 */
export function measuredTransfer(r, frequencies, s, angleDeg) {
  const [wide, tall] = [r.height < STRIP_MAX, r.width < STRIP_MAX];
  if (wide && tall) throw new RangeError(`measuredTransfer: an image needs a side of at least ${STRIP_MAX} px, got ${r.width} × ${r.height}`);
  const stripAngle = wide ? 0 : tall ? 90 : null;
  if (stripAngle !== null && angleDeg !== stripAngle) throw new RangeError(`measuredTransfer: a ${r.width} × ${r.height} strip measures a grating at ${stripAngle}° only, got ${angleDeg}°`);
  const margin = [tall ? 0 : gratingMargin(s, r.width), wide ? 0 : gratingMargin(s, r.height)];
  return [0, 1, 2].map((c) => {
    const before = amplitudes(r.before, r, c, frequencies, s, angleDeg, margin);
    const after = amplitudes(r.after, r, c, frequencies, s, angleDeg, margin);
    return after.map((a, k) => a / before[k]);
  });
}
