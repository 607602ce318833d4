// The lights a user has (issues 36 and 43), on the WebGPU node, both backends: `node.light`
// assigned at any time (a light after none, the other kind, none) gives the diffuse light of a
// node made with that light, to the bit; every light the WebGL pipeline takes (a point light's six
// faces and its aimed map against the float64 oracle, a list of up to four whose light adds up and
// equals the WebGL pipeline's, 'castShadow'), as test/browser/1-light-depth/lights.test.js asks of
// the pipeline; and a setting changed between two renders of one animation frame is that render's
// (the node plans per render, not per frame).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats } from '../../harness/page.js';
import { BACKENDS, openWebgpuPage } from '../../harness/webgpuBrowser.js';
import { transmittedFractionOracle } from '../../oracle/transmittance.js';
import { middle } from '../../harness/images.js';

let page;
beforeAll(async () => { page = await openWebgpuPage('/test/pages/webgpu.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

/** The largest RGB difference over the value, each value's floor 1e-3 (the node's diffuse light is half float: a step is 2^-11 of it). */
const relative = (a, b) => a.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, Math.abs(v - b[i]) / Math.max(1e-3, Math.abs(b[i])))), 0);

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

    it('up to four lights (two directional, a spot, a point light), each with its own map: each alone, summed, equals all together, equals the WebGL pipeline with the four; the list reads back', async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.nodeLightList({ backend: b }), backend);
      const names = ['behind', 'oblique', 'spot', 'bulb'];
      for (const name of names) {
        expect(brightest(r[name].diffuse), name).toBeGreaterThan(0.01); // each sends light
        expect(r[name].light).toBe(name === 'oblique' ? 'a list' : name);
      }
      expect(r.bulb.cubes).toEqual([false]); // the slab fits the point light's 120°: one map, aimed
      const sum = (labels) => r.all.diffuse.map((_, i) => labels.reduce((total, label) => total + r[label].diffuse[i], 0));
      // Each frame's light is rounded to half float apart: four roundings of 2^-12 of the value at most.
      expect(relative(r.all.diffuse, sum(names)), 'four together against the four alone, summed').toBeLessThan(2e-3);
      expect(relative(r.two.diffuse, sum(['spot', 'behind'])), 'two').toBeLessThan(1e-3);
      expect(r.all).toMatchObject({ light: 'a list', problems: [], cubes: [false, false, false, false] });
      // The WebGL pipeline's four-light frame (float): the node's within two half-float steps of its brightest.
      expect(worst(r.all.diffuse, r.webgl.all) / brightest(r.webgl.all), `brightest ${brightest(r.webgl.all)}`).toBeLessThan(1e-3);
    });

    it("a SpotLight, and a PointLight among transmitting meshes (six faces), straight behind a 1 mm slab (along +z, +x, −y and −z): the oracle's T(1 mm) within 2 %; aimed where the meshes fit 120° (one map): what a spot light at its place gives", async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.nodePointLight({ backend: b }), backend);
      const oracle = transmittedFractionOracle({ thicknessMm: 1, profile: 'skin', shrinkMm: 0.6, towardLightViewZ: -1 });
      expect(oracle[0]).toBeGreaterThan(0.3);
      // At the middle's edge the light is 0.7° off the axis: T, the entry cosine and the falloff change by under 0.1 %.
      for (const face of ['spot behind', '+z', '+x', '-y', '-z']) {
        expect(r[face]).toMatchObject({ light: face === 'spot behind' ? 'spot' : 'bulb', cubes: [face !== 'spot behind'], problems: [] });
        const mean = middle(r[face].diffuse, 48);
        for (let c = 0; c < 3; c++) {
          if (oracle[c] > 0.01) expect(Math.abs(mean[c] / oracle[c] - 1), `${face}, channel ${c}: node ${mean[c]}, oracle ${oracle[c]}`).toBeLessThan(0.02);
          else expect(Math.abs(mean[c] - oracle[c]), `${face}, channel ${c}`).toBeLessThan(2e-4);
        }
      }
      expect(r.aimed.cubes).toEqual([false]);
      const lit = brightest(r.spot.diffuse);
      expect(lit).toBeGreaterThan(0.05);
      expect(worst(r.aimed.diffuse, r.spot.diffuse) / lit).toBeLessThan(1e-3); // two half-float steps
    });

    it("'castShadow': the scene's shadow-casting lights, found each frame (the same floats as listing them), more than four said in problems", async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.nodeCastShadow({ backend: b }), backend);
      expect(brightest(r.listed.diffuse)).toBeGreaterThan(0.05);
      expect(r.castShadow).toMatchObject({ light: 'castShadow', problems: [], cubes: [false, false] });
      expect(worst(r.castShadow.diffuse, r.listed.diffuse)).toBe(0);
      expect(worst(r['one casts'].diffuse, r.sun.diffuse)).toBe(0);
      expect(r['bulb casts'].cubes).toEqual([false, false]); // the sun's map and the bulb's, aimed
      expect(brightest(r['bulb casts'].diffuse)).toBeGreaterThan(brightest(r.sun.diffuse));
      expect(r['six cast'].problems).toEqual(['6 lights cast shadows: transmittance comes from the first 4 in the scene\'s order (list the ones you want in `light`)']);
      expect(r['none cast']).toMatchObject({ light: 'castShadow', problems: [], cubes: [] });
      expect(brightest(r['none cast'].diffuse)).toBe(0);
    });

    it('scattering turned on between two renders of one animation frame: the second render is blurred (before: the unblurred image again)', async () => {
      const r = await evaluateFloats(page, (b) => window.wgpu.sameFrame({ backend: b }), backend);
      expect(worst(r.blurred, r.unblurred), 'the blur shows').toBeGreaterThan(0.01);
      expect(worst(r.onAgain, r.blurred), `from the unblurred: ${worst(r.onAgain, r.unblurred)}`).toBeLessThan(1e-6);
    });
  });
}
