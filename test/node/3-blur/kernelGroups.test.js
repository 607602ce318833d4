// The isotropic blur's groups (src/3-blur/kernelGroups.js) and the Gaussian fits they split
// (src/profiles/gaussianFit.js), against closed forms written out here and in
// test/oracle/closedForms.js: the transfer of a grouped separable blur at angle θ is
// Σ_g A_g(f cos θ) A_g(f sin θ) / W_g, the radial answer M(f); Burley's M(f) is its own closed form.
import { describe, it, expect } from 'vitest';
import { DEON, GAUSSIANS, transferOf, erfc } from '../../oracle/closedForms.js';
import { profiles } from '../../../src/profiles/presets.js';
import { gaussianSumOf, nonNegativeLeastSquares } from '../../../src/profiles/gaussianFit.js';
import { ISOTROPY_ERROR, MAX_KERNEL_GROUPS, autoKernelGroups, checkKernelGroups, footprintGroupFractions, groupEnergies, kernelGroups, kernelGroupsAt, possibleGroupCounts } from '../../../src/3-blur/kernelGroups.js';
import { gaussianSumProfile } from '../../../src/profiles/gaussianSum.js';
import { KernelGroupTable, splitFractions } from '../../../src/3-blur/KernelGroupTable.js';
import { GroupFractionTexture } from '../../../src/webgpu/3-blur/GroupFractionTexture.js';
import { FOOTPRINT_ROWS, footprintRowOf, footprintRowScale, footprintTable } from '../../../src/profiles/footprints.js';

const ANGLES_DEG = [0, 11.25, 22.5, 33.75, 45];
const FREQUENCIES = Array.from({ length: 151 }, (_, k) => k * 0.01); // 0..1.5 cycles/mm

/**
 * [variance, rgb] pairs → the grouped separable transfer in channel c (the oracle's own sum); a
 * group is a list of Gaussian indices, or of fractions per Gaussian (`fractions: true`).
 */
function oracleTransfer(pairs, groups, c, f, angleDeg, fractions = false) {
  const t = (angleDeg * Math.PI) / 180;
  const share = (group, i) => (fractions ? group[i] : group.includes(i) ? 1 : 0);
  const A = (group, ff) => pairs.reduce((s, [v, w], i) => s + share(group, i) * w[c] * Math.exp(-2 * Math.PI ** 2 * v * ff * ff), 0);
  return groups.reduce((s, g) => (A(g, 0) > 0 ? s + (A(g, f * Math.cos(t)) * A(g, f * Math.sin(t))) / A(g, 0) : s), 0);
}

/** Worst |grouped − M| over the angles and 0..fmax, per channel; M from `radial(f)`. */
function worstError(pairs, groupsOf, radial, fmax = 1.5, fractions = false) {
  const step = fmax / 150;
  return [0, 1, 2].map((c) => {
    let worst = 0;
    for (let k = 0; k <= 150; k++) {
      const f = k * step;
      for (const a of ANGLES_DEG) worst = Math.max(worst, Math.abs(oracleTransfer(pairs, groupsOf(c), c, f, a, fractions) - radial(f)[c]));
    }
    return worst;
  });
}

/** Φ, the standard normal distribution. */
const Phi = (x) => 1 - 0.5 * erfc(x / Math.SQRT2);

/**
 * The exact response, at pixel (0, m) from the edge, of the pixel image of a step at 45° (pixel
 * (i, j) lit where i + j ≥ 0) to the separable kernel N(va)(x)·N(vb)(y) (mm², s px/mm): the
 * energy of each pixel column dx times that of the lit pixels of its row, Σ_dx P_a(dx) (1 − Φ((−m − dx − ½) / σ_b)).
 */
