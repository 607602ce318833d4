import { describe, it, expect } from 'vitest';
import { integrateAdaptive } from '../../../src/math/quadrature.js';
import { stripIntegral, radialProfile } from '../../../src/profiles/radialProfile.js';
import { gaussianSumProfile } from '../../../src/profiles/gaussianSum.js';
import { burleyProfile } from '../../../src/profiles/burley.js';
import { dipoleProfile } from '../../../src/profiles/dipole.js';
import {
  profiles, getProfile, transmittance, DEON_SKIN_GAUSSIANS, MARBLE_GAUSSIANS, SKIN_BURLEY_SCATTER_DISTANCE_MM, WHOLE_MILK_COEFFICIENTS,
} from '../../../src/profiles/presets.js';

const NAMES = ['skin', 'skinBurley', 'marble', 'milk'];

/**
 * Independent quadrature for the tests: ∫_0^∞ f(x) dx with x = e^t and the trapezoid rule in t, which
 * converges exponentially for integrands smooth in log x that vanish at both ends (here x·f → 0 as x → 0
 * and f decays exponentially); t from ln(1e-12) to ln(2000).
 */
function logTrapezoid(f, { tMin = Math.log(1e-12), tMax = Math.log(2000), h = 0.005 } = {}) {
  const out = [0, 0, 0];
  const n = Math.ceil((tMax - tMin) / h);
  const step = (tMax - tMin) / n;
  for (let k = 0; k <= n; k++) {
    const x = Math.exp(tMin + k * step);
    const v = f(x);
    const w = (k === 0 || k === n ? 0.5 : 1) * step * x;
    for (let c = 0; c < 3; c++) out[c] += w * v[c];
  }
  return out;
}

const relErr = (a, b) => Math.abs(a - b) / Math.abs(b);

describe.each(NAMES)('profile %s', (name) => {
  const p = profiles[name];

  it('R integrates to 1 over the plane', () => {
    const total = logTrapezoid((r) => p.R(r).map((v) => 2 * Math.PI * r * v));
    total.forEach((v) => expect(Math.abs(v - 1)).toBeLessThan(1e-4));
  });

  it('marginal integrates to 1', () => {
    const total = logTrapezoid((x) => p.marginal(x).map((v) => 2 * v));
    total.forEach((v) => expect(Math.abs(v - 1)).toBeLessThan(1e-4));
  });

  it('marginal(x) equals the numeric ∫ R(√(x²+y²)) dy', () => {
    for (const x of [0.003, 0.05, 0.4, 1.5, 4]) {
      const numeric = logTrapezoid((y) => p.R(Math.hypot(x, y)).map((v) => 2 * v), { tMin: Math.log(1e-14) });
      const closed = p.marginal(x);
      closed.forEach((v, c) => {
        if (numeric[c] > 1e-200) expect(relErr(v, numeric[c])).toBeLessThan(1e-5);
      });
    }
  });

  it('marginalIntegral: whole line 1, half line 1/2, additive, equals ∫ marginal', () => {
    p.marginalIntegral(-Infinity, Infinity).forEach((v) => expect(Math.abs(v - 1)).toBeLessThan(1e-9));
    p.marginalIntegral(0, Infinity).forEach((v) => expect(Math.abs(v - 0.5)).toBeLessThan(1e-9));
    p.marginalIntegral(-Infinity, 0).forEach((v) => expect(Math.abs(v - 0.5)).toBeLessThan(1e-9));
    const ab = p.marginalIntegral(-0.7, 0.2);
    const bc = p.marginalIntegral(0.2, 1.9);
    const ac = p.marginalIntegral(-0.7, 1.9);
    ac.forEach((v, c) => expect(Math.abs(ab[c] + bc[c] - v)).toBeLessThan(1e-10));
    // reversed bounds give the negative
    p.marginalIntegral(1.9, 0.2).forEach((v, c) => expect(v).toBeCloseTo(-bc[c], 12));
    // against the marginal integrated on its own (the strip [0.3, 1.1] avoids Burley's log singularity at 0)
    const num = integrateAdaptive((x) => p.marginal(x), 0.3, 1.1);
    p.marginalIntegral(0.3, 1.1).forEach((v, c) => expect(relErr(v, num[c])).toBeLessThan(1e-8));
  });

  it('transmittance(0) = 1, decreasing, equals the energy outside radius d, cdf = 1 − T', () => {
    p.transmittance(0).forEach((v) => expect(v).toBeCloseTo(1, 14));
    let previous = [1, 1, 1];
    for (const d of [0.01, 0.1, 0.3, 1, 2, 5, 10]) {
      const t = p.transmittance(d);
      t.forEach((v, c) => expect(v).toBeLessThanOrEqual(previous[c]));
      previous = t;
      const outside = logTrapezoid((r) => p.R(d + r).map((v) => 2 * Math.PI * (d + r) * v), { tMin: Math.log(1e-14) });
      t.forEach((v, c) => {
        if (v > 1e-100) expect(relErr(outside[c], v)).toBeLessThan(1e-6);
      });
      p.cdf(d).forEach((v, c) => expect(Math.abs(v + t[c] - 1)).toBeLessThan(1e-14));
    }
    expect(p.transmittance(0.3).every((v, c) => v < p.transmittance(0.1)[c])).toBe(true);
  });

  it('radiusMm(f) holds the fraction f of the energy', () => {
    for (const f of [0.5, 0.9, 0.997]) {
      const r = p.radiusMm(f);
      r.forEach((rc, c) => expect(p.cdf(rc)[c]).toBeCloseTo(f, 10));
    }
    expect(() => p.radiusMm(1)).toThrow(RangeError);
    expect(() => p.radiusMm(0)).toThrow(/fraction/);
  });

  it('generic strip integral of R agrees with marginalIntegral (rel. 1e-7), far tails and narrow strips included', () => {
    const strips = [
      [-Infinity, Infinity],
      [-1, 2],
      [-0.3, 0.3],
      [0.5, 0.6],
      [0.001, 0.0011],
      [3, Infinity],
      [-Infinity, -6],
      [-2, -1],
      [5, 5.01],
    ];
    for (const [a, b] of strips) {
      const generic = stripIntegral(p.R, a, b, { lengthScaleMm: p.lengthScaleMm });
      const exact = p.marginalIntegral(a, b);
      exact.forEach((v, c) => {
        if (v > 1e-200) expect(relErr(generic[c], v)).toBeLessThan(1e-7);
      });
    }
  });

  it('strip energies of the tail agree with the independent form (1/π) ∫_0^{π/2} T(x / cos θ) dθ', () => {
    // the half plane x > x0 seen from the origin: the ray at angle θ leaves the disk of radius x0/cos θ
    for (const x0 of [0, 0.01, 0.2, 1, 3, 8]) {
      const polar = integrateAdaptive((t) => p.transmittance(x0 / Math.cos(t)), 0, Math.PI / 2).map((v) => v / Math.PI);
      const strip = p.marginalIntegral(x0, Infinity);
      strip.forEach((v, c) => {
        if (polar[c] > 1e-200) expect(relErr(v, polar[c])).toBeLessThan(1e-7);
      });
    }
  });
});

