// Resolution by need, in Node (src/3-blur/resolutionPlan.js): the error a level adds, held against a
// brute-force float64 simulation of the pipeline's resampling written here; which Gaussians go to
// which level; the parts' tables summing to the profile's.
import { describe, it, expect } from 'vitest';
import { erf } from '../../../src/math/specialFunctions.js';
import {
  LEVEL_GAIN, LEVEL_SHARE_STEPS, LEVEL_STEP_ERROR, LEVEL_VARIANCE, MAX_LEVEL, RESOLUTIONS, levelNarrowing, levelShares, levelStepError,
  minSigmaPx, partMarginalRow, partVarianceMm2, planLevels, rowRadiusMm, spanGaussians, splitScale,
} from '../../../src/3-blur/resolutionPlan.js';
import { PLAN_RAMP } from '../../../src/3-blur/planRamp.js';
import { frameLevels } from '../../../src/3-blur/blurPlan.js';
import { gaussianSumOf } from '../../../src/profiles/gaussianFit.js';
import { ProfileLookup } from '../../../src/profiles/ProfileLookup.js';
import { profiles } from '../../../src/profiles/presets.js';

const Phi = (x) => 0.5 * (1 + erf(x / Math.SQRT2));

/**
 * The oracle: a step edge in an image of `n` pixels blurred by a Gaussian of `sigma` pixels at full
 * resolution (every pixel weighed by the Gaussian's energy over it) and at a level of blocks of `s`
 * pixels: averaged per block, blurred at the block scale by a Gaussian narrowed by `variance`
 * blocks² (every block weighed by the energy over it), read at each pixel's centre by bilinear
 * interpolation between the block centres (the edge blocks clamped). Arrays, sums: no closed form.
 */
function bruteForceLevelError(sigma, s, variance) {
  const n = 64 * s + Math.ceil(24 * sigma);
  let worst = 0;
  for (let edge = n / 2; edge < n / 2 + s; edge++) {
    const light = Float64Array.from({ length: n }, (_, k) => (k >= edge ? 1 : 0));
    const blocks = Float64Array.from({ length: n / s }, (_, b) => light.slice(b * s, b * s + s).reduce((a, v) => a + v, 0) / s);
    const coarseSigma = Math.sqrt(Math.max(sigma * sigma / (s * s) - variance, 0.25 * sigma * sigma / (s * s)));
    const blurred = blocks.map((_, i) => blocks.reduce((sum, v, j) => sum + v * (Phi((j - i + 0.5) / coarseSigma) - Phi((j - i - 0.5) / coarseSigma)), 0));
    for (let k = n / 2 - 6 * sigma - 2 * s; k < n / 2 + 6 * sigma + 3 * s; k++) {
      let exact = 0;
      for (let j = 0; j < n; j++) exact += light[j] * (Phi((j - k + 0.5) / sigma) - Phi((j - k - 0.5) / sigma));
      const u = (k + 0.5) / s - 0.5;
      const below = Math.floor(u);
      const f = u - below;
      const at = (i) => blurred[Math.min(Math.max(i, 0), blocks.length - 1)];
      worst = Math.max(worst, Math.abs((1 - f) * at(below) + f * at(below + 1) - exact));
    }
  }
  return worst;
}

describe('levelStepError', () => {
  it('is the brute-force simulation of the downsample, the narrowed coarse blur and the bilinear upsample', () => {
    for (const level of [1, 2]) {
      for (const sigma of [3, 6, 12]) {
        expect(levelStepError(sigma, level), `σ ${sigma}, level ${level}`).toBeCloseTo(bruteForceLevelError(sigma, 2 ** level, LEVEL_VARIANCE), 6);
      }
    }
    expect(levelStepError(0.5, 0)).toBe(0);
  });

  it('narrowing by LEVEL_VARIANCE at least halves the error of the plain resampling', () => {
    for (const level of [1, 2]) {
      for (const sigma of [8, 16]) expect(levelStepError(sigma, level)).toBeLessThan(0.5 * bruteForceLevelError(sigma, 2 ** level, 0));
    }
  });

  it('falls as σ grows from half the narrowest within the bound, so minSigmaPx is that narrowest', () => {
    for (const level of [1, 2]) {
      let previous = Infinity;
      for (let sigma = minSigmaPx(level) / 2; sigma < 64; sigma *= 1.1) {
        const error = levelStepError(sigma, level);
        expect(error).toBeLessThan(previous);
        previous = error;
      }
      const narrowest = minSigmaPx(level);
      expect(levelStepError(narrowest, level)).toBeLessThanOrEqual(LEVEL_STEP_ERROR);
      expect(levelStepError(narrowest * 0.99, level)).toBeGreaterThan(LEVEL_STEP_ERROR);
    }
    expect(minSigmaPx(2)).toBeGreaterThan(minSigmaPx(1) * PLAN_RAMP); // the level ramps do not overlap
  });

  it('levelNarrowing takes LEVEL_VARIANCE pixels² off the variance, and at most halves the width', () => {
    const narrowed = levelNarrowing(0.5, 4); // σ = √0.5 mm at 4 px/mm: 8 pixels²
    expect((0.5 * 16) * narrowed ** 2).toBeCloseTo(8 - LEVEL_VARIANCE, 12);
    expect(levelNarrowing(1e-6, 1)).toBe(0.5);
  });
});

