// Stage 3's own plan, in Node: planBlur is pure and dispatches on METHOD_TABLE through BLUR_MODES
// (src/3-blur/blurPlan.js); BlurStage's plan reads only its own settings. The counts are worked
// out by hand from the rules in blurPlan.js's comments.
import { describe, it, expect } from 'vitest';
import { PerspectiveCamera, Texture } from 'three';
import { SubsurfaceBlurPass } from '../../../src/3-blur/SubsurfaceBlurPass.js';
import { ProfileLookup } from '../../../src/profiles/ProfileLookup.js';
import { planBlur, autoSampleCount, BLUR_MODES, blurModeOf } from '../../../src/3-blur/blurPlan.js';
import { AUTO_SAMPLES, AUTO_REACH, METHODS, METHOD_TABLE } from '../../../src/options.js';
import { AUTO_MAX_SAMPLES } from '../../../src/profiles/footprints.js';
import { computeKernel, kernelRadiusMm } from '../../../src/profiles/kernel.js';
import { profiles } from '../../../src/profiles/presets.js';
import { MAX_KERNEL_GROUPS, autoKernelGroups } from '../../../src/3-blur/kernelGroups.js';

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
    expect(planBlur({ ...base, method: 'footprint', samples: 'auto' }, 2)).toEqual({ samples: AUTO_MAX_SAMPLES, kernelPixels: 6, blur: true, passes: 'separable', ...oneKernel });
    expect(planBlur({ ...base, method: 'footprint', samples: 9 }, 2).samples).toBe(9);
  });

  it('fixed taps reach their outermost tap; below half a pixel, or switched off, nothing runs', () => {
    expect(planBlur({ ...base, method: 'marginal', samples: 17 }, 0.1)).toEqual({ samples: 17, kernelPixels: 0.4, blur: false, passes: 'separable', ...oneKernel });
    expect(planBlur({ ...base, method: 'marginal', samples: 17 }, 0.125).blur).toBe(true); // exactly 0.5 px
    expect(planBlur({ ...base, method: 'reference', samples: 25 }, 0).blur).toBe(false); // nothing drawn
    expect(planBlur({ ...base, method: 'marginal', samples: 17, scattering: false }, 100).blur).toBe(false);
    expect(() => planBlur({ ...base, method: 'marginal', samples: 9 }, 1)).toThrow(/no kernel reach for 9 taps/);
  });

  it("'auto' fixed taps: the fewest of AUTO_SAMPLES whose (n - 3) / 2 pixels per side reach AUTO_REACH of the radius", () => {
    const reach = Object.fromEntries(AUTO_SAMPLES.map((n) => [n, n / 10]));
    // 3 mm at 2 px/mm: 6 px; 0.92 × 6 = 5.52 px per side: (13 - 3) / 2 = 5 is short, (17 - 3) / 2 = 7 reaches.
    expect(planBlur({ ...base, kernelReachMm: reach, method: 'marginal', samples: 'auto' }, 2)).toEqual({ samples: 17, kernelPixels: 3.4, blur: true, passes: 'separable', ...oneKernel });
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
