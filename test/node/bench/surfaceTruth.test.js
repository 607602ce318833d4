// The bench's surface-space truth (bench/surfaceTruth/scatter.js) against closed forms: a step of
// light on a plane (each Gaussian's share beyond the line: erfc), on lattices of different and
// overlapping spacings, and uniform light on a sphere.
import { describe, it, expect } from 'vitest';
import { surfaceTruth, levelsOf, coarsen, SUMMED_SIGMA_PER_SPACING } from '../../../bench/surfaceTruth/scatter.js';
import { GAUSSIANS, erfc } from '../../oracle/closedForms.js';

const SKIN = GAUSSIANS.skin;

function plane(spacingMm, halfMm, lightAt) {
  const n = Math.round((2 * halfMm) / spacingMm);
  const positionMm = new Float64Array(3 * n * n);
  const light = new Float64Array(3 * n * n);
  const areaMm2 = new Float64Array(n * n).fill(spacingMm * spacingMm);
  const texel = Uint32Array.from({ length: n * n }, (_, k) => k);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const k = j * n + i;
    const x = -halfMm + (i + 0.5) * spacingMm;
    positionMm.set([x, -halfMm + (j + 0.5) * spacingMm, 0], 3 * k);
    light.fill(lightAt(x), 3 * k, 3 * k + 3);
  }
  return { positionMm, areaMm2, light, texel, size: n };
}

