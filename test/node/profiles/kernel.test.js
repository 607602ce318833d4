import { describe, it, expect } from 'vitest';
import { computeKernel, kernelRadiusMm, referenceKernel, REFERENCE_STRENGTH } from '../../../src/profiles/kernel.js';
import { profiles, DEON_SKIN_GAUSSIANS } from '../../../src/profiles/presets.js';
import { gaussianSumProfile } from '../../../src/profiles/gaussianSum.js';
import { edgeResponse1D, kernelEdgeResponse1D } from '../../oracle/convolution.js';

const ALL_SAMPLES = Array.from({ length: 31 }, (_, i) => 3 + 2 * i); // 3..63

const taps = (kernel) =>
  Array.from({ length: kernel.length / 4 }, (_, k) => ({
    w: [kernel[4 * k], kernel[4 * k + 1], kernel[4 * k + 2]],
    offset: kernel[4 * k + 3],
  }));

function expectWellFormed(kernel, samples) {
  expect(kernel).toBeInstanceOf(Float32Array);
  expect(kernel.length).toBe(4 * samples);
  const t = taps(kernel);
  expect(t[0].offset).toBe(0);
  for (let c = 0; c < 3; c++) expect(Math.abs(t.reduce((s, tap) => s + tap.w[c], 0) - 1)).toBeLessThan(1e-6);
  const others = t.slice(1);
  for (let k = 1; k < others.length; k++) expect(others[k].offset).toBeGreaterThan(others[k - 1].offset);
  // symmetric: the k-th from the left mirrors the k-th from the right, with the same weights
  const half = (samples - 1) / 2;
  for (let k = 0; k < half; k++) {
    const left = others[k];
    const right = others[others.length - 1 - k];
    expect(left.offset).toBeCloseTo(-right.offset, 6);
    left.w.forEach((v, c) => expect(v).toBeCloseTo(right.w[c], 7));
  }
  t.forEach((tap) => tap.w.forEach((v) => expect(v).toBeGreaterThanOrEqual(0)));
}

/** Footprint boundaries of a kernel's taps: midpoints between consecutive sorted offsets. */
function midpoints(kernel) {
  const offsets = taps(kernel).map((t) => t.offset).sort((a, b) => a - b);
  return offsets.slice(1).map((o, k) => 0.5 * (o + offsets[k]));
}

describe('reference kernel (REFERENCE §3)', () => {
  it('reproduces the published 17-tap centre weight (0.536343, 0.624624, 0.748867)', () => {
    const k = referenceKernel(17);
    [0.536343, 0.624624, 0.748867].forEach((v, c) => expect(Math.abs(k[c] - v)).toBeLessThan(1e-6));
    expect(k[3]).toBe(0);
  });
  it('uses RANGE 2 up to 20 taps and RANGE 3 above, with the quadratic warp sign(t)·t²/RANGE', () => {
    expect(kernelRadiusMm(referenceKernel(17))).toBe(2);
    expect(kernelRadiusMm(referenceKernel(11))).toBe(2);
    expect(kernelRadiusMm(referenceKernel(25))).toBe(3);
    const offsets = taps(referenceKernel(17)).slice(1).map((t) => t.offset);
    const expected = Array.from({ length: 17 }, (_, i) => -2 + (i * 4) / 16)
      .filter((t) => t !== 0)
      .map((t) => (Math.sign(t) * t * t) / 2);
    offsets.forEach((o, i) => expect(o).toBeCloseTo(expected[i], 6));
  });
  it('is well formed for every size 3..63', () => {
    for (const n of ALL_SAMPLES) expectWellFormed(referenceKernel(n), n);
  });
  it('defaults to strength (0.48, 0.41, 0.28); strength 0 gives the identity, strength 1 the bare profile', () => {
    const k0 = computeKernel({ samples: 9, strength: [0, 0, 0] });
    taps(k0).forEach((t, i) => t.w.forEach((v) => expect(v).toBe(i === 0 ? 1 : 0)));
    const k1 = computeKernel({ samples: 9, strength: [1, 1, 1] });
    const kd = computeKernel({ samples: 9 });
    for (let c = 0; c < 3; c++) {
      const s = REFERENCE_STRENGTH[c];
      expect(kd[c]).toBeCloseTo(1 - s + s * k1[c], 6);
      expect(kd[4 + c]).toBeCloseTo(s * k1[4 + c], 7);
    }
  });
  it('falloff narrows a channel: y = x / (0.001 + falloff)', () => {
    const wide = computeKernel({ samples: 17, strength: [1, 1, 1], falloff: [1, 0.5, 0.25] });
    // narrower profile → more weight on the centre tap
    expect(wide[0]).toBeLessThan(wide[1]);
    expect(wide[1]).toBeLessThan(wide[2]);
  });
});

