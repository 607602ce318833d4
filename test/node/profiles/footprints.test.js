// The 'footprint' tap allocation (src/profiles/footprints.js) in Node: its footprints tile the
// kernel, its claimed step-edge error matches a brute-force simulation of the taps on a step edge
// (an independent calculation from the profile's closed-form strip energies), it keeps the
// kernel's variance, and its error falls with the budget to what 'auto' promises.
import { describe, it, expect } from 'vitest';
import { profiles } from '../../../src/profiles/presets.js';
import {
  footprintAllocation, footprintTable, footprintRowOf, footprintRowScale, FOOTPRINT_ROWS, FOOTPRINT_SCALES,
  AUTO_STEP_ERROR, AUTO_MAX_SAMPLES, autoFootprintAllocation,
} from '../../../src/profiles/footprints.js';

const G = (name) => (xMm) => profiles[name].marginalIntegral(0, xMm); // closed form for skin (erf)

/** The taps of an allocation as the shader applies them: centre, then ± each footprint. */
function tapsOf(g, s, { edgesPx, offsetsPx }) {
  const centre = g(0.5 / s).map((v) => 2 * v);
  const taps = [];
  let below = g(0.5 / s);
  offsetsPx.forEach((t, k) => {
    const energy = k < edgesPx.length ? g((edgesPx[k] + 0.5) / s) : [0.5, 0.5, 0.5];
    const w = energy.map((e, c) => e - below[c]);
    taps.push({ t, w }, { t: -t, w });
    below = energy;
  });
  return { centre, taps };
}

/** Worst |taps − exact| over step edges at every pixel boundary (pixels ≥ 0 lit), per channel max. */
function bruteForceStepError(name, s, allocation) {
  const g = G(name);
  const { centre, taps } = tapsOf(g, s, allocation);
  const lit = (j) => (j >= 0 ? 1 : 0);
  let worst = 0;
  const reach = Math.ceil(Math.max(...allocation.offsetsPx)) + 2;
  for (let i = -reach; i <= reach; i++) {
    const exact = profiles[name].marginalIntegral((-i - 0.5) / s, Infinity);
    const out = centre.map((w) => w * lit(i));
    for (const { t, w } of taps) {
      const q = Math.floor(i + t);
      const f = i + t - q;
      const v = lit(q) * (1 - f) + lit(q + 1) * f;
      for (let c = 0; c < 3; c++) out[c] += w[c] * v;
    }
    for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(out[c] - exact[c]));
  }
  return worst;
}

describe('footprintAllocation', () => {
  for (const name of ['skin', 'skinBurley']) {
    it(`${name}: footprints tile the side, each sampled inside itself, and the claimed error is what the taps do`, () => {
      for (const s of [0.5, 2, 6]) {
        for (const samples of [9, 17]) {
          const a = footprintAllocation(G(name), samples, s);
          expect(a.offsetsPx.length).toBeLessThanOrEqual((samples - 1) / 2);
          let start = 1;
          a.offsetsPx.forEach((t, k) => {
            const end = k < a.edgesPx.length ? a.edgesPx[k] : Infinity;
            expect(end).toBeGreaterThanOrEqual(start);
            expect(t).toBeGreaterThanOrEqual(start);
            expect(t).toBeLessThan(Math.min(end, 1e9) + 1);
            start = end + 1;
          });
          // The brute force covers the edge at every boundary; the formula must not understate it.
          const brute = bruteForceStepError(name, s, a);
          expect(Math.abs(brute - a.stepError)).toBeLessThan(2e-4 + 0.02 * brute);
        }
      }
    });
  }

  it("keeps the kernel's variance (all channels together) within 0.5 %, where sampling each footprint's middle overshoots it", () => {
    for (const name of ['skin', 'skinBurley']) {
      for (const s of [2, 5, 8]) {
        const g = G(name);
        const a = footprintAllocation(g, 17, s);
        const { taps } = tapsOf(g, s, a);
        let allocated = 0;
        for (const { t, w } of taps) {
          const q = Math.floor(Math.abs(t));
          const f = Math.abs(t) - q;
          allocated += (w[0] + w[1] + w[2]) * ((1 - f) * q * q + f * (q + 1) * (q + 1));
        }
        // Exact: the pixel energies' second moment out to where less than 1e-7 is left.
        let exact = 0;
        for (let j = 1; j < 40 * s; j++) {
          const e = profiles[name].marginalIntegral((j - 0.5) / s, (j + 0.5) / s);
          exact += 2 * (e[0] + e[1] + e[2]) * j * j;
        }
        expect(Math.abs(allocated / exact - 1)).toBeLessThan(0.005);
      }
    }
  });

  it('with 17 taps the step-edge error stays within 1 % up to 5 px/mm, and falls as taps are added', () => {
    for (const name of ['skin', 'skinBurley']) {
      for (const s of [0.5, 1, 2, 4, 5]) expect(footprintAllocation(G(name), 17, s).stepError).toBeLessThan(0.01);
      const errors = [9, 17, 25, 45].map((n) => footprintAllocation(G(name), n, 8).stepError);
      for (let i = 1; i < errors.length; i++) expect(errors[i]).toBeLessThan(errors[i - 1]);
      // Version 0.1 put every footprint at one pixel and lumped the rest into one tap pair: 8.2 % at 8 px/mm.
      expect(errors[1]).toBeLessThan(0.016);
    }
  });
});

