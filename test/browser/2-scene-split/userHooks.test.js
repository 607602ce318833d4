// The user's shader hooks, in the pipeline (issue 41; test/pages/leaves.js): two leaves swaying in
// the wind through onBeforeCompile hooks of their own, set before or after makeSubsurface, are drawn
// and seen by the light as the same bends made in plain three.js geometry are; copies of a
// subsurface material scatter as it does; a hook that takes out a point the split goes in at leaves
// its material drawn as three draws it, named once. Version 0.3: the light's map held the unswayed
// leaves, a hook set after makeSubsurface dropped the split (INVALID_OPERATION every frame), two
// hooks shared one program, removeSubsurface put back the hook it found first, and copies rendered
// as plain three without a word.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openLabPage, closeCheckedPage, evaluateFloats } from '../../harness/page.js';
import { at } from '../../harness/images.js';

const warnings = [];
let page;
beforeAll(async () => { page = await openLabPage(warnings); });
afterAll(async () => closeCheckedPage(page));

/** Pixels of the left and right halves (rows bottom-up) where `a` and `b` differ by more than `tolerance` in some channel, and `a`'s mean red there. */
function compareHalves(r, a, b, tolerance) {
  const halves = [{ differ: 0, sum: 0, n: 0 }, { differ: 0, sum: 0, n: 0 }];
  for (let y = 0; y < r.height; y++) for (let x = 0; x < r.width; x++) {
    const half = halves[x < r.width / 2 ? 0 : 1];
    const i = at(r.width, x, y);
    if ([0, 1, 2].some((c) => Math.abs(a[i + c] - b[i + c]) > tolerance)) half.differ++;
    if (a[i + 3] !== 0) { half.sum += a[i]; half.n++; }
  }
  return halves.map(({ differ, sum, n }) => ({ differ, meanLit: sum / n, covered: n }));
}

describe("the user's hooks, in the pipeline", () => {
  it('two leaves swaying through hooks of their own, set before and after makeSubsurface: drawn and seen by the light as the same bends in plain geometry; removed and made again, the same', async () => {
    const r = await evaluateFloats(page, () => window.lab.swayingLeaves({ remake: true }));
    expect(r.glError).toBe(0); // 0.3: INVALID_OPERATION every frame for the hook set after
    expect(r.problems).toEqual([]);
    for (const [name, image] of [['hooked', r.hooked], ['remade', r.remade]]) {
      const halves = compareHalves(r, image, r.truth, 2e-3);
      halves.forEach(({ differ, meanLit, covered }, side) => {
        expect(covered, `${name}, leaf ${'ab'[side]}: drawn`).toBeGreaterThan(400);
        expect(meanLit, `${name}, leaf ${'ab'[side]}: it glows`).toBeGreaterThan(0.5); // straight behind: about the albedo where it faces the light
        expect(differ, `${name}, leaf ${'ab'[side]}: pixels unlike the geometry's bend`).toBe(0);
      });
    }
  });
});

describe('copies of a subsurface material', () => {
  it('a clone (tinted) and a .copy() scatter as the original, with its options, from the frame that meets them; removed with it; a leaf marked by another page is named once', async () => {
    const r = await evaluateFloats(page, () => window.lab.leafCopies());
    expect(r.glError).toBe(0);
    /** The mean diffuse light (red) and coverage of the leaf at column `col`, row `row` (upper 0). */
    const pixelsPerUnit = r.height / 2 / (8 * Math.tan(Math.PI / 12)); // the leaves' plane, 8 units from the camera (fov 30°)
    const leafMean = (image, col, row) => {
      const cx = Math.round(r.width / 2 + (col - 1) * 1.2 * pixelsPerUnit - 0.5);
      const cy = Math.round(r.height / 2 + (row === 0 ? 0.6 : -0.6) * pixelsPerUnit - 0.5);
      let sum = 0;
      let n = 0;
      for (let y = cy - 3; y <= cy + 3; y++) for (let x = cx - 3; x <= cx + 3; x++) { sum += image[at(r.width, x, y)]; n++; }
      return sum / n;
    };
    for (const image of [r.first, r.second]) {
      expect(leafMean(image, 0, 0)).toBeGreaterThan(0.9); // the original: white, straight behind
      expect(leafMean(image, 1, 0) / leafMean(image, 0, 1)).toBeCloseTo(1, 2); // the clone as its explicit twin
      expect(leafMean(image, 0, 1)).toBeGreaterThan(0.45);
      expect(leafMean(image, 2, 0) / leafMean(image, 0, 0)).toBeCloseTo(1, 2); // the copy as the original
      expect(leafMean(image, 1, 1)).toBe(0); // the stranger: drawn as three draws it, no diffuse light of ours
    }
    expect(r.materials).toBe(4); // original, twin, and the two copies the frame bound
    const stranger = 'material "Stranger" carries the subsurface mark of a material this page never made subsurface (a scene loaded from JSON, or a material since collected), so it is drawn as three draws it: make it subsurface with makeSubsurface';
    expect(r.firstProblems).toEqual([stranger]);
    expect(r.problems).toEqual([stranger]);
    expect(warnings.filter((w) => w.includes('Stranger'))).toHaveLength(1);
    // The original removed, its copies follow it: no light of ours on them; the twin stays.
    expect(leafMean(r.removed, 1, 0)).toBe(0);
    expect(leafMean(r.removed, 2, 0)).toBe(0);
    expect(leafMean(r.removed, 0, 1)).toBeGreaterThan(0.45);
    expect(r.materialsAfter).toBe(1);
  });
});

describe("a hook that cannot be composed", () => {
  it("a hook that inlines a chunk the split goes in at: the leaf is drawn as three draws it, no GL error, named once", async () => {
    warnings.length = 0;
    const r = await evaluateFloats(page, () => window.lab.uncomposedLeaf());
    expect(r.glError).toBe(0);
    let worst = 0;
    let lit = 0;
    for (let i = 0; i < r.output.length; i += 4) {
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(r.output[i + c] - r.three[i + c]));
      if (r.three[i] > 0.05) lit++;
    }
    expect(lit).toBeGreaterThan(400); // the leaf, 25 pixels across
    expect(worst).toBeLessThan(1e-3);
    const message = 'material "Inlined": its onBeforeCompile takes "#include <lights_fragment_end>" out of three\'s fragment shader, where the subsurface split goes in, so it is drawn as three draws it, without scattering or transmittance';
    expect(r.problems).toEqual([message]);
    expect(warnings).toEqual([`SubsurfaceScattering: ${message}`]);
  });

  it("a hook that throws on the light's depth shader (it reads a uniform of three's shader): the mesh is drawn, named once, seen by the light unmoved", async () => {
    warnings.length = 0;
    const r = await evaluateFloats(page, () => window.lab.throwingHookLeaf());
    expect(r.glError).toBe(0);
    const message = 'material "Tinted": its onBeforeCompile throws on the light\'s depth shader (Cannot read properties of undefined (reading \'value\')), so the light sees its mesh unmoved by it';
    expect(r.problems).toEqual([message]);
    expect(warnings).toEqual([`SubsurfaceScattering: ${message}`]);
    let lit = 0;
    for (let i = 0; i < r.diffuse.length; i += 4) if (r.diffuse[i + 3] !== 0) lit++;
    expect(lit).toBeGreaterThan(400); // drawn by the camera, its own hook and all
  });
});
