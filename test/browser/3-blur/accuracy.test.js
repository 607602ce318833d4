// The analytic accuracy suite of the WebGL pipeline (test/pages/lab.js's `flat`): the measurements,
// the closed forms and the default method's table of cases are in accuracyCases.js, shared with the
// WebGPURenderer node's suite (webgpuAccuracy.test.js); the other methods' known accuracy is here.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  await page.evaluate(() => window.lab.disposeFlatRig());
  expect(page.problems).toEqual([]);
  await page.close();
});

import { accuracyMeasures, footprintCases } from './accuracyCases.js';

const measures = accuracyMeasures((o) => evaluateFloats(page, (options) => window.lab.flat(options), o));
const { stepEdge } = measures;

describe("'footprint' (the default, samples 'auto', and 17 taps) against closed forms", () => {
  for (const [title, run] of footprintCases(measures)) it(title, run);
});

describe('the other methods against the same closed forms (their known accuracy)', () => {
  it("'marginal' (fixed taps): step edges within 7 % at 2 px/mm, the staircase of point taps", async () => {
    const worst = await stepEdge({ profile: 'skin', s: 2, sss: { method: 'marginal', samples: 17 } });
    expect(worst).toBeLessThan(0.07);
    expect(worst).toBeGreaterThan(0.01); // the footprint method is the better one
  });

  it("'reference' (Jimenez's kernel samples the radial profile): step edges off by up to about 0.3", async () => {
    const worst = await stepEdge({ profile: 'skin', s: 2, sss: { method: 'reference', samples: 17 } });
    expect(worst).toBeGreaterThan(0.1);
    expect(worst).toBeLessThan(0.35);
  });
});