describe("'auto'", () => {
  it('takes the fewest taps within AUTO_STEP_ERROR at each scale, fewer where the kernel is small on screen', () => {
    const g = G('skin');
    let previous = 0;
    for (const s of [0.25, 1, 2, 4, 8, 16]) {
      const { samples, allocation } = autoFootprintAllocation(g, s);
      expect(allocation.stepError).toBeLessThanOrEqual(AUTO_STEP_ERROR);
      expect(samples).toBeGreaterThanOrEqual(previous);
      if (samples > 3) expect(footprintAllocation(g, samples - 2, s).stepError).toBeGreaterThan(AUTO_STEP_ERROR);
      previous = samples;
    }
    expect(autoFootprintAllocation(g, 1.5).samples).toBeLessThan(17); // the head at 720p needs fewer than 17
    expect(autoFootprintAllocation(g, 16).samples).toBeLessThanOrEqual(AUTO_MAX_SAMPLES);
  });
});

describe('footprintTable', () => {
  it('holds one row per scale, edges and offsets in mm, the last footprint of each row open-ended', () => {
    const t = footprintTable(G('skin'), 17);
    expect(t.columns).toBe(8);
    expect(t.rows).toBe(FOOTPRINT_ROWS);
    expect(t.data.length).toBe(2 * 8 * FOOTPRINT_ROWS);
    for (let row = 0; row < t.rows; row++) {
      const s = footprintRowScale(row);
      const a = footprintAllocation(G('skin'), 17, s);
      const n = a.offsetsPx.length;
      expect(t.data[2 * (row * 8 + n - 1)]).toBe(Infinity);
      if (n > 1) expect(t.data[2 * (row * 8)] * s).toBeCloseTo(a.edgesPx[0], 4);
    }
  });

  it('maps a scale to its nearest row', () => {
    expect(footprintRowOf(FOOTPRINT_SCALES.min)).toBe(0);
    expect(footprintRowOf(FOOTPRINT_SCALES.min / 10)).toBe(0);
    expect(footprintRowOf(1e6)).toBe(FOOTPRINT_ROWS - 1);
    for (const row of [3, 40, 70]) {
      expect(footprintRowOf(footprintRowScale(row))).toBe(row);
      expect(footprintRowOf(footprintRowScale(row) * 2 ** (0.4 / FOOTPRINT_SCALES.perOctave))).toBe(row);
      expect(footprintRowOf(footprintRowScale(row) * 2 ** (0.6 / FOOTPRINT_SCALES.perOctave))).toBe(row + 1);
    }
  });
});