describe('skin (d\'Eon & Luebke)', () => {
  it('has the six published Gaussians, each channel summing to 1', () => {
    expect(DEON_SKIN_GAUSSIANS.map((g) => g.varianceMm2)).toEqual([0.0064, 0.0484, 0.187, 0.567, 1.99, 7.41]);
    for (let c = 0; c < 3; c++) expect(DEON_SKIN_GAUSSIANS.reduce((s, g) => s + g.weights[c], 0)).toBeCloseTo(1, 12);
    expect(profiles.skin.gaussians.length).toBe(6);
  });
  it('red scatters furthest and blue least; significant radius about 16 mm', () => {
    const r = profiles.skin.radiusMm(0.997);
    expect(r[0]).toBeGreaterThan(r[1]);
    expect(r[1]).toBeGreaterThan(r[2]);
    // 2 × the 99.99 % radius of the widest channel is the "significant" diameter
    expect(profiles.skin.radiusMm(0.9999)[0] * 2).toBeGreaterThan(12);
    expect(profiles.skin.radiusMm(0.9999)[0] * 2).toBeLessThan(20);
  });
  it('the generic numerical profile built from R alone matches the closed forms', () => {
    const skin = profiles.skin;
    const generic = radialProfile({ name: 'genericSkin', R: skin.R, lengthScaleMm: skin.lengthScaleMm });
    for (const x of [0, 0.02, 0.3, 2]) generic.marginal(x).forEach((v, c) => expect(relErr(v, skin.marginal(x)[c])).toBeLessThan(1e-8));
    for (const d of [0, 0.2, 1.5]) generic.transmittance(d).forEach((v, c) => expect(relErr(v, skin.transmittance(d)[c])).toBeLessThan(1e-8));
    generic.radiusMm(0.9).forEach((v, c) => expect(relErr(v, skin.radiusMm(0.9)[c])).toBeLessThan(1e-7));
    generic.marginalIntegral(-0.4, 1.3).forEach((v, c) => expect(relErr(v, skin.marginalIntegral(-0.4, 1.3)[c])).toBeLessThan(1e-8));
  });
});