function diagonalPairResponse(va, vb, s, m) {
  const sa = Math.sqrt(va) * s;
  const sb = Math.sqrt(vb) * s;
  const reach = Math.ceil(8 * sa) + 2;
  let r = 0;
  for (let dx = -reach; dx <= reach; dx++) r += (Phi((dx + 0.5) / sa) - Phi((dx - 0.5) / sa)) * (1 - Phi((-m - dx - 0.5) / sb));
  return r;
}

/** The worst difference, over the pixels near the edge, between a grouping's and the radial profile's 45° step response. */
function diagonalStepWorst(grouping, s) {
  const G = grouping.gaussians;
  let worst = 0;
  for (let m = -Math.ceil(8 * s); m <= Math.ceil(8 * s); m++) {
    for (let c = 0; c < 3; c++) {
      let difference = -G.reduce((sum, g) => sum + g.weights[c] * diagonalPairResponse(g.varianceMm2, g.varianceMm2, s, m), 0);
      for (const member of grouping.members[c]) {
        const w = G.map((g, i) => member[i] * g.weights[c]);
        const W = w.reduce((a, b) => a + b, 0);
        if (!(W > 0)) continue;
        G.forEach((gi, i) => G.forEach((gj, j) => { if (w[i] * w[j] > 0) difference += ((w[i] * w[j]) / W) * diagonalPairResponse(gi.varianceMm2, gj.varianceMm2, s, m); }));
      }
      worst = Math.max(worst, Math.abs(difference));
    }
  }
  return worst;
}

const pairsOf = (gaussians) => gaussians.map((g) => [g.varianceMm2, g.weights]);

describe('the separable error and the groups that remove it (closed form)', () => {
  const skin = GAUSSIANS.skin;
  const M = (f) => transferOf('skin', f);

  it("one separable blur of d'Eon skin is up to 0.18 off M(f) on the diagonal (red; 0.167 at 0.8 cycles/mm)", () => {
    const all = [[0, 1, 2, 3, 4, 5]];
    const worst = worstError(skin, () => all, M);
    expect(worst[0]).toBeGreaterThan(0.17);
    expect(worst[0]).toBeLessThan(0.19);
    expect(Math.abs(oracleTransfer(skin, all, 0, 0.8, 45) - M(0.8)[0])).toBeGreaterThan(0.16);
    expect(Math.abs(oracleTransfer(skin, all, 0, 0.8, 0) - M(0.8)[0])).toBeLessThan(1e-12); // exact on the axes
  });

  it("the issue's groups {1}, {2, 3}, {4, 5, 6} stay within 0.027 of M(f) at every angle up to 1.5 cycles/mm", () => {
    const issue = [[0], [1, 2], [3, 4, 5]];
    for (const e of worstError(skin, () => issue, M)) expect(e).toBeLessThan(0.027);
  });

  for (const name of ['skin', 'marble']) {
    it(`${name}: the library's groupings (6 px/mm) have the error they report, and fall with every group added`, () => {
      let last = Infinity;
      for (let count = 1; count <= MAX_KERNEL_GROUPS; count++) {
        const g = kernelGroups(profiles[name], count, 6);
        const measured = worstError(pairsOf(g.gaussians), (c) => g.members[c], (f) => transferOf(name, f), 1.5, true);
        measured.forEach((e, c) => expect(Math.abs(e - g.error[c])).toBeLessThan(2e-3)); // the library's frequency grid is coarser
        expect(Math.max(...measured)).toBeLessThanOrEqual(last + 1e-9);
        last = Math.max(...measured);
      }
      expect(last).toBeLessThan(0.014);
    });
  }

  it('skin in 3 groups per channel (fractions of Gaussians at the boundaries) is within 0.02 of M(f), a ninth of one group\'s', () => {
    const g = kernelGroups(profiles.skin, 3, 6);
    const e = worstError(GAUSSIANS.skin, (c) => g.members[c], M, 1.5, true);
    expect(e[0]).toBeLessThan(0.02);
    expect(Math.max(e[1], e[2])).toBeLessThan(0.003);
    g.members.forEach((members) => members[0].forEach((_, i) => expect(members.reduce((sum, m) => sum + m[i], 0)).toBeCloseTo(1, 12)));
  });

  for (const name of ['skin', 'marble']) {
    it(`${name}: 'auto' groups answer a 45° step edge of pixels like the radial profile within 1 % (exact pixel sums, 1-8 px/mm)`, () => {
      for (const s of [1, 2, 4, 8]) {
        const one = diagonalStepWorst(kernelGroups(profiles[name], 1, s), s);
        const auto = diagonalStepWorst(autoKernelGroups(profiles[name], s), s);
        expect(one, `${s} px/mm, one group`).toBeGreaterThan(0.03);
        expect(auto, `${s} px/mm, 'auto'`).toBeLessThan(0.01);
      }
    });
  }
});

