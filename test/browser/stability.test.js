// Stable when things move: a slow dolly towards the head across every scale where the frame's
// plan changes in steps (src/3-blur/blurPlan.js: the blur skipped below half a pixel, the 'auto'
// groups, the 'auto' fixed-tap counts), for the default, kernelGroups 'auto' and method 'reference'.
// The scales come from the plan in Node (test/harness/planThresholds.js); only six frames around
// each are rendered, 0.005 % of the scale apart. Per frame pair the page measures how far the
// change of the scattering signal s (the output minus the same frame's unscattered light) departs
// from the dolly's steady change (test/pages/stability.js's dolly); a change of the whole face in
// one frame shows as the pair across the scale departing more than its neighbours.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../harness/page.js';
import { blurSettings, planThresholds } from '../harness/planThresholds.js';

const WIDTH = 128;
const HEIGHT = 80;
/** Frames per threshold and the scale ratio between them. */
const FRAMES = 6;
const STEP = 1.00005;
/** The face's distance at each threshold, world units (the field of view zooms in to put it there). */
const DISTANCE = 18;
/** The head's scan: world units per profile mm (HEAD_WORLD_UNIT_IN_MM 50, widthMm 1). */
const WIDTH_WORLD = 1 / 50;
/**
 * The bound: the pair across a threshold may depart from its neighbours' mean by 0.5 % of s (a
 * jump of about 1.5 % of s: the departure operator spreads a step over three pairs, 1/3 : 2/3 : 1/3),
 * or by float rounding, 2^-20 of the unscattered light; where one kernel meets the groups, by half a
 * half-float step of it (2^-12), the groups' rounding between their passes
 * (shaders/3-blur/kernelGroups.glsl), which one kernel does not have. Where the groups' members
 * change between two scale steps (kernelGroups.js's kernelGroupsAt) the plan still steps: 1.5 % of s.
 */
const OF_S = 0.005;
const OF_S_REGROUPING = 0.015;
const OF_LIGHT = 2 ** -20;
const OF_LIGHT_GROUPS = 2 ** -12;

const SETTINGS = {
  default: {},
  "kernelGroups 'auto'": { kernelGroups: 'auto' },
  "method 'reference', samples 'auto'": { method: 'reference' },
};

let page;
beforeAll(async () => {
  page = await openPage('/test/pages/stability.html');
});
afterAll(async () => {
  await page.evaluate(() => window.stability.close());
  expect(page.problems).toEqual([]);
  await page.close();
});

describe('a slow dolly across the plan\'s thresholds', () => {
  it.each(Object.entries(SETTINGS))('%s: no coherent jump of s where the plan changes', async (_, sss) => {
    const thresholds = planThresholds(blurSettings(sss), 0.05, 7);
    expect(thresholds.length).toBeGreaterThan(0);
    const rows = [];
    for (const { pixelsPerMm, before, after } of thresholds) {
      // A vertical field of view putting the threshold about DISTANCE from the face.
      const fovDeg = Math.min(40, (2 * Math.atan((WIDTH_WORLD * HEIGHT) / (2 * pixelsPerMm * DISTANCE)) * 180) / Math.PI);
      const r = await evaluateFloats(page, async (o) => {
        const st = window.stability;
        const { isStandIn } = await st.open({ width: o.width, height: o.height, fovDeg: o.fovDeg, lightAzimuthDeg: 80, sss: o.sss });
        const distances = Array.from({ length: o.frames }, (_, k) => st.distanceFor(o.pixelsPerMm * o.step ** (k - (o.frames - 1) / 2)));
        return { isStandIn, ...(await st.dolly(distances)) };
      }, { width: WIDTH, height: HEIGHT, fovDeg, sss, pixelsPerMm, frames: FRAMES, step: STEP });
      expect(r.isStandIn).toBe(false);
      expect(r.glError).toBe(0);
      // The plan changes between the two middle frames, as Node found it.
      const middle = FRAMES / 2;
      expect([r.plans[middle - 1].samples, r.plans[middle].samples, r.plans[middle - 1].groups, r.plans[middle].groups, r.plans[middle - 1].blur, r.plans[middle].blur])
        .toEqual([JSON.parse(before)[1], JSON.parse(after)[1], JSON.parse(before)[2], JSON.parse(after)[2], JSON.parse(before)[0], JSON.parse(after)[0]]);
      const across = r.pairs.find((p) => p.k === middle - 1);
      const sides = r.pairs.filter((p) => p.k !== middle - 1);
      const excess = (name) => across[name] - sides.reduce((sum, p) => sum + p[name], 0) / sides.length;
      const [b, a] = [JSON.parse(before), JSON.parse(after)];
      const regrouping = b[2] > 1 && a[2] > 1;
      const ofLight = (b[2] > 1) !== (a[2] > 1) ? OF_LIGHT_GROUPS : OF_LIGHT;
      rows.push({
        pixelsPerMm, change: `${before} → ${after}`.replace(/\[\[\[.*?\]\]\]/g, 'groups'), excess: excess('s'), excessUnscattered: excess('unscattered'),
        s: r.s, unscattered: r.unscattered, bound: Math.max((regrouping ? OF_S_REGROUPING : OF_S) * r.s, ofLight * r.unscattered),
      });
    }
    console.log(rows.map((w) => `${w.pixelsPerMm.toFixed(4)} px/mm ${w.change.slice(0, 60)}: excess ${(100 * w.excess / w.s).toFixed(3)} % of s (${(w.excess / w.unscattered).toExponential(2)} of the light; bound ${(w.bound / w.unscattered).toExponential(2)}), unscattered ${(100 * w.excessUnscattered / w.unscattered).toFixed(4)} %`).join('\n'));
    for (const w of rows) {
      expect(w.excess, `${w.pixelsPerMm} px/mm: ${w.change}`).toBeLessThanOrEqual(w.bound);
      expect(w.excessUnscattered).toBeLessThanOrEqual(OF_S * w.unscattered); // the dolly itself is smooth
    }
  });
});
