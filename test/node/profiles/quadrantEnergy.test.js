// QuadrantEnergyLookup: the table the dense reference reads its pixel energies from, read the
// way the shader reads it, against closed forms of the profiles.
import { describe, it, expect } from 'vitest';
import { QuadrantEnergyLookup } from '../../../src/profiles/QuadrantEnergyLookup.js';
import { getProfile } from '../../../src/profiles/presets.js';
import { normalIntervalProbability } from '../../../src/math/specialFunctions.js';

const lookups = Object.fromEntries(['skin', 'skinBurley', 'milk'].map((name) => [name, new QuadrantEnergyLookup(name)]));
const grid = [0.002, 0.02, 0.06, 0.1, 0.25, 0.5, 1, 2, 4, 8];

describe('QuadrantEnergyLookup', () => {
  it('skin: Q(a, b) equals the closed form Σ w P(0 < X < a) P(0 < Y < b) within 1e-4', () => {
    const { gaussians } = getProfile('skin');
    let worst = 0;
    for (const a of grid) {
      for (const b of grid) {
        const q = lookups.skin.quadrantEnergy(a, b);
        for (let c = 0; c < 3; c++) {
          const exact = gaussians.reduce((s, g) => s + g.weights[c] * normalIntervalProbability(0, a, g.varianceMm2) * normalIntervalProbability(0, b, g.varianceMm2), 0);
          worst = Math.max(worst, Math.abs(q[c] - exact));
        }
      }
    }
    expect(worst).toBeLessThan(1e-4);
  });

  for (const name of ['skinBurley', 'milk']) {
    it(`${name}: Q(a, ∞) is half the strip energy ∫_0^a marginal within 1e-4; Q(∞, ∞) = 1/4`, () => {
      const profile = getProfile(name);
      const lookup = lookups[name];
      for (const a of grid) {
        const strip = profile.marginalIntegral(0, a);
        lookup.quadrantEnergy(a, 1e9).forEach((q, c) => expect(Math.abs(q - strip[c] / 2)).toBeLessThan(1e-4));
      }
      lookup.quadrantEnergy(1e9, 1e9).forEach((q) => expect(Math.abs(q - 0.25)).toBeLessThan(2e-5));
    });
  }

  it('is odd in each argument, so double differences give any rectangle, and pixels tile to 1', () => {
    const lookup = lookups.skinBurley;
    expect(lookup.quadrantEnergy(-0.3, 0.7)).toEqual(lookup.quadrantEnergy(0.3, 0.7).map((v) => -v));
    expect(lookup.quadrantEnergy(-0.3, -0.7)).toEqual(lookup.quadrantEnergy(0.3, 0.7));
    // The pixels of a 1.6 px/mm lattice out to the range carry all the energy.
    const s = 1.6;
    const n = Math.ceil(lookup.rangeMm * s);
    const Q = (i, j) => lookup.quadrantEnergy((i - 0.5) / s, (j - 0.5) / s);
    const total = [0, 0, 0];
    for (let j = -n; j <= n; j++) {
      for (let i = -n; i <= n; i++) {
        const e = [Q(i + 1, j + 1), Q(i, j + 1), Q(i + 1, j), Q(i, j)];
        for (let c = 0; c < 3; c++) total[c] += e[0][c] - e[1][c] - e[2][c] + e[3][c];
      }
    }
    total.forEach((t) => expect(Math.abs(t - 1)).toBeLessThan(1e-4));
  });

  it('refuses a bad size', () => {
    expect(() => new QuadrantEnergyLookup('skin', { size: 8 })).toThrow(RangeError);
  });
});