describe('marble', () => {
  it('pairs the four variances with the four non-zero weight rows, renormalised per channel', () => {
    expect(MARBLE_GAUSSIANS.map((g) => g.varianceMm2)).toEqual([0.0362, 0.1145, 0.4556, 3.4833]);
    const gs = profiles.marble.gaussians;
    for (let c = 0; c < 3; c++) {
      expect(Math.abs(gs.reduce((s, g) => s + g.weights[c], 0) - 1)).toBeLessThan(1e-15);
      const published = MARBLE_GAUSSIANS.reduce((s, g) => s + g.weights[c], 0);
      gs.forEach((g, i) => expect(g.weights[c]).toBeCloseTo(MARBLE_GAUSSIANS[i].weights[c] / published, 15));
    }
  });
});

describe('Burley', () => {
  it('radiusMm(0.997) = 16.56 × scatter distance (r = 16.56 / s, s = 1/l)', () => {
    const p = burleyProfile({ scatterDistanceMm: [1, 0.5, 0.1] });
    const r = p.radiusMm(0.997);
    [1, 0.5, 0.1].forEach((l, c) => expect(r[c] / l).toBeCloseTo(16.56, 2));
  });
  it('closed-form inverse round-trips with the CDF 1 − e^{−sr}/4 − 3e^{−sr/3}/4', () => {
    const l = 0.7;
    const p = burleyProfile({ scatterDistanceMm: [l, l, l] });
    for (const f of [1e-6, 0.1, 0.5, 0.9, 0.997, 0.999999]) {
      const r = p.radiusMm(f)[0];
      const cdf = 1 - Math.exp(-r / l) / 4 - (3 * Math.exp(-r / (3 * l))) / 4;
      expect(Math.abs(cdf - f)).toBeLessThan(1e-12);
    }
  });
  it('transmittance is (e^{−d/l} + 3e^{−d/3l})/4', () => {
    const p = burleyProfile({ scatterDistanceMm: [2, 1, 0.5] });
    [2, 1, 0.5].forEach((l, c) => expect(p.transmittance(1.3)[c]).toBeCloseTo((Math.exp(-1.3 / l) + 3 * Math.exp(-1.3 / (3 * l))) / 4, 15));
  });
  it('albedo fits: s = 1.85 − A + 7|A − 0.8|³ (searchlight), 1.9 − A + 3.5(A − 0.8)² (diffuse), l = mfp / s', () => {
    const A = [0.8, 0.5, 0.2];
    const s1 = A.map((a) => 1.85 - a + 7 * Math.abs(a - 0.8) ** 3);
    const s2 = A.map((a) => 1.9 - a + 3.5 * (a - 0.8) ** 2);
    const p1 = burleyProfile({ albedo: A, meanFreePathMm: 2, fit: 'searchlight' });
    const p2 = burleyProfile({ albedo: A, meanFreePathMm: [2, 2, 2], fit: 'diffuse' });
    p1.scatterDistanceMm.forEach((l, c) => expect(l).toBeCloseTo(2 / s1[c], 14));
    p2.scatterDistanceMm.forEach((l, c) => expect(l).toBeCloseTo(2 / s2[c], 14));
    expect(p1.scatterDistanceMm[0]).toBeCloseTo(2 / 1.05, 14);
    expect(() => burleyProfile({ albedo: A, meanFreePathMm: 1, fit: 'other' })).toThrow(/fit must be one of/);
    expect(() => burleyProfile({ albedo: [1.2, 0, 0], meanFreePathMm: 1 })).toThrow(/albedo\[0\]/);
  });
  it('skinBurley matches skin\'s 99.7 % radius per channel, with the stated scatter distances', () => {
    const k = burleyProfile({ scatterDistanceMm: [1, 1, 1] }).radiusMm(0.997)[0];
    const skinR = profiles.skin.radiusMm(0.997);
    skinR.forEach((r, c) => expect(relErr(SKIN_BURLEY_SCATTER_DISTANCE_MM[c], r / k)).toBeLessThan(1e-4));
    profiles.skinBurley.radiusMm(0.997).forEach((r, c) => expect(relErr(r, skinR[c])).toBeLessThan(1e-4));
  });
  it('marginal is infinite at 0 (log singularity) and finite elsewhere', () => {
    expect(profiles.skinBurley.marginal(0)[0]).toBe(Infinity);
    expect(Number.isFinite(profiles.skinBurley.marginal(1e-9)[0])).toBe(true);
  });
});