describe('Gaussian fits of the profiles without Gaussians', () => {
  it("Gaussian profiles are their own sum, sorted by variance", () => {
    const { gaussians, stepError, exact } = gaussianSumOf(profiles.skin);
    expect(exact).toBe(true);
    expect(stepError).toEqual([0, 0, 0]);
    expect(gaussians.map((g) => g.varianceMm2)).toEqual(DEON.map(([v]) => v));
  });

  for (const name of ['skinBurley', 'milk']) {
    it(`${name}: the fit's marginal energy is within its stated step error (≤ 0.2 %) of the profile's, unit energy`, () => {
      const { gaussians, stepError, exact } = gaussianSumOf(profiles[name]);
      expect(exact).toBe(false);
      expect(Math.max(...stepError)).toBeLessThan(0.002);
      for (let c = 0; c < 3; c++) expect(Math.abs(gaussians.reduce((s, g) => s + g.weights[c], 0) - 1)).toBeLessThan(1e-4);
      const erfHalf = (x, v) => 0.5 * Math.sign(x) * (1 - erfc(Math.abs(x) / Math.sqrt(2 * v)));
      for (const x of [0.01, 0.05, 0.2, 0.7, 2, 6]) {
        const exactEnergy = profiles[name].marginalIntegral(0, x);
        for (let c = 0; c < 3; c++) {
          const fit = gaussians.reduce((s, g) => s + g.weights[c] * erfHalf(x, g.varianceMm2), 0);
          expect(Math.abs(fit - exactEnergy[c])).toBeLessThanOrEqual(stepError[c] + 1e-9);
        }
      }
    });
  }

  it("skinBurley's fit has Burley's transfer (closed form) within 0.01 up to 1.5 cycles/mm", () => {
    const pairs = pairsOf(gaussianSumOf(profiles.skinBurley).gaussians);
    const worst = worstError(pairs, () => [pairs.map((_, i) => i)], (f) => transferOf('skinBurley', f));
    // along the axis one group's transfer is the fit's own A(f)
    for (const f of FREQUENCIES) {
      const m = transferOf('skinBurley', f);
      for (let c = 0; c < 3; c++) expect(Math.abs(oracleTransfer(pairs, [pairs.map((_, i) => i)], c, f, 0) - m[c])).toBeLessThan(0.01);
    }
    expect(worst[0]).toBeGreaterThan(0.1); // and one separable blur of it is far from isotropic
  });

  it('non-negative least squares: the known answer of a small problem with an active bound', () => {
    // min (w0 − 1)² + (w1 + 1)² over w ≥ 0: w = (1, 0)
    const w = nonNegativeLeastSquares([[1, 0], [0, 1]], [1, -1]);
    expect(w[0]).toBeCloseTo(1, 12);
    expect(w[1]).toBe(0);
  });
});

