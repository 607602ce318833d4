// Stage 3's own plan, in Node: planBlur is pure and dispatches on METHOD_TABLE through BLUR_MODES
// (src/3-blur/blurPlan.js); BlurStage's plan reads only its own settings. The counts are worked
// out by hand from the rules in blurPlan.js's comments.
import { describe, it, expect } from 'vitest';
import { PerspectiveCamera, Texture } from 'three';
import { SubsurfaceBlurPass } from '../../../src/3-blur/SubsurfaceBlurPass.js';
import { ProfileLookup } from '../../../src/profiles/ProfileLookup.js';
import { planBlur, autoSampleCount, autoTapBlend, blendKernels, frameGroupings, rampShare, BLUR_MODES, blurModeOf, FADE_IN_PIXELS, PLAN_RAMP } from '../../../src/3-blur/blurPlan.js';
import { MIN_KERNEL_PIXELS } from '../../../src/3-blur/samplingModel.js';
import { AUTO_SAMPLES, AUTO_REACH, METHODS, METHOD_TABLE } from '../../../src/options.js';
import { AUTO_MAX_SAMPLES, FOOTPRINT_ROWS, footprintTable } from '../../../src/profiles/footprints.js';
import { computeKernel, kernelRadiusMm } from '../../../src/profiles/kernel.js';
import { profiles } from '../../../src/profiles/presets.js';
import { MAX_KERNEL_GROUPS, autoKernelGroups, fadedGrouping, footprintGroupFractions, groupEnergies, kernelGroupsAt } from '../../../src/3-blur/kernelGroups.js';

const base = { scattering: true, marginalRadiusMm: 3, denseRadiusMm: 7, kernelReachMm: { 17: 4, 25: 5 }, kernelGroups: 1, profiles: [profiles.skin] };
const oneKernel = { groups: 1, groupings: null };

describe('planBlur', () => {
  it('every method has a blur mode, and every mode a pass kind', () => {
    for (const method of METHODS) {
      expect(BLUR_MODES[METHOD_TABLE[method].blur], method).toBeDefined();
      expect(['separable', 'dense']).toContain(blurModeOf(method).passes);
    }
  });

  it("'footprint': the frame keeps the budget (per pixel the table chooses) and reaches the marginal's 99 % radius", () => {
    expect(planBlur({ ...base, method: 'footprint', samples: 'auto' }, 2)).toEqual({ samples: AUTO_MAX_SAMPLES, tapBlend: null, kernelPixels: 6, blur: true, fade: 1, passes: 'separable', ...oneKernel });
    expect(planBlur({ ...base, method: 'footprint', samples: 9 }, 2).samples).toBe(9);
  });

  it('fixed taps reach their outermost tap; below half a pixel, or switched off, nothing runs', () => {
    expect(planBlur({ ...base, method: 'marginal', samples: 17 }, 0.1)).toEqual({ samples: 17, tapBlend: null, kernelPixels: 0.4, blur: false, fade: 0, passes: 'separable', ...oneKernel });
    expect(planBlur({ ...base, method: 'marginal', samples: 17 }, 0.125)).toMatchObject({ blur: false, fade: 0 }); // exactly 0.5 px: the fade starts
    expect(planBlur({ ...base, method: 'reference', samples: 25 }, 0).blur).toBe(false); // nothing drawn
    expect(planBlur({ ...base, method: 'marginal', samples: 17, scattering: false }, 100).blur).toBe(false);
    expect(() => planBlur({ ...base, method: 'marginal', samples: 9 }, 1)).toThrow(/no kernel reach for 9 taps/);
  });

  it("'auto' fixed taps: the fewest of AUTO_SAMPLES whose (n - 3) / 2 pixels per side reach AUTO_REACH of the radius", () => {
    const reach = Object.fromEntries(AUTO_SAMPLES.map((n) => [n, n / 10]));
    // 3 mm at 2 px/mm: 6 px; 0.92 × 6 = 5.52 px per side: (13 - 3) / 2 = 5 is short, (17 - 3) / 2 = 7 reaches.
    expect(planBlur({ ...base, kernelReachMm: reach, method: 'marginal', samples: 'auto' }, 2)).toEqual({ samples: 17, tapBlend: null, kernelPixels: 3.4, blur: true, fade: 1, passes: 'separable', ...oneKernel });
    expect(autoSampleCount(6)).toBe(17);
    expect(autoSampleCount(1e6)).toBe(63);
    for (const n of AUTO_SAMPLES) expect(autoSampleCount((((n - 3) / 2) / AUTO_REACH) * (1 - 1e-9))).toBe(n);
  });

  it('the dense reference runs the dense pass, whatever the method, and reaches its own radius', () => {
    for (const method of METHODS) expect(planBlur({ ...base, method, dense: true, samples: 'auto' }, 2)).toMatchObject({ kernelPixels: 14, blur: true, passes: 'dense' });
  });

  it('every count of taps, in either mode, is a uniform change: the pass is compiled for the most taps', () => {
    const camera = new PerspectiveCamera();
    const pass = new SubsurfaceBlurPass({ direction: 'horizontal', kernel: computeKernel({ samples: 9, profile: profiles.skin }), camera, surfaceTexture: new Texture(), profileLookup: new ProfileLookup(profiles.skin) });
    const defines = JSON.stringify(pass.material.defines);
    for (const mode of ['taps', 'footprint']) {
      pass.setMode(mode);
      const modeDefines = JSON.stringify(pass.material.defines);
      for (const samples of [3, 17, AUTO_MAX_SAMPLES]) {
        pass.setKernel(computeKernel({ samples, profile: profiles.skin }));
        expect(JSON.stringify(pass.material.defines)).toBe(modeDefines);
        expect(pass.uniforms.tapCount.value).toBe(samples);
      }
    }
    expect(pass.material.defines.SAMPLES).toBe(AUTO_MAX_SAMPLES);
    expect(defines).toContain(`"SAMPLES":${AUTO_MAX_SAMPLES}`);
    pass.dispose();
  });

  it('a real kernel reach is its outermost tap', () => {
    const kernel = computeKernel({ samples: 17, method: 'marginal', profile: profiles.skin });
    const mm = kernelRadiusMm(kernel);
    expect(planBlur({ ...base, kernelReachMm: { 17: mm }, method: 'marginal', samples: 17 }, 3).kernelPixels).toBeCloseTo(3 * mm, 12);
  });

  it("the isotropic blur's groups: 'auto' is one kernel where one group is within the budget at the frame's scale, else the most; a count that many in every slot; fixed taps and the dense pass none", () => {
    const grouped = { ...base, method: 'footprint', samples: 'auto', kernelGroups: 'auto', profiles: [profiles.skin, profiles.marble] };
    const far = planBlur(grouped, 0.125);
    expect(autoKernelGroups(profiles.skin, 0.125).count).toBe(1);
    expect(far).toMatchObject(oneKernel); // a far head pays for one kernel
    const near = planBlur(grouped, 5);
    expect(autoKernelGroups(profiles.skin, 5).count).toBeGreaterThan(1);
    expect(near.groups).toBe(MAX_KERNEL_GROUPS);
    expect(near.groupings.map((g) => g.count)).toEqual([MAX_KERNEL_GROUPS, MAX_KERNEL_GROUPS]); // marble has four Gaussians
    expect(planBlur({ ...grouped, kernelGroups: 1 }, 5)).toMatchObject(oneKernel);
    expect(planBlur({ ...grouped, kernelGroups: 2 }, 5).groups).toBe(2);
    for (const setting of [{ method: 'marginal' }, { dense: true }]) {
      expect(planBlur({ ...grouped, ...setting, samples: 17 }, 5)).toMatchObject(oneKernel);
    }
  });
});

