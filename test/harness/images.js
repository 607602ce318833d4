// Small helpers over RGBA float read-backs (rows bottom-up, GL order), used by the pixel tests.

/** Index of pixel (x, y) in an RGBA array. */
export const at = (width, x, y) => (y * width + x) * 4;

/** Channel `c` of an RGBA image as a Float64Array of width·height. */
export function channel(rgba, c) {
  const out = new Float64Array(rgba.length / 4);
  for (let i = 0; i < out.length; i++) out[i] = rgba[i * 4 + c];
  return out;
}

/** RGB of an RGBA image as a Float64Array of width·height·3 (the oracle's layout). */
export function rgb(rgba) {
  const out = new Float64Array((rgba.length / 4) * 3);
  for (let i = 0; i < rgba.length / 4; i++) for (let c = 0; c < 3; c++) out[i * 3 + c] = rgba[i * 4 + c];
  return out;
}

/** Pixel-wise a - b over RGB (RGBA in, RGBA out with alpha 1). */
export function subtract(a, b) {
  const out = new Float32Array(a.length);
  for (let i = 0; i < a.length; i += 4) {
    for (let c = 0; c < 3; c++) out[i + c] = a[i + c] - b[i + c];
    out[i + 3] = 1;
  }
  return out;
}

/** Count of non-finite values in an array. */
export function countNonFinite(values) {
  let n = 0;
  for (const v of values) if (!Number.isFinite(v)) n++;
  return n;
}

/** Mean RGB over the middle `share` of a square image's width and height. */
export function middle(rgba, size, share = 0.3) {
  const lo = Math.round(size * (0.5 - share / 2));
  const hi = Math.round(size * (0.5 + share / 2));
  const sum = [0, 0, 0];
  for (let y = lo; y < hi; y++) for (let x = lo; x < hi; x++) for (let c = 0; c < 3; c++) sum[c] += rgba[(y * size + x) * 4 + c];
  return sum.map((v) => v / (hi - lo) ** 2);
}