describe('levelShares', () => {
  it('all at full resolution below the first level\'s narrowest Gaussian; then moving over PLAN_RAMP of scale', () => {
    expect(levelShares(minSigmaPx(1) * 0.999)).toEqual([1, 0, 0]);
    expect(levelShares(minSigmaPx(1) * Math.sqrt(PLAN_RAMP))[1]).toBeCloseTo(0.5, 9);
    expect(levelShares(minSigmaPx(1) * PLAN_RAMP)).toEqual([0, 1, 0]);
    expect(levelShares(minSigmaPx(2) * PLAN_RAMP)).toEqual([0, 0, 1]);
    expect(levelShares(minSigmaPx(2) * 4, 1)).toEqual([0, 1, 0]); // a level cap
  });

  it('sum to 1 and change continuously with σ', () => {
    let previous = levelShares(1);
    for (let sigma = 1; sigma < 40; sigma *= 1.001) {
      const shares = levelShares(sigma);
      expect(shares.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 12);
      shares.forEach((share, level) => expect(Math.abs(share - previous[level])).toBeLessThan(0.01));
      previous = shares;
    }
  });
});

describe('planLevels', () => {
  const sigmasPx = (profile, pixelsPerMm) => gaussianSumOf(profile).gaussians.map((g) => Math.sqrt(g.varianceMm2) * pixelsPerMm);

  it('far: the whole profile at full resolution (null, the one-kernel blur as without levels)', () => {
    for (const name of ['skin', 'skinBurley', 'marble']) expect(planLevels(profiles[name], 1, 'auto'), name).toBe(null);
    expect(planLevels(profiles.skin, 20, 1)).toBe(null);
  });

  it("'auto': every Gaussian sent to a level holds the bound there, and shares sum to 1 per Gaussian", () => {
    for (const name of ['skin', 'skinBurley', 'marble', 'milk']) {
      for (const pixelsPerMm of [2, 4, 6, 9, 14, 20, 40]) {
        const plan = planLevels(profiles[name], pixelsPerMm, 'auto');
        if (!plan) continue;
        const sigmas = sigmasPx(profiles[name], pixelsPerMm);
        for (const part of plan.parts) {
          part.members.forEach((m, i) => { if (m > 0 && part.level > 0) expect(levelStepError(sigmas[i], part.level), `${name} ${pixelsPerMm} px/mm, Gaussian ${i} at level ${part.level}`).toBeLessThanOrEqual(LEVEL_STEP_ERROR); });
        }
        plan.gaussians.forEach((_, i) => expect(plan.parts.reduce((sum, part) => sum + part.members[i], 0)).toBeCloseTo(1, 12));
        // Wider Gaussians are never at a finer level than narrower ones.
        const levelOf = plan.gaussians.map((_, i) => plan.parts.reduce((sum, part) => sum + part.level * part.members[i], 0));
        for (let i = 1; i < levelOf.length; i++) expect(levelOf[i]).toBeGreaterThanOrEqual(levelOf[i - 1] - 1e-12);
      }
    }
  });

  it("'auto' splits from splitScale, where the full-resolution part reaches LEVEL_GAIN less far, fading in over PLAN_RAMP", () => {
    for (const name of ['skin', 'skinBurley', 'marble']) {
      const scale = splitScale(profiles[name]);
      expect(planLevels(profiles[name], scale * 0.999, 'auto'), name).toBe(null);
      expect(planLevels(profiles[name], scale * PLAN_RAMP * 1.01, 'auto').parts.length, name).toBeGreaterThan(1);
    }
    const plan = planLevels(profiles.skin, 12, 'auto');
    const lookup = new ProfileLookup(profiles.skin);
    const { width, data } = lookup.texture.image;
    const whole = data.subarray(width * 4, width * 8);
    const own = plan.parts.find((part) => part.level === 0);
    const ownRadius = rowRadiusMm(partMarginalRow(plan, own, whole, lookup.marginalRangeMm), lookup.marginalRangeMm);
    expect(1 - ownRadius / lookup.marginalRadiusMm).toBeGreaterThan(LEVEL_GAIN);
    expect(plan.parts.map((part) => part.level)).toEqual([0, 1, 2]);
    lookup.dispose();
  });

  it("'auto' changes by at most two share steps (one per coarse level) and two ramps' slopes between scales a thousandth apart: no jump", () => {
    for (const name of ['skin', 'skinBurley']) {
      let previous = null;
      for (let x = 1; x < 30; x *= 1.001) {
        const plan = planLevels(profiles[name], x, 'auto');
        const shares = gaussianSumOf(profiles[name]).gaussians.map((_, i) => Array.from({ length: MAX_LEVEL + 1 }, (__, level) => plan?.parts.find((p) => p.level === level)?.members[i] ?? (level === 0 ? 1 : 0)));
        if (previous) shares.forEach((levels, i) => levels.forEach((share, level) => expect(Math.abs(share - previous[i][level]), `${name} at ${x.toFixed(3)} px/mm`).toBeLessThanOrEqual(2 / LEVEL_SHARE_STEPS + 2 * Math.log(1.001) / Math.log(PLAN_RAMP) + 1e-12)));
        previous = shares;
      }
    }
  });

  it('a fixed resolution: the whole profile at its level, whatever the scale', () => {
    for (const [resolution, level] of [[0.5, 1], [0.25, 2]]) {
      for (const pixelsPerMm of [0.5, 5, 50]) {
        const plan = planLevels(profiles.skinBurley, pixelsPerMm, resolution);
        expect(plan.parts).toHaveLength(1);
        expect(plan.parts[0]).toMatchObject({ level, whole: true });
      }
    }
    expect(RESOLUTIONS).toEqual(['auto', 1, 0.5, 0.25]);
  });
});

