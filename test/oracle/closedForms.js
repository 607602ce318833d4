// Closed forms of the profiles, written out from the papers rather than taken from the library
// (src/profiles): the accuracy suite (test/browser/3-blur/accuracy.test.js), the bench's transfer plot and
// its surface-space truth (bench/surfaceTruth/) all compare with these.
// d'Eon & Luebke 2007's six Gaussians [variance mm², rgb weights] (REFERENCE §2); the skinBurley
// scatter distances, which src/profiles/presets.js documents and the profile unit tests derive
// from skin's radii.
export const DEON = [
  [0.0064, [0.233, 0.455, 0.649]], [0.0484, [0.1, 0.336, 0.344]], [0.187, [0.118, 0.198, 0]],
  [0.567, [0.113, 0.007, 0.007]], [1.99, [0.358, 0.004, 0]], [7.41, [0.078, 0, 0]],
];
export const MARBLE = [
  [0.0362, [0.0545, 0.1245, 0.2177]], [0.1145, [0.2437, 0.2435, 0.189]], [0.4556, [0.3105, 0.3158, 0.3742]], [3.4833, [0.3913, 0.3161, 0.219]],
];
export const BURLEY_L = [0.41954, 0.097094, 0.059361];

export function normalised(gaussians) {
  const sums = [0, 1, 2].map((c) => gaussians.reduce((s, [, w]) => s + w[c], 0));
  return gaussians.map(([v, w]) => [v, w.map((x, c) => x / sums[c])]);
}
export const GAUSSIANS = { skin: normalised(DEON), marble: normalised(MARBLE) };

/** M(f): the marginal's Fourier transform, per channel. */
export function transferOf(profile, f) {
  if (profile === 'skinBurley') {
    return BURLEY_L.map((l) => 0.25 * (1 / Math.hypot(1, 2 * Math.PI * f * l) + 3 / Math.hypot(1, 6 * Math.PI * f * l)));
  }
  return [0, 1, 2].map((c) => GAUSSIANS[profile].reduce((s, [v, w]) => s + w[c] * Math.exp(-2 * Math.PI ** 2 * v * f * f), 0));
}

/** erfc (Abramowitz & Stegun 7.1.26 is too coarse here: a series / continued fraction, 1e-12). */
export function erfc(x) {
  if (x < 0) return 2 - erfc(-x);
  if (x < 2) {
    let term = x;
    let sum = x;
    for (let n = 1; n < 60; n++) { term *= (2 * x * x) / (2 * n + 1); sum += term; }
    return 1 - (2 / Math.sqrt(Math.PI)) * Math.exp(-x * x) * sum;
  }
  let f = 0;
  for (let n = 60; n >= 1; n--) f = (n / 2) / (x + f);
  return Math.exp(-x * x) / (Math.sqrt(Math.PI) * (x + f));
}