describe('marginal kernel', () => {
  it('is well formed for every size 3..63 (skin), and for every built-in profile', () => {
    for (const n of ALL_SAMPLES) expectWellFormed(computeKernel({ samples: n, profile: 'skin' }), n);
    for (const name of ['skinBurley', 'marble', 'milk']) {
      for (const n of [3, 11, 17, 25, 63]) expectWellFormed(computeKernel({ samples: n, profile: name }), n);
    }
  });
  it('places taps at the (i + 0.5)/samples quantiles of the channel-average marginal CDF', () => {
    for (const name of ['skin', 'skinBurley']) {
      const p = profiles[name];
      const samples = 11;
      const positive = taps(computeKernel({ samples, profile: name })).filter((t) => t.offset > 0);
      positive.forEach((t, j) => {
        const tail = p.marginalIntegral(t.offset, Infinity);
        expect((tail[0] + tail[1] + tail[2]) / 3).toBeCloseTo(0.5 - (j + 1) / samples, 6);
      });
      // the widest channel (red) with placement 'widest'
      const widest = taps(computeKernel({ samples, profile: name, placement: 'widest' })).filter((t) => t.offset > 0);
      widest.forEach((t, j) => expect(p.marginalIntegral(t.offset, Infinity)[0]).toBeCloseTo(0.5 - (j + 1) / samples, 6));
    }
  });
  it('weights are the marginal energy over each footprint: the step-edge response is exact at footprint boundaries', () => {
    for (const name of ['skin', 'skinBurley', 'marble', 'milk']) {
      const kernel = computeKernel({ samples: 17, profile: name });
      for (const x of midpoints(kernel)) {
        const exact = edgeResponse1D(name, x);
        const discrete = kernelEdgeResponse1D(kernel, x);
        // within 1 % of the exact value (in practice float32 rounding, ~1e-7)
        exact.forEach((v, c) => expect(Math.abs(discrete[c] - v)).toBeLessThanOrEqual(0.01 * v + 1e-6));
      }
    }
  });
  it('the reference kernel\'s edge response is much further from the exact marginal (measured ≈ 0.13 at 17 taps)', () => {
    // Compare like with like: the reference kernel with strength 1 and falloff 1 samples the radial profile
    // made of the red d'Eon Gaussians 2..6 with x scaled by 1/1.001; the exact answer is that profile's marginal.
    const scaled = gaussianSumProfile(
      'red2to6',
      DEON_SKIN_GAUSSIANS.slice(1).map((g) => ({ varianceMm2: g.varianceMm2 * 1.001 ** 2, weights: [g.weights[0], g.weights[0], g.weights[0]] })),
    );
    const maxError = (kernel) =>
      Math.max(...midpoints(kernel).map((x) => Math.abs(kernelEdgeResponse1D(kernel, x)[0] - edgeResponse1D(scaled, x)[0])));
    const reference = computeKernel({ samples: 17, method: 'reference', strength: [1, 1, 1], falloff: [1, 1, 1] });
    const marginal = computeKernel({ samples: 17, profile: scaled });
    const referenceError = maxError(reference);
    const marginalError = maxError(marginal);
    expect(referenceError).toBeGreaterThan(0.1);
    expect(referenceError).toBeLessThan(0.26);
    expect(referenceError).toBeCloseTo(0.1304, 3);
    expect(marginalError).toBeLessThan(1e-5);
  });
  it('strength mixes with the identity', () => {
    const full = computeKernel({ samples: 9, profile: 'marble' });
    const mixed = computeKernel({ samples: 9, profile: 'marble', strength: [0.5, 0, 1] });
    expect(mixed[0]).toBeCloseTo(0.5 + 0.5 * full[0], 7);
    expect(mixed[1]).toBeCloseTo(1, 7);
    expect(mixed[2]).toBeCloseTo(full[2], 7);
    expect(mixed[4]).toBeCloseTo(0.5 * full[4], 7);
    expect(mixed[5]).toBe(0);
  });
  it('maxRadiusMm truncates: taps inside, weights = clipped footprint energy renormalised', () => {
    const p = profiles.skin;
    const R = 1;
    const kernel = computeKernel({ samples: 15, profile: p, maxRadiusMm: R });
    expectWellFormed(kernel, 15);
    expect(kernelRadiusMm(kernel)).toBeLessThan(R);
    const outer = taps(kernel).reduce((best, t) => (t.offset > best.offset ? t : best));
    const bounds = midpoints(kernel);
    const mass = p.marginalIntegral(-R, R);
    const expected = p.marginalIntegral(bounds[bounds.length - 1], R).map((v, c) => v / mass[c]);
    outer.w.forEach((v, c) => expect(v).toBeCloseTo(expected[c], 6));
  });
  it('each method ignores the other method\'s (valid) options, so one options object serves both', () => {
    const shared = { samples: 11, profile: 'marble', falloff: [1, 0.5, 0.5], strength: [0.5, 0.5, 0.5] };
    const reference = computeKernel({ ...shared, method: 'reference' });
    expect(Array.from(reference)).toEqual(Array.from(computeKernel({ samples: 11, falloff: [1, 0.5, 0.5], strength: [0.5, 0.5, 0.5] })));
    const marginal = computeKernel({ ...shared, method: 'marginal' });
    expect(Array.from(marginal)).toEqual(Array.from(computeKernel({ samples: 11, profile: 'marble', strength: [0.5, 0.5, 0.5] })));
  });
  it('accepts a profile name or object and defaults to method marginal when a profile is given', () => {
    const byName = computeKernel({ samples: 7, profile: 'marble' });
    const byObject = computeKernel({ samples: 7, profile: profiles.marble, method: 'marginal' });
    expect(Array.from(byName)).toEqual(Array.from(byObject));
    expect(Array.from(computeKernel({ samples: 7 }))).toEqual(Array.from(referenceKernel(7)));
  });
});

