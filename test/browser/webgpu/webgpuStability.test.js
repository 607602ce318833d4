// The WebGPU node stable when things move: the WebGL pipeline's dolly check
// (test/harness/dollyCheck.js) on the node, which shares the plan (src/3-blur/blurPlan.js): the
// blur fading in and, with kernelGroups 'auto', the groups fading in (their split: kernelGroups.js's
// fadedGrouping, read through src/webgpu/3-blur/GroupFractionTexture.js). On the WebGPU backend
// (the node's WebGL 2 backend shares the node's code).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { closeCheckedPage, evaluateFloats } from '../../harness/page.js';
import { openWebgpuPage } from '../../harness/webgpuBrowser.js';
import { DOLLY, checkDolly } from '../../harness/dollyCheck.js';

/**
 * Where one kernel meets the groups the node's two programs round the light to halves each on
 * their own (every target of the node is half float): two half-float steps of the light, 2^-10.
 */
const GROUPS_OF_LIGHT = 2 ** -10;

let page;
beforeAll(async () => { page = await openWebgpuPage('/test/pages/webgpu.html'); });
afterAll(async () => {
  await page.evaluate(() => window.wgpu.dollyClose());
  await closeCheckedPage(page);
});

describe('the node on a slow dolly across the plan\'s thresholds', () => {
  it.each([['default', {}], ["kernelGroups 'auto'", { kernelGroups: 'auto' }]])('%s: no coherent jump of s where the plan changes', async (_, sss) => {
    const rows = await checkDolly(sss, ({ fovDeg, scales }) => evaluateFloats(page, async (o) => {
      const { isStandIn } = await window.wgpu.dollyOpen({ width: o.width, height: o.height, fovDeg: o.fovDeg, lightAzimuthDeg: o.lightAzimuthDeg, sss: o.sss });
      return { isStandIn, ...(await window.wgpu.dollyFrames(o.scales)) };
    }, { ...DOLLY, fovDeg, scales, sss }), { groupsOfLight: GROUPS_OF_LIGHT });
    expect(rows.length).toBeGreaterThan(0);
    for (const w of rows) expect(w.excess, `${w.pixelsPerMm} px/mm: ${w.change}`).toBeLessThanOrEqual(w.bound);
  });
});
