// The shader programs the pipeline compiles (renderer.info.programs): the first frame compiles only
// what it draws with, and changing a setting back and forth does not grow the count without limit
// (a slider over `samples` is a uniform change, not a program per value); after the warm-up
// (compileAsync) no frame compiles one.
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

/**
 * In the page, on a fresh renderer: the slab (the subsurface material), an opaque box, a glass box
 * (transparent) and, with `withLight`, a light behind the slab (transmittance: the light's pass), in
 * a composer of `samples` MSAA; warmed up by the pipeline's compileAsync, or with `threeOnly` by
 * three's renderer.compileAsync(scene, camera) alone. Then frames: the first; one with each of
 * `counts` set as kernelGroups (the counts 'auto' switches between); the camera each of
 * `aways` times as far (fewer taps, 'auto' groups fewer); the slab off the screen (three's plain frame).
 * Returns the programs' cache keys after each step.
 */
async function warmedPrograms({ settings, samples = 0, counts = [], aways = [2, 4, 8, 12, 16], withLight = false, threeOnly = false, noReadBuffer = false }) {
  const { THREE, SSS, createRenderer, createComposer, buildScene, DEFAULTS } = window.lab;
  const keys = (renderer) => renderer.info.programs.map((p) => p.cacheKey);
  const renderer = createRenderer(DEFAULTS.width, DEFAULTS.height);
  renderer.shadowMap.enabled = true;
  const composer = createComposer(renderer, { samples });
  const { scene, camera, subsurface, light } = buildScene('slab', { ...DEFAULTS, pattern: 'noise' });
  light.position.set(2, 3, -10); // behind the slab: its light comes through
  light.castShadow = true;
  const box = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshStandardMaterial({ color: 0x3366cc }));
  box.position.set(2, 0, 1);
  const glass = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshPhysicalMaterial({ color: 0x88aaff, transparent: true, opacity: 0.4 }));
  glass.position.set(-2, 0, 1);
  scene.add(box, glass);
  const slab = scene.children.find((object) => object.material === subsurface[0]);
  const sss = new SSS.SubsurfaceScattering({ scene, camera, worldUnitInMm: DEFAULTS.worldUnitInMm, light: withLight ? light : null });
  sss.makeSubsurface(subsurface[0], { widthMm: 4 });
  Object.assign(sss, settings);
  composer.addPass(sss);
  if (threeOnly) await renderer.compileAsync(scene, camera);
  else await sss.compileAsync(renderer, noReadBuffer ? undefined : composer.readBuffer);
  const warmed = keys(renderer);
  composer.render();
  const first = keys(renderer);
  const firstPlan = { ...sss.plan, lightMap: sss._lightDepth?.valid ?? false };
  // Each count of groups in turn, as 'auto' switches between them when the view moves.
  const countPlans = [];
  for (const count of counts) {
    sss.kernelGroups = count;
    composer.render();
    countPlans.push(sss.plan.groups);
  }
  if (counts.length > 0) sss.kernelGroups = settings.kernelGroups;
  const counted = keys(renderer);
  // A dolly out, a frame at each distance: the taps, and 'auto''s groups, follow the scale.
  const near = camera.position.length();
  const farPlans = [];
  for (const times of aways) {
    camera.position.setLength(near * times);
    composer.render();
    farPlans.push({ blur: sss.plan.blur, groups: sss.plan.groups });
  }
  const far = keys(renderer);
  slab.position.x = 1000; // off the screen: three's own frame
  composer.render();
  const plain = keys(renderer);
  const glError = renderer.getContext().getError();
  sss.dispose();
  composer.dispose();
  renderer.dispose();
  return { warmed, first, far, plain, firstPlan: { blur: firstPlan.blur, groups: firstPlan.groups, lightMap: firstPlan.lightMap }, countPlans, counted, farPlans, glError };
}

describe('warm-up (compileAsync)', () => {
  // Every program the frames draw with compiled before the first: the first frame, frames with
  // each count of groups 'auto' may take, a dolly out (fewer taps) and a frame with the slab off
  // the screen compile none.
  const cases = [
    ['the defaults', {}, {}],
    ['MSAA 4 (the output takes the split\'s depth)', {}, { samples: 4 }],
    ['a light behind the slab (its depth pass)', {}, { withLight: true }],
    ["kernelGroups 'auto' (then each count it may switch to)", { kernelGroups: 'auto' }, { counts: [1, 2, 3, 4] }],
    ["method 'reference', debugView 'diffuse'", { method: 'reference', debugView: 'diffuse' }, {}],
    ['no read buffer given (renderer.setEffects has none at hand)', {}, { noReadBuffer: true }],
  ];
  const added = (after, before) => after.filter((key) => !before.includes(key)).map((key) => key.slice(0, 60));
  for (const [label, settings, options] of cases) {
    it(`${label}: no frame after sss.compileAsync compiles a program`, async () => {
      const r = await page.evaluate(warmedPrograms, { settings, ...options });
      expect(r.glError).toBe(0);
      expect(r.firstPlan.blur).toBe(true);
      if (options.withLight) expect(r.firstPlan.lightMap).toBe(true);
      if (settings.kernelGroups) {
        expect(r.firstPlan.groups).toBe(4);
        expect(r.countPlans).toEqual([1, 2, 3, 4]);
        expect(added(r.counted, r.warmed), 'the frames of each count compiled these').toEqual([]);
      }
      expect(added(r.first, r.warmed), 'the first frame compiled these').toEqual([]);
      expect(added(r.far, r.warmed), 'the frame further away compiled these').toEqual([]);
      expect(added(r.plain, r.warmed), 'the plain frame compiled these').toEqual([]);
    });
  }

  it('refuses what is not a WebGLRenderer, and a readBuffer that is not a render target, by name', async () => {
    const messages = await page.evaluate(() => {
      const { THREE, SSS } = window.lab;
      const sss = new SSS.SubsurfaceScattering({ scene: new THREE.Scene(), camera: new THREE.PerspectiveCamera() });
      const renderer = new THREE.WebGLRenderer();
      const refused = (...args) => { try { sss.compileAsync(...args); return null; } catch (error) { return `${error.name}: ${error.message}`; } };
      const result = [refused({}), refused(renderer, new THREE.Texture())];
      sss.dispose();
      renderer.dispose();
      return result;
    });
    expect(messages[0]).toMatch(/^TypeError: SubsurfaceScattering\.compileAsync: renderer must be a THREE\.WebGLRenderer/);
    expect(messages[1]).toMatch(/^TypeError: SubsurfaceScattering\.compileAsync: readBuffer must be a THREE\.WebGLRenderTarget or null, got /);
  });

  it("three's renderer.compileAsync(scene, camera) alone leaves the pipeline's passes (and the split's target) to the first frame", async () => {
    const r = await page.evaluate(warmedPrograms, { settings: {}, threeOnly: true });
    expect(added(r.first, r.warmed).length).toBeGreaterThanOrEqual(3); // blurH, blurV, compose at least
  });
});