describe("the parts' tables", () => {
  it("the parts' G rows, each times its energy, sum to the whole profile's (exact: the full-resolution part is the rest)", () => {
    for (const name of ['skin', 'skinBurley', 'milk']) {
      const lookup = new ProfileLookup(profiles[name]);
      const { width, data } = lookup.texture.image;
      const whole = data.subarray(width * 4, width * 8);
      const plan = planLevels(profiles[name], 12, 'auto');
      const energyOf = (part) => (part.level === 0 ? [0, 1, 2].map((c) => 1 - plan.parts.reduce((sum, p) => sum + (p.level > 0 ? p.energies[c] : 0), 0)) : part.energies);
      const rows = plan.parts.map((part) => partMarginalRow(plan, part, whole, lookup.marginalRangeMm));
      for (const row of rows) {
        for (let t = 1; t < width; t++) for (let c = 0; c < 3; c++) expect(row[t * 4 + c]).toBeGreaterThanOrEqual(row[(t - 1) * 4 + c]);
        for (let c = 0; c < 3; c++) expect(row[(width - 1) * 4 + c]).toBeCloseTo(0.5, 4);
      }
      let worst = 0;
      for (let t = 0; t < width; t++) {
        for (let c = 0; c < 3; c++) {
          const sum = plan.parts.reduce((s, part, p) => s + energyOf(part)[c] * rows[p][t * 4 + c], 0);
          worst = Math.max(worst, Math.abs(sum - whole[t * 4 + c]));
        }
      }
      expect(worst, name).toBeLessThan(name === 'skin' ? 1e-6 : 2e-3); // a fit's coarse Gaussians may overshoot its tail by its error
      lookup.dispose();
    }
  });

  it("a coarse part's row is its Gaussians' closed form; a span's Gaussians are normalised per channel", () => {
    const plan = planLevels(profiles.skin, 12, 'auto');
    const coarse = plan.parts.find((part) => part.level === 2);
    const lookup = new ProfileLookup(profiles.skin);
    const { width, data } = lookup.texture.image;
    const row = partMarginalRow(plan, coarse, data.subarray(width * 4, width * 8), lookup.marginalRangeMm);
    const x = (100 / (width - 1)) ** 2 * lookup.marginalRangeMm;
    const red = plan.gaussians.reduce((sum, g, i) => sum + coarse.members[i] * g.weights[0] * 0.5 * erf(x / Math.sqrt(2 * g.varianceMm2)), 0) / coarse.energies[0];
    expect(row[100 * 4]).toBeCloseTo(red, 6);
    const span = spanGaussians(plan, coarse.span);
    for (let c = 0; c < 3; c++) expect(span.reduce((sum, g) => sum + g.weights[c], 0)).toBeCloseTo(1, 12);
    expect(partVarianceMm2(plan, coarse)).toBeCloseTo(plan.gaussians.reduce((sum, g, i) => sum + coarse.members[i] * g.weights[0] * g.varianceMm2, 0) / coarse.energies[0], 12);
    lookup.dispose();
  });
});

describe('frameLevels (the blur plan)', () => {
  const settings = { kernelGroups: 1, profiles: [profiles.skin], resolution: 'auto' };
  it('levels for one profile and one kernel; full resolution with groups, several profiles or resolution 1', () => {
    expect(frameLevels(settings, 12)).not.toBe(null);
    expect(frameLevels({ ...settings, kernelGroups: 'auto' }, 12)).toBe(null);
    expect(frameLevels({ ...settings, profiles: [profiles.skin, profiles.marble] }, 12)).toBe(null);
    expect(frameLevels({ ...settings, resolution: 1 }, 12)).toBe(null);
    expect(frameLevels({ ...settings, resolution: undefined }, 12)).toBe(null);
  });
});
