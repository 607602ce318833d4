// The analytic accuracy suite's measurements and its table of cases for the default method
// ('footprint', samples 'auto'), shared by the WebGL pipeline's test (accuracy.test.js) and the
// WebGPURenderer node's (webgpuAccuracy.test.js), so both renderers meet the same thresholds on the
// same scenes (test/pages/flatScene.js). A flat plane of subsurface material seen straight on at a
// known scale, with cosine gratings and step edges of albedo, blurred and compared with closed forms
// of the profiles (written out here, independent of the library's kernel code):
// - transfer of a grating at f cycles/mm along an axis: the marginal's Fourier transform M(f):
//   Gaussian sums Σ wᵢ exp(−2π² vᵢ f²) (d'Eon skin, marble), Burley ¼(1/√(1+(2πfl)²) + 3/√(1+(6πfl)²));
//   along the diagonal a separable blur gives M(f/√2)²;
// - a step edge: the exact 1D convolution of the pixel image with the marginal, E(x) = the
//   profile's energy beyond a line at x (Gaussian sums: Σ wᵢ erfc(x/√(2vᵢ))/2; Burley: a polar
//   integral of its closed-form R, computed here).
// - off the axes (the isotropic blur, issue 20): the radial answer M(f) at every angle; a step edge
//   at 45° and a lit pixel against the exact 2D convolution of the pixel image with the radial
//   Gaussian sum (radialBlur below: per Gaussian, separable, each pixel a constant square), and
//   the lit pixel's response compared in rings between sectors on and off the axes.
// Thresholds for the default: transfer within 0.03 where the grating has at least 4 pixels per
// cycle, step edges within 1 % of the step, at 0.5-10 px/mm.
import { expect } from 'vitest';
import { GAUSSIANS, BURLEY_L, transferOf, erfc } from '../../oracle/closedForms.js';
import { frequenciesAt, measuredTransfer } from '../../oracle/gratingFit.js';

/** E(x): the profile's energy beyond the line at x mm (x may be negative), per channel. */
export function beyondLine(profile, x) {
  if (x < 0) return beyondLine(profile, -x).map((e) => 1 - e);
  if (profile !== 'skinBurley') return [0, 1, 2].map((c) => GAUSSIANS[profile].reduce((s, [v, w]) => s + w[c] * 0.5 * erfc(x / Math.sqrt(2 * v)), 0));
  // Burley: R(r) = (e^{−r/l} + e^{−r/3l}) / (8π l r); the circle of radius r > x has the angle
  // 2 acos(x / r) beyond the line: E(x) = ∫_x^∞ 2 acos(x/r) R(r) r dr, with r = x + u² against the
  // square-root start, trapezoid in u (smooth), out to 80 l.
  return BURLEY_L.map((l) => {
    if (x === 0) return 0.5;
    const R = (r) => (Math.exp(-r / l) + Math.exp(-r / (3 * l))) / (8 * Math.PI * l * r);
    const U = Math.sqrt(80 * l);
    const n = 6000;
    let sum = 0;
    for (let k = 1; k <= n; k++) {
      const u = (k / n) * U;
      const r = x + u * u;
      sum += (k === n ? 0.5 : 1) * 2 * Math.acos(x / r) * R(r) * r * 2 * u;
    }
    return sum * (U / n);
  });
}

/**
 * The exact response of a pixel image (RGBA floats, rows bottom-up) to a Gaussian-sum profile's
 * radial 2D kernel at `s` px/mm: each pixel a constant square, each 2D Gaussian separable, its
 * weight over pixel offset k the 1D normal's energy over [k − ½, k + ½] / s mm (to 7 σ). Only the
 * pixels of `region` (x0 ≤ x < x1, y0 ≤ y < y1; the whole image by default) are computed: the rows
 * the vertical pass reads there, within their reach, in the horizontal pass.
 * @returns {Float64Array} RGB per pixel of the image, 0 outside `region` (off-screen light counts
 *   as 0: compare away from the border)
 */
