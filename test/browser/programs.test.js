// The shader programs the pipeline compiles (renderer.info.programs): the first frame compiles only
// what it draws with, and changing a setting back and forth does not grow the count without limit
// (a slider over `samples` is a uniform change, not a program per value).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, closeCheckedPage } from '../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/**
 * In the page, on a fresh renderer each: a subsurface slab (and an ordinary box) drawn once by a
 * plain RenderPass, and once by the pipeline (`settings` assigned first); then `sweep`'s values of
 * one setting, a frame each. Returns the program names after each step.
 */
function countPrograms({ settings, sweep, withLight = false }) {
  const { THREE, SSS, RenderPass, createRenderer, createComposer, buildScene, DEFAULTS } = window.lab;
  const programs = (renderer) => renderer.info.programs.map((p) => p.name);
  const built = () => {
    const b = buildScene('slab', { ...DEFAULTS, pattern: 'noise' });
    const box = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshStandardMaterial({ color: 0x3366cc }));
    box.position.set(2, 0, 1);
    b.scene.add(box);
    return b;
  };
  const plain = (() => {
    const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
    const { scene, camera } = built();
    const composer = createComposer(renderer);
    composer.addPass(new RenderPass(scene, camera));
    composer.render();
    const names = programs(renderer);
    composer.dispose();
    renderer.dispose();
    return names;
  })();
  const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
  const composer = createComposer(renderer);
  const { scene, camera, subsurface, light } = built();
  const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: DEFAULTS.worldUnitInMm, light: withLight ? light : null });
  sss.makeSubsurface(subsurface[0], { widthMm: 4 });
  Object.assign(sss, settings);
  composer.addPass(sss);
  composer.render();
  const first = programs(renderer);
  const blurred = sss.plan.blur;
  const [name, values] = sweep;
  for (const value of values) {
    sss[name] = value;
    composer.render();
  }
  const swept = programs(renderer);
  sss.dispose();
  composer.dispose();
  renderer.dispose();
  return { plain, first, swept, blurred };
}

/** samples 3..63 and back down: a slider dragged both ways. */
const SLIDER = [...Array.from({ length: 31 }, (_, i) => 3 + 2 * i), ...Array.from({ length: 31 }, (_, i) => 63 - 2 * i)];

describe('shader programs', () => {
  // The first frame: the plain frame's programs (the subsurface material's variant stands in for
  // its plain one) and the three passes it draws with (blurH, blurV, compose). The slider: every
  // value a uniform change, so the count stays; the isotropic blur ('auto' groups) may add its
  // groups' pair (two passes) once, when a frame first draws with them.
  const cases = [
    ['footprint (default)', {}, 0],
    ['marginal', { method: 'marginal' }, 0],
    ["the isotropic blur, kernelGroups 'auto'", { kernelGroups: 'auto' }, 2],
  ];
  for (const [label, settings, groupPair] of cases) {
    it(`${label}: the first frame compiles the plain frame's programs + 3, and a samples slider 3..63..3 adds ${groupPair}`, async () => {
      const r = await page.evaluate(countPrograms, { settings: { ...settings, samples: 9 }, sweep: ['samples', [...SLIDER, 'auto', 9]] });
      expect(r.blurred).toBe(true);
      expect(r.first.length, JSON.stringify(r.first)).toBe(r.plain.length + 3);
      expect(r.swept.length, JSON.stringify(r.swept)).toBeLessThanOrEqual(r.first.length + groupPair);
    });
  }
});
