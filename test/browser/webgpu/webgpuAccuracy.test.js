// The analytic accuracy suite (accuracyCases.js: the same cases and thresholds as the WebGL
// pipeline's accuracy.test.js) on the three-separable-sss/webgpu node, on WebGPURenderer's WebGPU
// backend (SwiftShader's Vulkan) and on its WebGL 2 backend (forceWebGL). The isotropic blur's
// cases (kernelGroups 'auto', the radial answer off the axes) run at 2 and 5 px/mm on WebGPU, and
// on WebGL 2, where the same TSL blur runs again, for skin at the harder, 5 px/mm (the blur's own
// error largest there: 0.030 of the 0.03 at 45°); the plan they follow is the WebGL path's JS,
// which accuracy.test.js runs at 1-10 px/mm.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats } from '../../harness/page.js';
import { BACKENDS, openWebgpuPage } from '../../harness/webgpuBrowser.js';
import { accuracyMeasures, footprintCases } from '../3-blur/accuracyCases.js';

let page;
beforeAll(async () => { page = await openWebgpuPage('/test/pages/webgpu.html'); });
afterAll(async () => {
  await page.evaluate((backends) => { for (const backend of backends) window.wgpu.disposeFlatRig(backend); }, BACKENDS);
  expect(page.problems).toEqual([]);
  await page.close();
});

for (const backend of BACKENDS) {
  describe(`the node on ${backend}: 'footprint' (the default, samples 'auto', and 17 taps) against closed forms`, () => {
    const measures = accuracyMeasures((o) => evaluateFloats(page, (options) => window.wgpu.flat(options), { ...o, backend }));
    for (const [title, run] of footprintCases(measures, backend === 'webgpu' ? { isotropicScales: [2, 5] } : { isotropicScales: [5], isotropicProfiles: ['skin'] })) it(title, run);
  });
}