export function radialBlur(image, width, height, profile, s, { x0 = 0, x1 = width, y0 = 0, y1 = height } = {}) {
  const whole = (v, lo, hi) => Number.isInteger(v) && v >= lo && v <= hi;
  if (!whole(x0, 0, width) || !whole(x1, x0, width) || !whole(y0, 0, height) || !whole(y1, y0, height)) {
    throw new RangeError(`radialBlur: the region must be whole pixels within ${width} × ${height}, got x ${x0}..${x1}, y ${y0}..${y1}`);
  }
  const out = new Float64Array(width * height * 3);
  const row = new Float64Array(width * height);
  for (const [v, w] of GAUSSIANS[profile]) {
    const sigmaPx = Math.sqrt(v) * s;
    const reach = Math.ceil(7 * sigmaPx) + 1;
    const cdf = (x) => 0.5 * erfc(-x / (Math.SQRT2 * sigmaPx));
    const taps = Float64Array.from({ length: 2 * reach + 1 }, (_, k) => cdf(k - reach + 0.5) - cdf(k - reach - 0.5));
    for (let c = 0; c < 3; c++) {
      if (!(w[c] > 0)) continue;
      for (let y = Math.max(0, y0 - reach); y < Math.min(height, y1 + reach); y++) {
        for (let x = x0; x < x1; x++) {
          let sum = 0;
          for (let k = -reach; k <= reach; k++) if (x + k >= 0 && x + k < width) sum += taps[k + reach] * image[(y * width + x + k) * 4 + c];
          row[y * width + x] = sum;
        }
      }
      for (let y = y0; y < y1; y++) {
        for (let x = x0; x < x1; x++) {
          let sum = 0;
          for (let k = -reach; k <= reach; k++) if (y + k >= 0 && y + k < height) sum += taps[k + reach] * row[(y + k) * width + x];
          out[(y * width + x) * 3 + c] += w[c] * sum;
        }
      }
    }
  }
  return out;
}

/**
 * The canvas across the axis of a step edge or a grating along x or y, pixels: the pattern is
 * constant across it, so a strip gives the row (or column) through the centre exactly as a square
 * would (taps across it fall on the same value, dropped or kept alike at the strip's ends), at a
 * sixteenth of the square's pixels. Only for a separable blur, which blurs along the pattern first
 * (the dense 2D reference would weigh each row by a disc cut at the strip's ends).
 */
const STRIP = 16;

/**
 * The canvas of a pattern along the axis at `angleDeg` at `s` px/mm: a strip along x or y, else a
 * square, of 128 px up to 2 px/mm (the grating fit's window then 92 px or more, 46 mm, at least two
 * periods of the lowest frequency: measured against 256 px for skin, skinBurley and marble at 22.5°
 * and 45°, the isotropic blur's transfer within 2e-4), else 256.
 */
const canvasFor = (angleDeg, s = Infinity) => {
  if (angleDeg === 0) return [256, STRIP];
  if (angleDeg === 90) return [STRIP, 256];
  return s <= 2 ? [128, 128] : [256, 256];
};

/**
 * The two measurements over a renderer's flat scene.
 * @param {(options: object) => Promise<{ before: Float32Array, after: Float32Array, glError?: number }>} flat
 *   renders test/pages/flatScene.js's scene with `options` and reads the diffuse light back before
 *   and after the blur (float RGBA)
 */