describe('surface truth', () => {
  it('a step of light on a plane: within 3e-3 of the closed form, off the samples\' lattice too (a discontinuity is the lattice sum\'s worst case: its error is first order in the spacing)', () => {
    const spacing = 0.2;
    const step = (x) => (x < 0 ? 1 : 0);
    const samples = plane(spacing, 20, step);
    const xs = [-3, -1, -0.31, -0.07, 0.13, 0.5, 1.7, 4];
    const queryMm = Float64Array.from(xs.flatMap((x) => [x, 0.037, 0]));
    const queryLight = Float64Array.from(xs.flatMap((x) => [step(x), step(x), step(x)]));
    const truth = surfaceTruth({ levels: [samples], queryMm, queryLight, gaussians: SKIN });
    expect(levelsOf(SKIN, [spacing])).toEqual([-1, 0, 0, 0, 0, 0]); // all but the narrowest (σ 0.08 mm < 0.6 × 0.2 mm)
    expect(truth.localShare).toEqual([1, 0, 0, 0, 0, 0]);
    const local = SKIN[0][1];
    xs.forEach((x, q) => {
      for (let c = 0; c < 3; c++) {
        const expected = SKIN.reduce((s, [v, w]) => s + (Math.sqrt(v) >= SUMMED_SIGMA_PER_SPACING * spacing ? w[c] * erfc(x / Math.sqrt(2 * v)) / 2 : 0), local[c] * step(x));
        expect(Math.abs(truth.light[3 * q + c] - expected), `x ${x} mm, channel ${c}`).toBeLessThan(3e-3);
      }
    });
  });

  it('wide Gaussians summed over the atlas merged 4 × 4 give the same step within 3e-3, and the merge keeps light and area', () => {
    const step = (x) => (x < 0 ? 1 : 0);
    const fine = plane(0.2, 20, step);
    const coarse = coarsen(fine, fine.size);
    const sum = (a) => a.reduce((s, x) => s + x, 0);
    expect(coarse.areaMm2.length).toBe(fine.areaMm2.length / 16);
    expect(sum(coarse.areaMm2)).toBeCloseTo(sum(fine.areaMm2), 6);
    expect(sum(coarse.light.filter((_, i) => i % 3 === 0).map((e, n) => e * coarse.areaMm2[n]))).toBeCloseTo(sum(fine.light.filter((_, i) => i % 3 === 0).map((e, n) => e * fine.areaMm2[n])), 6);
    const xs = [-2, -0.45, 0.2, 1.3];
    const queryMm = Float64Array.from(xs.flatMap((x) => [x, 0.11, 0]));
    const queryLight = Float64Array.from(xs.flatMap((x) => [step(x), step(x), step(x)]));
    const one = surfaceTruth({ levels: [fine], queryMm, queryLight, gaussians: SKIN });
    const two = surfaceTruth({ levels: [fine, coarse], queryMm, queryLight, gaussians: SKIN });
    expect(levelsOf(SKIN, [0.2, 0.8])).toEqual([-1, 0, 0, 1, 1, 1]); // σ ≥ 0.6 × 0.8 mm: the three widest
    for (let i = 0; i < one.light.length; i++) expect(Math.abs(two.light[i] - one.light[i])).toBeLessThan(3e-3);
  });

  it('where the samples are sparser (half the plane at 0.5 mm, half at 0.1 mm) uniform light stays uniform within 2e-3: each point chooses by the spacing around it', () => {
    const dense = plane(0.1, 20, () => 1); // 20 mm from the edges: the widest Gaussian (2.7 mm) sees none
    const sparse = plane(0.5, 20, () => 1);
    const keep = (set, side) => {
      const take = [];
      for (let k = 0; k < set.areaMm2.length; k++) if (side(set.positionMm[3 * k])) take.push(k);
      return {
        positionMm: Float64Array.from(take.flatMap((k) => [...set.positionMm.subarray(3 * k, 3 * k + 3)])),
        areaMm2: Float64Array.from(take.map((k) => set.areaMm2[k])),
        light: new Float64Array(3 * take.length).fill(1),
      };
    };
    const a = keep(dense, (x) => x < 0);
    const b = keep(sparse, (x) => x >= 0);
    const samples = {
      positionMm: Float64Array.from([...a.positionMm, ...b.positionMm]),
      areaMm2: Float64Array.from([...a.areaMm2, ...b.areaMm2]),
      light: Float64Array.from([...a.light, ...b.light]),
    };
    const xs = [-5, -2, 2.13, 3.37, 5.05, 6.81];
    const queryMm = Float64Array.from(xs.flatMap((x) => [x, 0.21 * x, 0]));
    const truth = surfaceTruth({ levels: [samples], queryMm, queryLight: new Float64Array(3 * xs.length).fill(1), gaussians: SKIN });
    for (let i = 0; i < truth.light.length; i++) expect(Math.abs(truth.light[i] - 1), `point ${Math.floor(i / 3)}`).toBeLessThan(2e-3);
    // With the whole set's spacing (the median, 0.1 mm) σ 0.22 mm would be summed over 0.5 mm samples too: off by several %.
    expect(levelsOf(SKIN, [0.5])).toEqual([-1, -1, 0, 0, 0, 0]);
  });

  it('a merge keeps texels of another uv island apart (two sheets 50 mm apart side by side in the atlas)', () => {
    const sheet = plane(0.25, 2.25, () => 1); // 18 × 18 texels: the atlas block of columns 16-19 holds both islands
    const n = sheet.size;
    const size = 2 * n;
    const positionMm = new Float64Array(2 * sheet.positionMm.length);
    const texel = new Uint32Array(2 * n * n);
    for (let k = 0; k < n * n; k++) {
      const [i, j] = [k % n, Math.floor(k / n)];
      positionMm.set(sheet.positionMm.subarray(3 * k, 3 * k + 3), 3 * k);
      positionMm.set([sheet.positionMm[3 * k] + 50, sheet.positionMm[3 * k + 1], 0], 3 * (n * n + k));
      texel[k] = j * size + i;
      texel[n * n + k] = j * size + i + n;
    }
    const samples = { positionMm, texel, areaMm2: new Float64Array(2 * n * n).fill(0.0625), light: new Float64Array(6 * n * n).fill(1) };
    const merged = coarsen(samples, size);
    const xs = Array.from(merged.positionMm.filter((_, i) => i % 3 === 0));
    expect(xs.every((x) => x < 2.5 || x > 47.5)).toBe(true); // no sample between the sheets
    expect(merged.areaMm2.length).toBeGreaterThan((2 * n * n) / 16); // the shared blocks split in two
  });

  it('where two uv islands overlap or part by half a texel (as rasterised borders do), a step of light stays within 0.015 of the closed form, though the samples\' own weight Σ G A is off by more than 10 % there (summed without dividing by it: 0.08)', () => {
    const spacing = 0.2;
    const step = (x) => (x < 0.5 ? 1 : 0); // the seam at x = 0 lies in the light
    for (const shift of [spacing / 2, -spacing / 2]) {
      // Left island: texel centres at x = −0.1, −0.3, …; right island: at x = 0.1 − shift, 0.3 − shift, ….
      const sheet = plane(spacing, 20, step);
      const ks = [...sheet.areaMm2.keys()];
      const positionMm = Float64Array.from(ks.flatMap((k) => {
        const [x, y, z] = sheet.positionMm.subarray(3 * k, 3 * k + 3);
        return [x > 0 ? x - shift : x, y, z];
      }));
      const light = Float64Array.from(ks.flatMap((k) => new Array(3).fill(step(positionMm[3 * k]))));
      const samples = { positionMm, areaMm2: sheet.areaMm2, light };
      const [v1] = SKIN[1];
      const ownWeight = (x) => samples.areaMm2.reduce((sum, area, k) => {
        const d2 = (positionMm[3 * k] - x) ** 2 + (positionMm[3 * k + 1] - 0.05) ** 2;
        return sum + (area * Math.exp(-d2 / (2 * v1))) / (2 * Math.PI * v1);
      }, 0);
      expect(Math.abs(ownWeight(0) - 1)).toBeGreaterThan(0.1);
      const xs = [-0.8, -0.3, -0.05, 0.1, 0.4, 0.9, 1.6];
      const queryMm = Float64Array.from(xs.flatMap((x) => [x, 0.05, 0]));
      const queryLight = Float64Array.from(xs.flatMap((x) => [step(x), step(x), step(x)]));
      const truth = surfaceTruth({ levels: [samples], queryMm, queryLight, gaussians: SKIN });
      const local = SKIN[0][1];
      xs.forEach((x, q) => {
        for (let c = 0; c < 3; c++) {
          const expected = SKIN.reduce((sum, [v, w], m) => sum + (m > 0 ? w[c] * erfc((x - 0.5) / Math.sqrt(2 * v)) / 2 : 0), local[c] * step(x));
          expect(Math.abs(truth.light[3 * q + c] - expected), `shift ${shift}, x ${x} mm, channel ${c}`).toBeLessThan(0.015);
        }
      });
    }
  });

  it('uniform light on a sphere of radius 3 mm stays uniform (1 within 1e-9): each Gaussian is divided by its own weight over the samples', () => {
    const rho = 3;
    // A Fibonacci lattice: equal areas, locally near-regular (spacing about 0.075 mm).
    const n = 20000;
    const positions = [];
    const areas = new Array(n).fill((4 * Math.PI * rho * rho) / n);
    for (let i = 0; i < n; i++) {
      const z = 1 - (2 * (i + 0.5)) / n;
      const phi = i * Math.PI * (3 - Math.sqrt(5));
      const r = Math.sqrt(1 - z * z);
      positions.push(rho * r * Math.cos(phi), rho * r * Math.sin(phi), rho * z);
    }
    const samples = { positionMm: Float64Array.from(positions), areaMm2: Float64Array.from(areas), light: new Float64Array(positions.length).fill(1) };
    const queryMm = Float64Array.from([0, 0, rho, rho, 0, 0, 0, -rho * Math.SQRT1_2, rho * Math.SQRT1_2]);
    const truth = surfaceTruth({ levels: [samples], queryMm, queryLight: new Float64Array(9).fill(1), gaussians: SKIN });
    for (let i = 0; i < 9; i++) expect(Math.abs(truth.light[i] - 1)).toBeLessThan(1e-9);
  });

  it('widthMm scales the profile: at width 2 a step reads as the width-1 step at half the distance', () => {
    const samples = plane(0.2, 30, (x) => (x < 0 ? 1 : 0));
    const at = (x, widthMm) => surfaceTruth({ levels: [samples], queryMm: Float64Array.from([x, 0, 0]), queryLight: Float64Array.from([0, 0, 0]), gaussians: SKIN, widthMm }).light[0];
    expect(Math.abs(at(1.0, 2) - at(0.5, 1))).toBeLessThan(2e-3);
  });
});
