// Stable when things move: a slow dolly towards the head across every scale where the frame's
// plan changes in steps (src/3-blur/blurPlan.js: the blur skipped below half a pixel, the 'auto'
// groups, the 'auto' fixed-tap counts), for the default, kernelGroups 'auto' and method
// 'reference'; the check and its bound are test/harness/dollyCheck.js's, the frames
// test/pages/stability.js's. The WebGPU node's: test/browser/webgpu/webgpuStability.test.js.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { closeCheckedPage, openPage, evaluateFloats } from '../harness/page.js';
import { DOLLY, checkDolly } from '../harness/dollyCheck.js';

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
  await closeCheckedPage(page);
});

describe('a slow dolly across the plan\'s thresholds', () => {
  it.each(Object.entries(SETTINGS))('%s: no coherent jump of s where the plan changes', async (_, sss) => {
    const rows = await checkDolly(sss, ({ fovDeg, scales }) => evaluateFloats(page, async (o) => {
      const st = window.stability;
      const { isStandIn } = await st.open({ width: o.width, height: o.height, fovDeg: o.fovDeg, lightAzimuthDeg: o.lightAzimuthDeg, sss: o.sss });
      const r = await st.dolly(o.scales.map((x) => st.distanceFor(x)));
      if (r.glError !== 0) throw new Error(`GL error ${r.glError}`);
      return { isStandIn, ...r };
    }, { ...DOLLY, fovDeg, scales, sss }));
    // Across each threshold the pair's change departs from the steady dolly's by no more than the bound.
    expect(rows.length).toBeGreaterThan(0);
    for (const w of rows) expect(w.excess, `${w.pixelsPerMm} px/mm: ${w.change}`).toBeLessThanOrEqual(w.bound);
  });
});
