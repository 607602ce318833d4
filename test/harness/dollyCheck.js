// The stability tests' check, shared by the WebGL pipeline's (test/browser/stability.test.js) and
// the WebGPU node's (test/browser/webgpu/webgpuStability.test.js): a slow dolly towards the head
// across every scale where the frame's plan changes in steps (src/3-blur/blurPlan.js), the scales
// found in Node (planThresholds.js); six frames around each, 0.005 % of the scale apart, measured
// by the page (test/pages/dolly.js's dollyDepartures): a change of the whole face in one frame
// shows as the pair across the scale departing from the dolly's steady change more than its
// neighbours.
import { expect } from 'vitest';
import { blurSettings, planThresholds } from './planThresholds.js';

export const DOLLY = Object.freeze({
  width: 128, height: 80,
  /** Frames per threshold and the scale ratio between them. */
  frames: 6, step: 1.00005,
  /** The face's distance at each threshold, world units (the field of view zooms in to put it there). */
  distance: 18,
  /** Light from the side: more light crosses shadow edges, more to scatter. */
  lightAzimuthDeg: 80,
});

/** The head's scan: world units per profile mm (HEAD_WORLD_UNIT_IN_MM 50, widthMm 1). */
const WIDTH_WORLD = 1 / 50;

/**
 * The bound: the pair across a threshold may depart from its neighbours' mean by 0.5 % of s (a
 * jump of about 1.5 % of s: the departure operator spreads a step over three pairs, 1/3 : 2/3 : 1/3),
 * or by float rounding, 2^-20 of the unscattered light; where one kernel meets the groups, by the
 * rounding the two programs do differently (`groupsOfLight`: on the WebGL pipeline half a
 * half-float step, 2^-12, the groups' halves between their passes, which one kernel does not
 * have). Where the groups' members change between two scale steps (kernelGroups.js's
 * kernelGroupsAt) the plan still steps: 2 % of s.
 */
const OF_S = 0.005;
const OF_S_REGROUPING = 0.02;
const OF_LIGHT = 2 ** -20;

/**
 * Dollies across every threshold of `sss` (pipeline options) with `dolly({ fovDeg, scales })`,
 * which renders a frame at each scale (px/mm) and returns dollyDepartures with `plans` and
 * `isStandIn`; asserts the set-up (the plan changes where Node found it, the dolly itself is
 * smooth) and returns the rows measured, each with its bound, for the test to assert. `groupsOfLight`:
 * the bound's rounding floor where one kernel meets the groups, a fraction of the unscattered light.
 */
export async function checkDolly(sss, dolly, { groupsOfLight = 2 ** -12 } = {}) {
  const thresholds = planThresholds(blurSettings(sss), 0.05, 7);
  expect(thresholds.length).toBeGreaterThan(0);
  const rows = [];
  for (const { pixelsPerMm, before, after } of thresholds) {
    const fovDeg = Math.min(40, (2 * Math.atan((WIDTH_WORLD * DOLLY.height) / (2 * pixelsPerMm * DOLLY.distance)) * 180) / Math.PI);
    const scales = Array.from({ length: DOLLY.frames }, (_, k) => pixelsPerMm * DOLLY.step ** (k - (DOLLY.frames - 1) / 2));
    const r = await dolly({ fovDeg, scales });
    expect(r.isStandIn).toBe(false);
    // The plan changes between the two middle frames, as Node found it.
    const middle = DOLLY.frames / 2;
    const [b, a] = [JSON.parse(before), JSON.parse(after)];
    const parts = (plan) => [plan.blur, plan.samples, plan.groups];
    expect([parts(r.plans[middle - 1]), parts(r.plans[middle])]).toEqual([b.slice(0, 3), a.slice(0, 3)]);
    const across = r.pairs.find((p) => p.k === middle - 1);
    const sides = r.pairs.filter((p) => p.k !== middle - 1);
    const excess = (name) => across[name] - sides.reduce((sum, p) => sum + p[name], 0) / sides.length;
    const ofLight = (b[2] > 1) !== (a[2] > 1) ? groupsOfLight : OF_LIGHT;
    rows.push({
      pixelsPerMm, change: `${before} → ${after}`.replace(/\[\[\[.*?\]\]\]/g, 'groups'), excess: excess('s'), excessUnscattered: excess('unscattered'),
      s: r.s, unscattered: r.unscattered, bound: Math.max((b[2] > 1 && a[2] > 1 ? OF_S_REGROUPING : OF_S) * r.s, ofLight * r.unscattered),
    });
  }
  console.log(rows.map((w) => `${w.pixelsPerMm.toFixed(4)} px/mm ${w.change.slice(0, 60)}: excess ${(100 * w.excess / w.s).toFixed(3)} % of s (${(w.excess / w.unscattered).toExponential(2)} of the light; bound ${(w.bound / w.unscattered).toExponential(2)}), unscattered ${(100 * w.excessUnscattered / w.unscattered).toFixed(4)} %`).join('\n'));
  for (const w of rows) expect(w.excessUnscattered).toBeLessThanOrEqual(OF_S * w.unscattered); // the dolly itself is smooth
  return rows;
}