describe('kernel argument errors', () => {
  it('rejects bad sample counts naming samples and 3..63', () => {
    for (const [samples, type] of [
      [4, RangeError],
      [2, RangeError],
      [65, RangeError],
      [NaN, TypeError],
      ['17', TypeError],
    ]) {
      for (const extra of [{}, { profile: 'skin' }]) {
        let error;
        try {
          computeKernel({ samples, ...extra });
        } catch (e) {
          error = e;
        }
        expect(error).toBeInstanceOf(type);
        expect(error.message).toContain('samples');
        expect(error.message).toContain('3..63');
      }
    }
  });
  it('rejects bad strength, falloff, method, profile and option mixes', () => {
    expect(() => computeKernel({ strength: [0.5, 1.5, 0] })).toThrow(/strength\[1\] must be in \[0, 1\]/);
    expect(() => computeKernel({ falloff: [0, 1, 1] })).toThrow(/falloff\[0\] must be in \(0, 10\]/);
    expect(() => computeKernel({ falloff: [1, 1, 11] })).toThrow(RangeError);
    expect(() => computeKernel({ falloff: 1 })).toThrow(TypeError);
    expect(() => computeKernel({ method: 'gaussian' })).toThrow(/method must be one of 'reference', 'marginal'/);
    expect(() => computeKernel({ method: 'marginal', profile: 'ketchup' })).toThrow(/'skin', 'skinBurley', 'marble', 'milk'/);
    expect(() => computeKernel({ method: 'reference', profile: 'ketchup' })).toThrow(/'skin', 'skinBurley', 'marble', 'milk'/);
    expect(() => computeKernel({ profile: 'skin', falloff: [1, 0, 1] })).toThrow(/falloff\[1\]/);
    expect(() => computeKernel({ profile: 'skin', maxRadiusMm: 0 })).toThrow(/maxRadiusMm/);
    expect(() => computeKernel({ profile: 'skin', placement: 'centre' })).toThrow(/placement/);
    expect(() => computeKernel(null)).toThrow(TypeError);
    expect(() => kernelRadiusMm([1, 2, 3])).toThrow(TypeError);
  });
});
