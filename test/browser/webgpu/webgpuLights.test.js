// The lights a user has (issue 36), on the WebGPU node, both backends: `node.light` assigned at
// any time (a light after none, the other kind, none) gives the diffuse light of a node made with
// that light, to the bit; and a setting changed between two renders of one animation frame is that
// render's (the node plans per render, not per frame).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats } from '../../harness/page.js';
import { BACKENDS, openWebgpuPage } from '../../harness/webgpuBrowser.js';
import { transmittedFractionOracle } from '../../oracle/transmittance.js';

let page;
beforeAll(async () => { page = await openWebgpuPage('/test/pages/webgpu.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

const worst = (a, b) => a.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, Math.abs(v - b[i]))), 0);
const brightest = (a) => a.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, v)), 0);

for (const backend of BACKENDS) {
  describe(`the node's lights, ${backend}`, () => {
    it('node.light assigned: a light after none, the other kind, none, the first again: each frame the frame of a node made with that light', async () => {
      const { made, assigned: a } = await evaluateFloats(page, (b) => window.wgpu.lightAssigned({ backend: b }), backend);
      expect(brightest(made.sun.diffuse)).toBeGreaterThan(0.3); // 1 mm of skin, back-lit: red through
      expect(worst(made.spot.diffuse, made.sun.diffuse)).toBeGreaterThan(0.05); // two different pictures
      expect(a.none).toMatchObject({ light: null, transmittance: true }); // the default, kept: it acts through the light there is
      expect(brightest(a.none.diffuse)).toBe(0);
      expect(a.sun).toMatchObject({ light: 'sun', transmittance: true });
      expect(worst(a.sun.diffuse, made.sun.diffuse)).toBe(0);
      expect(a.spot).toMatchObject({ light: 'spot', transmittance: true });
      expect(worst(a.spot.diffuse, made.spot.diffuse)).toBe(0);
      expect(a.null).toMatchObject({ light: null, transmittance: true });
      expect(brightest(a.null.diffuse)).toBe(0);
      expect(worst(a['sun again'].diffuse, made.sun.diffuse)).toBe(0);
    });

    it('the settings a light needs, set at once in either key order on a node made without one: the same frames; without a light the thickness view is black and the frame says why (issue 40)', async () => {
      const forward = await evaluateFloats(page, (b) => window.wgpu.lightKeyOrder({ backend: b, order: 'forward' }), backend);
      const backward = await evaluateFloats(page, (b) => window.wgpu.lightKeyOrder({ backend: b, order: 'backward' }), backend);
      const { made } = forward;
      expect(brightest(made.diffuse)).toBeGreaterThan(0.3);
      for (const label of Object.keys(forward.steps)) {
        const [f, b] = [forward.steps[label], backward.steps[label]];
        expect(worst(b.diffuse, f.diffuse), label).toBe(0);
        expect(worst(b.output, f.output), label).toBe(0);
        expect(b.problems, label).toEqual(f.problems);
        expect(f.transmittance, label).toBe(true);
      }
      const [lit, dark, again] = Object.values(forward.steps);
      expect(worst(lit.diffuse, made.diffuse)).toBe(0);
      expect(lit.problems).toEqual([]);
      expect(brightest(dark.output)).toBe(0); // the slab fills the view: the thickness view black, not the diffuse light
      expect(dark.problems).toEqual([
        expect.stringMatching(/^transmittance is true but there is no light/),
        expect.stringMatching(/^debugView 'thickness' shows what the light gives, and there is no light/),
      ]);
      expect(brightest(again.output)).toBeGreaterThan(0.05); // the light back: its thickness shows
      expect(again.problems).toEqual([]);
    });

    it("a light nearer the slab than its shadow camera's near: the oracle's T(1 mm) within 2 % (before: 0, clipped away)", async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.nearLight({ backend: b }), backend);
      const oracle = transmittedFractionOracle({ thicknessMm: 1, profile: 'skin', shrinkMm: 0.6, towardLightViewZ: -1 });
      const sums = [0, 0, 0];
      let n = 0;
      for (let y = 10; y < 44; y++) for (let x = 15; x < 81; x++) { for (let c = 0; c < 3; c++) sums[c] += r.diffuse[(y * 96 + x) * 4 + c]; n++; }
      expect(Math.abs(sums[0] / n / oracle[0] - 1), `red: node ${sums[0] / n}, oracle ${oracle[0]}`).toBeLessThan(0.02);
      expect(r.problems).toEqual([]);
    });

    it('scattering turned on between two renders of one animation frame: the second render is blurred (before: the unblurred image again)', async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.sameFrame({ backend: b }), backend);
      expect(worst(r.blurred, r.unblurred), 'the blur shows').toBeGreaterThan(0.01);
      expect(worst(r.onAgain, r.blurred), `from the unblurred: ${worst(r.onAgain, r.unblurred)}`).toBeLessThan(1e-6);
    });
  });
}