describe("'auto' groups follow the on-screen scale", () => {
  for (const name of ['skin', 'skinBurley', 'marble']) {
    it(`${name}: one group for a far head (0.125 px/mm), more as the scale grows, each within ISOTROPY_ERROR of the radial transfer`, () => {
      expect(autoKernelGroups(profiles[name], 0.125).count).toBe(1);
      let last = 0;
      for (const s of [0.25, 0.5, 1, 2, 3, 5, 10]) {
        const g = autoKernelGroups(profiles[name], s);
        expect(g.count).toBeGreaterThanOrEqual(last);
        last = g.count;
        // the oracle's error at the gratings this scale shows (≥ 4 px per cycle), against the true M(f)
        const e = worstError(pairsOf(g.gaussians), (c) => g.members[c], (f) => transferOf(name, f), s / 4, true);
        expect(Math.max(...e), `${s} px/mm`).toBeLessThan(ISOTROPY_ERROR + Math.max(...g.fitStepError) + 2e-3);
      }
    });
  }

  it('refuses a group count outside 1..4, naming it', () => {
    expect(() => kernelGroups(profiles.skin, 0, 1)).toThrow(RangeError);
    expect(() => checkKernelGroups('some')).toThrow(/kernelGroups must be 'auto' or an integer in 1\.\.4, got 'some'/);
    expect(checkKernelGroups('auto')).toBe('auto');
    expect(() => kernelGroups(profiles.skin, 5, 1)).toThrow(/kernelGroups must be an integer in 1\.\.4/);
    expect(() => kernelGroups(profiles.skin, '2', 1)).toThrow(TypeError);
  });
});

