// Three's scene graph, feature by feature (the matrix of docs/TESTING.md, "The scene graph"): for
// each feature that changes what three draws or where, the pipeline with scattering and
// transmittance off equals three's RenderPass; on, it scatters and transmits as the same picture
// drawn without the feature does (the reference the accuracy and transmittance tests hold to
// their oracles); and its cost follows what is on the screen: a frame without a subsurface pixel
// on it is three's frame, draw call for draw call, with no light depth pass; with one, the light's
// pass draws the subsurface mesh and what three's frustum test cannot part from it, not the
// scene. Scenes: test/pages/sceneGraph.js (96 × 64, a 2 mm slab 1 m away, back-lit by a spot).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, closeCheckedPage } from '../harness/page.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/sceneGraph.html'); });
afterAll(() => closeCheckedPage(page));

const row = (name, options) => page.evaluate((n, o) => window.sceneGraph.row(n, o), name, options);

/** Within half-float rounding of the reference's largest value. */
const within = (comparison, relative = 2e-3) => comparison.worst <= relative * Math.max(1, comparison.level);

/** What every row holds: no GL error, no NaN, and off equal to three's RenderPass. */
function expectOffAsThree(r) {
  expect(r.off.glError).toBe(0);
  expect(r.on.glError).toBe(0);
  expect(r.offVsPlain.nonFinite + r.onVsOff.nonFinite).toBe(0);
  expect(within(r.offVsPlain), JSON.stringify(r.offVsPlain)).toBe(true);
}

/** A row whose subsurface mesh is on the screen: it scatters and transmits; the light's pass draws it, not the boxes. */
function expectOnScreenCost(r, subsurfaceDraws = 1) {
  expect(r.on.subsurfaceOnScreen).toBeGreaterThan(0);
  expect(r.onVsOff.differing).toBeGreaterThan(100); // scattered and transmitted: hundreds of the slab's 784 px
  expect(r.on.lightPasses).toBe(1);
  expect(r.on.lightCalls).toBeLessThanOrEqual(subsurfaceDraws + 1); // the slab(s), and the floor three's sphere test keeps
  // The rest of the pipeline's draws: the split's call 2 (each subsurface draw), the two blur passes and the compose.
  expect(r.on.calls - r.plain.calls).toBe(subsurfaceDraws + r.on.lightCalls + 3);
}

describe('three\'s scene graph: off, as three; on, as the same picture without the feature; costs what is on the screen', () => {
  for (const name of ['visible', 'behindCamera', 'turnedAway']) {
    it(`${name}: no subsurface mesh on the screen, so the frame is three's own, draw call for draw call, with no light depth pass`, async () => {
      const r = await row(name);
      expectOffAsThree(r);
      expect(r.on.subsurfaceOnScreen).toBe(0);
      expect(r.onVsOff.worst).toBe(0);
      expect(r.on.calls).toBe(r.plain.calls);
      expect(r.on.lightPasses).toBe(0);
      expect(r.on.plan.blur).toBe(false);
    });
  }

  const equivalent = {
    frustumCulledFalse: 'frustumCulled false on the on-screen mesh: as culled',
    cameraLayers: 'the subsurface mesh on layer 1 of a camera seeing 0 and 1: as on layer 0, transmittance included',
    renderOrder: 'renderOrder reversed: as the default order',
    instancedMesh: 'an InstancedMesh with a colour per instance: as separate meshes',
    batchedMesh: 'a BatchedMesh: as separate meshes',
    morphTargets: 'morph targets: as the shape baked',
    skinning: 'a skinned mesh: as its pose baked',
    clones: 'a mesh and its clone (one material): as two meshes',
    side: 'side DoubleSide: as FrontSide',
    lod: 'an LOD, the light in another level\'s range: the camera\'s level, as that mesh alone, no GL error',
    logarithmicDepth: 'a logarithmic depth buffer: as the plain one',
    reversedDepth: 'a reversed depth buffer: as the plain one',
  };
  for (const [name, title] of Object.entries(equivalent)) {
    it(title, async () => {
      const r = await row(name);
      expectOffAsThree(r);
      expect(within(r.onVsReference), JSON.stringify(r.onVsReference)).toBe(true);
      expectOnScreenCost(r, ['renderOrder', 'clones'].includes(name) ? 2 : 1);
      expect(r.on.problems).toEqual([]);
    });
  }

  it('the light\'s shadow camera on layer 2 only: its pass leaves the mesh on layer 0 out (three\'s shadow rule), so it scatters without transmittance', async () => {
    const r = await row('lightLayers');
    expectOffAsThree(r);
    expect(within(r.onVsReference), JSON.stringify(r.onVsReference)).toBe(true); // the reference: transmittance off
    expect(r.on.lightPasses).toBe(0);
    expect(r.onVsOff.differing).toBeGreaterThan(100); // scattered
  });

  for (const name of ['alphaTest', 'alphaHash']) {
    it(`${name}: the cut-out half is as a plane of the kept half (the light's map too), within 5 % of the lit level along the cut`, async () => {
      const r = await row(name);
      expectOffAsThree(r);
      expect(r.onVsReference.worst).toBeLessThan(0.05 * r.onVsReference.level);
      // Only along the cut: the light's map, fitted to each mesh, holds the edge on other texels.
      expect(r.onVsReference.where.every(([x]) => x >= 44 && x <= 48), JSON.stringify(r.onVsReference.where)).toBe(true);
      expectOnScreenCost(r);
    });
  }

  it('a transparent subsurface material is drawn as three draws it (blended, unscattered), said once per material', async () => {
    const r = await row('transparent');
    expectOffAsThree(r);
    expect(r.onVsOff.worst).toBe(0);
    expect(r.on.calls).toBe(r.plain.calls);
    expect(r.warnings.filter((w) => /is transparent, so it is blended over the scattered image without scattering/.test(w))).toHaveLength(2); // its material in each of two scenes
  });

  it('an orthographic camera: as a perspective camera 40 m away at the same scale (nearly parallel), within 1 % of the lit level', async () => {
    const r = await row('orthographicCamera');
    expectOffAsThree(r);
    expect(r.onVsReference.worst).toBeLessThan(0.01 * r.onVsReference.level);
    expect(r.onVsOff.differing).toBeGreaterThan(100);
  });

  it('fog: the scattered frame fogged as three fogs it (the unfogged frame mixed towards the fog colour by the fog factor)', async () => {
    const r = await row('fog');
    expectOffAsThree(r);
    const f = await page.evaluate(() => window.sceneGraph.fogRow());
    expect(f.compared).toBeGreaterThan(500);
    expect(f.factor).toBeGreaterThan(0.3);
    expect(f.worst, JSON.stringify(f)).toBeLessThan(2e-3 * Math.max(1, f.level));
  });

  it('pixel ratio 2 at half the size: the frame of pixel ratio 1 at the full size', async () => {
    const r = await page.evaluate(() => window.sceneGraph.pixelRatioRow());
    expect(r.sizes).toEqual([[96, 64], [96, 64]]);
    expect(r.worst).toBe(0);
  });

  it('a second camera in the frame (a minimap drawn by three between the frames): the pipeline\'s frame unchanged, the minimap three\'s own', async () => {
    const r = await page.evaluate(() => window.sceneGraph.secondCameraRow());
    expect(r.glError).toBe(0);
    expect(r.frame.worst).toBe(0);
    expect(r.minimap.worst).toBe(0);
  });
});
