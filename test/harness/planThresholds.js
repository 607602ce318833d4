// Where a frame's plan changes discretely with the on-screen scale, found in Node from the plan
// itself (src/3-blur/blurPlan.js's planBlur over the settings BlurStage would hand it), so the
// stability test renders only frames around those scales.
import { planBlur } from '../../src/3-blur/blurPlan.js';
import { AUTO_SAMPLES, METHOD_TABLE } from '../../src/options.js';
import { computeKernel, kernelRadiusMm } from '../../src/profiles/kernel.js';
import { ProfileLookup } from '../../src/profiles/ProfileLookup.js';
import { getProfile } from '../../src/profiles/presets.js';

/**
 * The settings BlurStage.planSettings gives for one profile.
 * @param {{ method?: string, samples?: number|'auto', kernelGroups?: number|'auto', profile?: string }} options
 */
export function blurSettings({ method = 'footprint', samples = 'auto', kernelGroups = 1, profile = 'skin' } = {}) {
  const lookup = new ProfileLookup(getProfile(profile));
  const counts = samples === 'auto' ? AUTO_SAMPLES : [samples];
  const kernel = METHOD_TABLE[method].kernel;
  const kernelReachMm = Object.fromEntries(counts.map((n) => [n, kernelRadiusMm(computeKernel({ samples: n, method: kernel, profile: lookup.profile }))]));
  const settings = {
    method, samples, scattering: true, marginalRadiusMm: lookup.marginalRadiusMm, denseRadiusMm: 0, kernelReachMm,
    kernelGroups: METHOD_TABLE[method].blur === 'footprint' ? kernelGroups : 1, profiles: [lookup.profile],
  };
  lookup.dispose();
  return settings;
}

/** What of a plan changes in steps: whether it blurs, its taps, its groups and their members (not a ramp's share). */
function discreteParts(plan) {
  return JSON.stringify([plan.blur, plan.samples, plan.groups, plan.tapBlend && [plan.tapBlend.from, plan.tapBlend.to], plan.groupings?.map((g) => g.members)]);
}

/**
 * The scales in [low, high] px/mm where planBlur's discrete parts change (found in steps of 0.1 %, then to 1e-9).
 * @param {object} settings blurSettings(...) @param {number} low @param {number} high
 * @returns {Array<{ pixelsPerMm: number, before: string, after: string }>}
 */
export function planThresholds(settings, low, high) {
  const out = [];
  let previous = null;
  for (let x = low; x <= high; x *= 1.001) {
    const parts = discreteParts(planBlur(settings, x));
    if (previous !== null && parts !== previous.parts) {
      let [a, b] = [previous.x, x]; // bisection to 1e-9 of the scale
      while (b / a > 1 + 1e-9) {
        const mid = Math.sqrt(a * b);
        if (discreteParts(planBlur(settings, mid)) === previous.parts) a = mid;
        else b = mid;
      }
      out.push({ pixelsPerMm: Math.sqrt(a * b), before: previous.parts, after: parts });
    }
    previous = { x, parts };
  }
  return out;
}