describe('dipole (Jensen et al. 2001)', () => {
  it('milk uses the published whole-milk coefficients', () => {
    expect(WHOLE_MILK_COEFFICIENTS.sigmaSPrimeMm).toEqual([2.55, 3.21, 3.77]);
    expect(WHOLE_MILK_COEFFICIENTS.sigmaAMm).toEqual([0.0011, 0.0024, 0.014]);
    expect(WHOLE_MILK_COEFFICIENTS.eta).toBe(1.3);
  });
  it('is Jensen\'s R_d(r) up to a per-channel constant equal to its numerically integrated energy', () => {
    const sigmaS = [1.2, 0.8, 2.5];
    const sigmaA = [0.03, 0.2, 0.05];
    const eta = 1.4;
    const p = dipoleProfile({ sigmaSPrimeMm: sigmaS, sigmaAMm: sigmaA, eta });
    const Fdr = -1.44 / eta ** 2 + 0.71 / eta + 0.668 + 0.0636 * eta;
    const A = (1 + Fdr) / (1 - Fdr);
    const raw = (r) =>
      [0, 1, 2].map((c) => {
        const st = sigmaA[c] + sigmaS[c];
        const alpha = sigmaS[c] / st;
        const str = Math.sqrt(3 * sigmaA[c] * st);
        const zr = 1 / st;
        const zv = zr * (1 + (4 / 3) * A);
        const dr = Math.hypot(r, zr);
        const dv = Math.hypot(r, zv);
        return (alpha / (4 * Math.PI)) * ((zr * (str * dr + 1) * Math.exp(-str * dr)) / dr ** 3 + (zv * (str * dv + 1) * Math.exp(-str * dv)) / dv ** 3);
      });
    const energy = logTrapezoid((r) => raw(r).map((v) => 2 * Math.PI * r * v));
    for (const r of [0, 0.1, 1, 5]) raw(r).forEach((v, c) => expect(relErr(v / p.R(r)[c], energy[c])).toBeLessThan(1e-6));
  });
  it('rejects bad coefficients', () => {
    expect(() => dipoleProfile({ sigmaSPrimeMm: [1, 1], sigmaAMm: [1, 1, 1], eta: 1.3 })).toThrow(/sigmaSPrimeMm/);
    expect(() => dipoleProfile({ sigmaSPrimeMm: [1, 1, 1], sigmaAMm: [0, 1, 1], eta: 1.3 })).toThrow(/sigmaAMm\[0\]/);
  });
});

describe('reference transmittance (Jimenez 2010, REFERENCE §5)', () => {
  it('matches the published values at s = 0.5, 1, 2 mm within rounding', () => {
    const expected = [
      [0.5, [0.495, 0.062, 0.0065]],
      [1, [0.305, 0.0046, 0.0012]],
      [2, [0.094, 0.0005, 0]],
    ];
    for (const [s, rgb] of expected) {
      const t = transmittance(s);
      rgb.forEach((v, c) => {
        const decimals = String(v).includes('.') ? String(v).split('.')[1].length : 0;
        const halfUnit = v === 0 ? 5e-5 : 0.5 * 10 ** -decimals;
        expect(Math.abs(t[c] - v)).toBeLessThanOrEqual(halfUnit + 1e-12);
      });
    }
  });
  it('equals the exact profile transmittance at √2 times the thickness', () => {
    for (const s of [0.1, 0.5, 1, 3]) {
      transmittance(s).forEach((v, c) => expect(v).toBeCloseTo(profiles.skin.transmittance(Math.SQRT2 * s)[c], 14));
    }
    expect(() => transmittance(-1)).toThrow(/sMm/);
  });
});

describe('getProfile', () => {
  it('resolves names and passes profile objects through', () => {
    for (const n of NAMES) expect(getProfile(n)).toBe(profiles[n]);
    const custom = gaussianSumProfile('one', [{ varianceMm2: 1, weights: [1, 1, 1] }]);
    expect(getProfile(custom)).toBe(custom);
  });
  it('throws TypeError naming the accepted names', () => {
    for (const bad of ['Skin', 'ketchup', 42, null, undefined, {}]) {
      expect(() => getProfile(bad)).toThrow(TypeError);
      expect(() => getProfile(bad)).toThrow(/'skin', 'skinBurley', 'marble', 'milk'/);
    }
  });
});