export function accuracyMeasures(flat) {
  /** Measured transfer per frequency and channel, and its worst difference from `expected(f)`. */
  async function grating({ profile, s, angleDeg = 0, sss = {}, size = canvasFor(angleDeg, s), expected = (f) => transferOf(profile, f) }) {
    const [width, height] = size;
    const frequencies = frequenciesAt(s);
    const phases = frequencies.map((_, k) => 0.7 * k);
    const r = await flat({ width, height, pxPerMm: s, pattern: 'cosines', frequencies, phases, angleDeg, sss: { profile, ...sss } });
    if (r.glError !== undefined) expect(r.glError).toBe(0);
    const measured = measuredTransfer(r, frequencies, s, angleDeg);
    let worst = 0;
    frequencies.forEach((f, k) => {
      const e = expected(f);
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(measured[c][k] - e[c]));
    });
    return { worst, measured, frequencies };
  }

  /** Worst |measured − exact| of a step edge's response along the row (or column) through the centre, per channel. */
  async function stepEdge({ profile, s, angleDeg = 0, sss = {} }) {
    const [width, height] = canvasFor(angleDeg); // a strip (STRIP)
    const low = 0.05;
    const r = await flat({ width, height, pxPerMm: s, pattern: 'step', angleDeg, low, sss: { profile, ...sss } });
    if (r.glError !== undefined) expect(r.glError).toBe(0);
    const vertical = angleDeg === 90;
    const length = vertical ? height : width;
    const reach = Math.min(Math.ceil(12 * s), length / 2 - 2);
    const at = (image, i, c) => {
      const x = vertical ? width / 2 : length / 2 + i;
      const y = vertical ? length / 2 + i : height / 2;
      return image[(y * width + x) * 4 + c];
    };
    let worst = 0;
    for (let i = -reach; i < reach; i++) {
      // Pixel i from the edge (the edge between pixels −1 and 0): lit pixels are j ≥ 0, so the exact
      // response is the energy beyond the line through the edge, at (−i − 1/2) / s mm from the centre.
      // (A backend storing rows top-down mirrors the vertical case about the edge: the response
      // measured from the two levels is then the same.)
      const exact = beyondLine(profile, (-i - 0.5) / s);
      for (let c = 0; c < 3; c++) {
        // The step's two levels as the material shaded them (three's diffuse is not exactly the albedo).
        const dark = at(r.before, -reach, c);
        const lit = at(r.before, reach - 1, c);
        const response = (at(r.after, i, c) - dark) / (lit - dark);
        worst = Math.max(worst, Math.abs(response - exact[c]));
      }
    }
    return worst;
  }

  /**
   * A step edge at 45° on a square canvas against radialBlur of the image before the blur: the
   * worst difference over the pixels within `window` of the centre, as a fraction of the step. On
   * 256² at every scale: on 192² at 2 px/mm the error moved from 0.0047 to 0.0050 (skin), the
   * screen's border within reach of the light along the edge.
   */
  async function diagonalStep({ profile, s, sss = {}, size = 256, window = 48 }) {
    const low = 0.05;
    const r = await flat({ width: size, height: size, pxPerMm: s, pattern: 'step', angleDeg: 45, low, sss: { profile, ...sss } });
    if (r.glError !== undefined) expect(r.glError).toBe(0);
    const exact = radialBlur(r.before, size, size, profile, s, { x0: size / 2 - window, x1: size / 2 + window, y0: size / 2 - window, y1: size / 2 + window });
    let worst = 0;
    let step = 0;
    for (let c = 0; c < 3; c++) step = Math.max(step, Math.abs(r.before[((size - 4) * size + size - 4) * 4 + c] - r.before[(3 * size + 3) * 4 + c]));
    for (let y = size / 2 - window; y < size / 2 + window; y++) {
      for (let x = size / 2 - window; x < size / 2 + window; x++) {
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(r.after[(y * size + x) * 4 + c] - exact[(y * size + x) * 3 + c]));
      }
    }
    return worst / step;
  }

  /**
   * One lit pixel's response (its point spread) in rings 2 px wide around it: per ring from 2 px
   * out, the mean response within 22.5° of the diagonals over that within 22.5° of the axes
   * (`anisotropy[k]`: the worst channel's |ratio − 1|; sectors, because a blur of one pixel by
   * taps one footprint apart is a lattice, not a smooth disc, at any single pixel), and the worst
   * difference from radialBlur's, as a fraction of its peak (`worst`). On 128² up to 2 px/mm (the
   * spot 64 px from the border, the kernel's reach 18 px): against 256² at 2 px/mm, with groups and
   * with one kernel, the same numbers to 6 digits.
   */
  async function pointSpread({ profile, s, sss = {}, size = s <= 2 ? 128 : 256, rings = 8 }) {
    const r = await flat({ width: size, height: size, pxPerMm: s, pattern: 'spot', low: 0, sss: { profile, ...sss } });
    if (r.glError !== undefined) expect(r.glError).toBe(0);
    const centre = size / 2;
    const exact = radialBlur(r.before, size, size, profile, s, { x0: centre - 2 * rings, x1: centre + 2 * rings, y0: centre - 2 * rings, y1: centre + 2 * rings });
    let peak = 0;
    for (let c = 0; c < 3; c++) peak = Math.max(peak, exact[(centre * size + centre) * 3 + c]);
    let worst = 0;
    const sums = Array.from({ length: rings }, () => ({ axis: [0, 0, 0], diagonal: [0, 0, 0], nAxis: 0, nDiagonal: 0 }));
    for (let dy = -2 * rings; dy < 2 * rings; dy++) {
      for (let dx = -2 * rings; dx < 2 * rings; dx++) {
        const i = (centre + dy) * size + centre + dx;
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(r.after[i * 4 + c] - exact[i * 3 + c]));
        const ring = Math.floor(Math.hypot(dx, dy) / 2);
        if (ring < 1 || ring >= rings) continue;
        const angle = Math.abs(Math.atan2(dy, dx) * 180 / Math.PI) % 90; // 0..90
        const sector = angle < 22.5 || angle > 67.5 ? 'axis' : 'diagonal';
        for (let c = 0; c < 3; c++) sums[ring][sector][c] += r.after[i * 4 + c];
        sums[ring][sector === 'axis' ? 'nAxis' : 'nDiagonal']++;
      }
    }
    // Per ring, the worst channel's |diagonal / axis − 1|.
    const anisotropy = sums.slice(1).map((ring) => Math.max(...[0, 1, 2].map((c) => Math.abs((ring.diagonal[c] / ring.nDiagonal) / (ring.axis[c] / ring.nAxis) - 1))));
    return { worst: worst / peak, anisotropy };
  }

  return { grating, stepEdge, diagonalStep, pointSpread };
}