describe('stable under motion: plan changes ramp over a range of scales', () => {
  it('rampShare: 0 up to end / ratio, 1 from end on, linear in log scale between', () => {
    expect(rampShare(1, 2, 2)).toBe(0);
    expect(rampShare(2, 2, 2)).toBe(1);
    expect(rampShare(Math.SQRT2, 2, 2)).toBeCloseTo(0.5, 12);
    expect(rampShare(3, 2, 2)).toBe(1);
    expect(rampShare(0, 2, 2)).toBe(0);
  });

  it('the blur fades in from half a pixel to FADE_IN_PIXELS of reach: no blur at the start, all of it at the end, between in proportion', () => {
    const plan = (px) => planBlur({ ...base, method: 'footprint', samples: 'auto' }, px / base.marginalRadiusMm);
    expect(plan(MIN_KERNEL_PIXELS)).toMatchObject({ blur: false, fade: 0 });
    expect(plan(MIN_KERNEL_PIXELS * 1.01).blur).toBe(true);
    expect(plan(Math.sqrt(MIN_KERNEL_PIXELS * FADE_IN_PIXELS)).fade).toBeCloseTo(0.5, 12);
    expect(plan(FADE_IN_PIXELS).fade).toBe(1);
    // Continuous: a 0.1 % step of the scale moves the fade by at most 0.1 % / ln 2 of it.
    for (let px = 0.4; px < 1.2; px *= 1.001) expect(plan(px * 1.001).fade - plan(px).fade).toBeLessThanOrEqual(Math.log(1.001) / Math.log(FADE_IN_PIXELS / MIN_KERNEL_PIXELS) + 1e-12);
    expect(planBlur({ ...base, method: 'footprint', samples: 'auto', scattering: false }, 10)).toMatchObject({ blur: false, fade: 0 });
  });

  it("'auto' fixed taps blend the two counts over PLAN_RAMP below each change, where their taps fit the compiled 63", () => {
    const change = (n) => (n - 3) / 2 / AUTO_REACH; // where autoSampleCount leaves n
    expect(autoTapBlend(change(17) / PLAN_RAMP)).toBe(null);
    expect(autoTapBlend(change(17) / Math.sqrt(PLAN_RAMP))).toEqual({ from: 17, to: 25, share: expect.closeTo(0.5, 12) });
    expect(autoTapBlend(change(17))).toEqual({ from: 17, to: 25, share: 1 });
    expect(autoTapBlend(change(17) * 1.001)).toBe(null); // 25 alone above
    expect(autoTapBlend(change(25) * 0.99)).toMatchObject({ from: 25, to: 33 }); // 57 taps
    expect(autoTapBlend(change(33) * 0.99)).toBe(null); // 33 + 45 - 1 = 77: a switch
    const reach = Object.fromEntries(AUTO_SAMPLES.map((n) => [n, n / 10]));
    const plan = planBlur({ ...base, kernelReachMm: reach, method: 'reference', samples: 'auto' }, change(17) / Math.sqrt(PLAN_RAMP) / base.marginalRadiusMm);
    expect(plan).toMatchObject({ samples: 17 + 25 - 1, tapBlend: { from: 17, to: 25 } });
    expect(plan.kernelPixels).toBeCloseTo(2.5 * change(17) / Math.sqrt(PLAN_RAMP) / base.marginalRadiusMm, 12); // the wider kernel's reach
  });

  it('blendKernels: every tap of both, weighted 1 - share and share, one centre; the weights still sum to 1', () => {
    const a = computeKernel({ samples: 17, method: 'reference' });
    const b = computeKernel({ samples: 25, method: 'reference' });
    const k = blendKernels(a, b, 0.25);
    expect(k.length / 4).toBe(17 + 25 - 1);
    for (let c = 0; c < 3; c++) {
      let sum = 0;
      for (let i = 0; i < k.length; i += 4) sum += k[i + c];
      expect(sum).toBeCloseTo(1, 6);
      expect(k[c]).toBeCloseTo(0.75 * a[c] + 0.25 * b[c], 7);
    }
    expect(kernelRadiusMm(k)).toBeCloseTo(Math.max(kernelRadiusMm(a), kernelRadiusMm(b)), 6);
    expect(Array.from(blendKernels(a, b, 0).subarray(0, a.length))).toEqual(Array.from(a));
  });

  it("kernelGroups 'auto' fades the groups in over PLAN_RAMP below the step where one kernel leaves the budget", () => {
    const grouped = { ...base, method: 'footprint', samples: 'auto', kernelGroups: 'auto' };
    let end = 0.05;
    while (autoKernelGroups(profiles.skin, end * 1.0001).count === 1) end *= 1.0001; // where one group stops
    expect(frameGroupings(grouped, end / PLAN_RAMP / 1.01)).toBe(null);
    const faded = frameGroupings(grouped, end / Math.sqrt(PLAN_RAMP));
    expect(faded[0].count).toBe(MAX_KERNEL_GROUPS);
    expect(faded[0].share).toBeCloseTo(0.5, 1);
    expect(frameGroupings(grouped, end * 1.01)[0].share).toBeUndefined(); // the groups themselves above
    // The faded grouping's members are those just above the step: no change of members at the ramp's end.
    expect(faded[0].members).toEqual(frameGroupings(grouped, end * 1.01)[0].members);
  });

  it('fadedGrouping: each footprint split as share of its own and 1 - share of the energy shares; at 0 every footprint alike', () => {
    const grouping = kernelGroupsAt(profiles.skin, 2, MAX_KERNEL_GROUPS);
    const table = footprintTable((x) => profiles.skin.marginalIntegral(0, x), 17);
    const own = footprintGroupFractions(grouping, table);
    const energies = groupEnergies(grouping);
    const flat = footprintGroupFractions(fadedGrouping(grouping, 0), table);
    const half = footprintGroupFractions(fadedGrouping(grouping, 0.5), table);
    let checked = 0;
    for (let i = 0; i < own.length; i += MAX_KERNEL_GROUPS * 3) {
      if (own[i] + own[i + 3] + own[i + 6] + own[i + 9] === 0) { // past a row's last footprint: nothing there either
        expect(flat.subarray(i, i + MAX_KERNEL_GROUPS * 3).every((f) => f === 0)).toBe(true);
        continue;
      }
      checked++;
      for (let g = 0; g < MAX_KERNEL_GROUPS; g++) {
        for (let c = 0; c < 3; c++) {
          const j = i + g * 3 + c;
          expect(flat[j]).toBeCloseTo(energies[g][c], 6);
          expect(half[j]).toBeCloseTo(0.5 * own[j] + 0.5 * energies[g][c], 6);
        }
      }
    }
    expect(checked).toBeGreaterThan(FOOTPRINT_ROWS);
    expect(fadedGrouping(grouping, 1)).toBe(grouping);
    expect(fadedGrouping(grouping, 0.5)).toBe(fadedGrouping(grouping, 0.5)); // cached: the blur's table is refilled per share step
  });
});