describe("what the blur reads of a grouping (KernelGroupTable, shaders/3-blur/kernelGroups.glsl)", () => {
  const G = (x) => profiles.skin.marginalIntegral(0, x);
  const table = footprintTable(G, 17);
  const grouping = kernelGroups(profiles.skin, 3, 4);
  const fractions = footprintGroupFractions(grouping, table);
  const at = (row, column, g, c) => fractions[((row * (table.columns + 1) + column) * MAX_KERNEL_GROUPS + g) * 3 + c];
  // Group g's energy over [a, b] mm of one side, from the closed-form Gaussians (the oracle's own sum).
  const groupEnergy = (g, c, a, b) => GAUSSIANS.skin.reduce((sum, [v, w], i) => sum + grouping.members[c][g][i] * w[c] * 0.5 * (erfc(a / Math.sqrt(2 * v)) - (b === Infinity ? 0 : erfc(b / Math.sqrt(2 * v)))), 0);

  it("each footprint's energy is split between the groups as their Gaussians share it, the parts summing to 1", () => {
    for (const row of [footprintRowOf(1), footprintRowOf(4), footprintRowOf(10)]) {
      const s = footprintRowScale(row);
      // The centre pixel (|x| < ½ px) and the first footprint, whose edge the table gives.
      const edge = Math.floor(table.data[2 * row * table.columns] * s + 0.5);
      for (const [column, a, b] of [[0, 0, 0.5 / s], [1, 0.5 / s, (edge + 0.5) / s]]) {
        for (let c = 0; c < 3; c++) {
          const e = [0, 1, 2].map((g) => groupEnergy(g, c, a, b));
          const total = e[0] + e[1] + e[2];
          for (let g = 0; g < 3; g++) expect(at(row, column, g, c)).toBeCloseTo(e[g] / total, 5);
          expect(at(row, column, 3, c)).toBe(0); // three groups: the fourth holds nothing
        }
      }
      for (let column = 0; column <= table.columns; column++) {
        const sum = [0, 1, 2, 3].reduce((s2, g) => s2 + at(row, column, g, 0), 0);
        if (sum > 0) expect(sum).toBeCloseTo(1, 6); // past the last footprint: unused zeros
      }
    }
  });

  it("the WebGPU node's float texture (GroupFractionTexture) holds the WebGL shader's split (splitFractions: the shader's own decoding of its texels, within a unorm step of the fractions, summing to 1; past groups 1 and 2's reach theirs 0), group g's rows after groups 0..g − 1's", () => {
    const width = table.columns + 1;
    for (const count of [2, 3, 4]) {
      const g4 = kernelGroups(profiles.skin, count, 4);
      const exact = footprintGroupFractions(g4, table);
      const split = splitFractions(g4, table);
      const t = new GroupFractionTexture();
      const texture = t.update(g4, table);
      expect([texture.image.width, texture.image.height]).toEqual([width, MAX_KERNEL_GROUPS * FOOTPRINT_ROWS]);
      expect(t.update(g4, table)).toBe(texture); // unchanged: not refilled
      let far = 0;
      for (const row of [0, footprintRowOf(1), footprintRowOf(4), footprintRowOf(10), FOOTPRINT_ROWS - 1]) {
        for (let column = 0; column < width; column++) {
          for (let c = 0; c < 3; c++) {
            const at = (fractions, g) => fractions[((row * width + column) * MAX_KERNEL_GROUPS + g) * 3 + c];
            const parts = [0, 1, 2, 3].map((g) => at(split, g));
            for (let g = 0; g < MAX_KERNEL_GROUPS; g++) expect(texture.image.data[((g * FOOTPRINT_ROWS + row) * width + column) * 4 + c]).toBe(parts[g]);
            const sum = parts.reduce((a, b) => a + b, 0);
            if (exact.slice(((row * width + column) * MAX_KERNEL_GROUPS) * 3, ((row * width + column + 1) * MAX_KERNEL_GROUPS) * 3).every((x) => x === 0)) continue; // past the last footprint
            expect(sum).toBeCloseTo(1, 6);
            const isFar = count > 2 && parts[0] === 0 && parts[1] === 0 && at(exact, 0) + at(exact, 1) > 0;
            if (isFar) {
              far++;
              expect(at(exact, 0) + at(exact, 1)).toBeLessThanOrEqual(2 / 1023 + 1e-7); // groups 1 and 2's share there is the table's NEAR_SHARE at most
            } else {
              for (let g = 0; g < count; g++) expect(Math.abs(parts[g] - at(exact, g))).toBeLessThan(count / 1023); // the last takes the others' rounding
            }
            for (let g = count; g < MAX_KERNEL_GROUPS; g++) expect(parts[g]).toBe(0);
          }
        }
      }
      if (count === 4) expect(far).toBeGreaterThan(0); // the far footprints are among the rows checked
      // The split as kernelGroups.glsl makes it from KernelGroupTable's texels (sssSplit, and past
      // the row's near count, the centre texel's a, its far loop), decoded here on its own.
      const packed = new KernelGroupTable().update([g4], [table]).image.data;
      for (let texel = 0; texel < packed.length / 4; texel++) {
        const column = texel % width;
        const farColumn = count > 2 && column > 0 && column - 1 >= packed[(texel - column) * 4 + 3];
        for (let c = 0; c < 3; c++) {
          const unorm = (g) => ((packed[texel * 4 + g] >>> (10 * c)) & 1023) / 1023;
          let parts;
          if (farColumn) parts = count === 3 ? [0, 0, 1, 0] : [0, 0, unorm(2), Math.max(1 - unorm(2), 0)];
          else if (count === 2) parts = [unorm(0), Math.max(1 - unorm(0), 0), 0, 0];
          else if (count === 3) parts = [unorm(0), unorm(1), Math.max(1 - unorm(0) - unorm(1), 0), 0];
          else parts = [unorm(0), unorm(1), unorm(2), Math.max(1 - unorm(0) - unorm(1) - unorm(2), 0)];
          parts.forEach((part, g) => expect(split[(texel * MAX_KERNEL_GROUPS + g) * 3 + c]).toBeCloseTo(part, 6));
        }
      }
      t.dispose();
      expect(t.texture).toBe(null);
    }
  });

  it('the narrowest group holds less of each footprint the farther out it lies, and the centre pixel most', () => {
    const row = footprintRowOf(4);
    for (let column = 1; column < 4; column++) expect(at(row, column, 0, 1)).toBeLessThan(at(row, column - 1, 0, 1));
  });

  it("the texture holds them as 10-bit unorms summing to 1023 (so the shader's parts sum to the footprint's energy), the energy shares to 1 (two slots stacked)", () => {
    const lookups = [profiles.skin, profiles.marble];
    const groupings = lookups.map((p) => kernelGroups(p, 3, 4));
    const tables = lookups.map((p) => footprintTable((x) => p.marginalIntegral(0, x), 17));
    const t = new KernelGroupTable();
    const texture = t.update(groupings, tables);
    expect(texture.image.width).toBe(tables[0].columns + 1);
    expect(texture.image.height).toBe(2 * FOOTPRINT_ROWS);
    expect(t.update(groupings, tables)).toBe(texture); // unchanged: not refilled
    const marble = footprintGroupFractions(groupings[1], tables[1]);
    const row = footprintRowOf(4);
    for (let column = 0; column < 4; column++) {
      const texel = (FOOTPRINT_ROWS + row) * texture.image.width + column; // slot 1's rows follow slot 0's
      for (let c = 0; c < 3; c++) {
        let sum = 0;
        for (let g = 0; g < 3; g++) {
          const share = (texture.image.data[texel * 4 + g] >>> (10 * c)) & 1023;
          expect(Math.abs(share / 1023 - marble[((row * (tables[1].columns + 1) + column) * MAX_KERNEL_GROUPS + g) * 3 + c])).toBeLessThan(1 / 1023);
          sum += share;
        }
        expect(sum).toBe(1023); // three groups: the fourth holds none
      }
    }
    for (let slot = 0; slot < 2; slot++) {
      for (let c = 0; c < 3; c++) {
        let sum = 0;
        for (let g = 0; g < MAX_KERNEL_GROUPS; g++) sum += t.energies[(slot * MAX_KERNEL_GROUPS + g) * 3 + c];
        expect(sum).toBeCloseTo(1, 6);
      }
    }
    expect(groupEnergies(groupings[0]).map((e) => e[1])).toEqual(groupings[0].members[1].map((m) => m.reduce((s2, f, i) => s2 + f * groupings[0].gaussians[i].weights[1], 0)).map((e, _, all) => e / all.reduce((a, b) => a + b, 0)));
    t.dispose();
    expect(t.texture).toBe(null);
  });
});