/** The isotropic blur's setting (the default is one kernel, `kernelGroups: 1`). */
const ISOTROPIC = Object.freeze({ kernelGroups: 'auto' });

/**
 * The 'footprint' method's cases, the default (samples 'auto') and a fixed 17 taps: [title, run]
 * pairs for `it(title, run)`, over `accuracyMeasures(flat)`.
 * @param {ReturnType<typeof accuracyMeasures>} measures
 * @param {{ isotropicScales?: number[], isotropicProfiles?: string[] }} [options] the scales (px/mm)
 *   and profiles the isotropic blur's cases (`kernelGroups: 'auto'`: the radial answer off the axes)
 *   run at: 1-10 px/mm and skin, skinBurley and marble by default; a subset where the same blur code
 *   runs again (the WebGPU node's second backend)
 * @returns {[string, () => Promise<void>][]}
 */
export function footprintCases({ grating, stepEdge, diagonalStep, pointSpread }, { isotropicScales = [1, 2, 5, 10], isotropicProfiles = ['skin', 'skinBurley', 'marble'] } = {}) {
  const scales = (within) => isotropicScales.filter((s) => within.includes(s));
  const named = (list) => list.join(' and ');
  const cases = [];
  for (const profile of ['skin', 'skinBurley']) {
    for (const s of [1, 2, 5, 10]) {
      cases.push([`${profile}: gratings along x and y at ${s} px/mm have the analytic transfer within 0.03`, async () => {
        for (const angleDeg of [0, 90]) {
          const { worst, frequencies } = await grating({ profile, s, angleDeg });
          expect(frequencies.length).toBeGreaterThan(0);
          expect(worst, `${angleDeg}°`).toBeLessThan(0.03);
        }
      }]);
    }
    cases.push([`${profile}: step edges along x and y at 0.5-8 px/mm are within 1 % of the exact 1D convolution`, async () => {
      for (const s of [0.5, 1, 2, 4, 8]) {
        for (const angleDeg of [0, 90]) expect(await stepEdge({ profile, s, angleDeg }), `${s} px/mm, ${angleDeg}°`).toBeLessThan(0.01);
      }
    }]);
  }
  cases.push(['marble: gratings along x at 2 and 5 px/mm within 0.03', async () => {
    for (const s of [2, 5]) expect((await grating({ profile: 'marble', s })).worst).toBeLessThan(0.03);
  }]);
  for (const profile of isotropicProfiles) {
    const at = scales(profile === 'marble' ? [2, 5] : [1, 2, 5, 10]);
    if (at.length === 0) continue;
    cases.push([`${profile}: gratings at 22.5° and 45° have the radial transfer M(f) within 0.03 at ${named(at)} px/mm (the isotropic blur, kernelGroups 'auto')`, async () => {
      for (const s of at) {
        for (const angleDeg of [22.5, 45]) expect((await grating({ profile, s, angleDeg, sss: ISOTROPIC })).worst, `${s} px/mm, ${angleDeg}°`).toBeLessThan(0.03);
      }
    }]);
  }
  cases.push(['one kernel (kernelGroups 1, the default) gets the separable transfer M(f/√2)² on the diagonal instead, 0.18 off M(f)', async () => {
    const separable = (f) => transferOf('skin', f / Math.SQRT2).map((m) => m * m);
    expect((await grating({ profile: 'skin', s: 3, angleDeg: 45, expected: separable, sss: { kernelGroups: 1 } })).worst).toBeLessThan(0.03);
    expect((await grating({ profile: 'skin', s: 3, angleDeg: 45, sss: { kernelGroups: 1 } })).worst).toBeGreaterThan(0.15);
  }]);
  const near = scales([2, 5]);
  for (const profile of near.length > 0 ? isotropicProfiles.filter((p) => p !== 'skinBurley') : []) {
    cases.push([`${profile}: a step edge at 45° is within 1 % of the step of the exact 2D convolution (${named(near)} px/mm)`, async () => {
      for (const s of near) expect(await diagonalStep({ profile, s, sss: ISOTROPIC }), `${s} px/mm`).toBeLessThan(0.01);
    }]);
  }
  if (near.length > 0 && isotropicProfiles.includes('skin')) cases.push([`skin: one lit pixel (${near.map((s) => 1 / s).join(' and ')} mm at ${named(near)} px/mm) spreads as the exact 2D convolution does within 2.5 % of its peak, and 2-4 px out as much on the diagonals as on the axes within 25 % (one kernel: 65-95 % less)`, async () => {
    for (const s of near) {
      const iso = await pointSpread({ profile: 'skin', s, sss: ISOTROPIC });
      const one = await pointSpread({ profile: 'skin', s, sss: { kernelGroups: 1 } });
      expect(iso.worst, `${s} px/mm`).toBeLessThan(0.025);
      expect(one.worst, `${s} px/mm, one kernel`).toBeGreaterThan(0.1); // the separable blur's cross: the test can tell
      // The ring 2-4 px out, where most of the spread light is (measured 0.16-0.18, one kernel
      // 0.66-0.93); farther out the footprints' sparse taps make a lattice: docs/ARCHITECTURE.md
      // gives those rings.
      expect(iso.anisotropy[0], `${s} px/mm`).toBeLessThan(0.25);
      expect(one.anisotropy[0], `${s} px/mm, one kernel`).toBeGreaterThan(0.5);
    }
  }]);
  cases.push(['is the same along x and y whatever the viewport aspect (2:1 and 1:2)', async () => {
    const wide = await grating({ profile: 'skin', s: 2, angleDeg: 0, size: [384, 192] });
    const tall = await grating({ profile: 'skin', s: 2, angleDeg: 90, size: [192, 384] });
    expect(wide.worst).toBeLessThan(0.03);
    for (let c = 0; c < 3; c++) wide.measured[c].forEach((m, k) => expect(Math.abs(m - tall.measured[c][k])).toBeLessThan(0.005));
  }]);
  cases.push(["'footprint' with a fixed 17 taps: step edges within 1 % up to 4 px/mm", async () => {
    for (const s of [1, 4]) expect(await stepEdge({ profile: 'skin', s, sss: { samples: 17 } })).toBeLessThan(0.01);
  }]);
  return cases;
}