describe('possibleGroupCounts (the warm-up compiles these)', () => {
  // Every count a frame takes, found by choosing at scales a half octave apart over 0.01..100 px/mm.
  const taken = (profile, setting) => {
    const counts = new Set();
    for (let k = -14; k <= 14; k++) counts.add(kernelGroupsAt(profile, 10 ** (k / 7), setting).count);
    return [...counts].sort();
  };
  const two = gaussianSumProfile('two', [{ varianceMm2: 0.05, weights: [0.5, 0.6, 0.7] }, { varianceMm2: 2, weights: [0.5, 0.4, 0.3] }]);
  it.each([
    ['skin', profiles.skin, 'auto'], ['skin', profiles.skin, 3], ['marble', profiles.marble, 'auto'], ['two Gaussians', two, 'auto'], ['two Gaussians', two, 4],
  ])('%s, kernelGroups %s: every count a frame takes at any scale is listed', (_, profile, setting) => {
    const listed = possibleGroupCounts([profile], setting);
    for (const count of taken(profile, setting)) expect(listed).toContain(count);
  });
  it("a profile of two Gaussians takes at most 2 ('auto': 1 or 2; 4 asked: 2); the most of several profiles'", () => {
    expect(possibleGroupCounts([two], 'auto')).toEqual([1, 2]);
    expect(possibleGroupCounts([two], 4)).toEqual([2]);
    expect(possibleGroupCounts([two, profiles.skin], 4)).toEqual([4]);
    expect(possibleGroupCounts([profiles.skin], 'auto')).toEqual([1, 2, 3, 4]);
  });
});
