// Several profiles in one pipeline (makeSubsurface's `profile`): two half slabs side by side at the
// same depth, meeting at the centre column's edge (test/pages/lab.js's sideBySide), bright noisy
// skin on the left and dark noisy marble on the right. Each side must come out as a one-profile
// pipeline of its profile gives it alone, and no light may cross where they touch: the depth rule
// cannot part them there, their depths agree.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, runLab } from '../../harness/page.js';
import { at } from '../../harness/images.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

// The marble side is dark (albedo 0.05 against 1) so that light crossing from the skin shows.
const SKIN = { albedo: 1, pattern: 'noise', material: { profile: 'skin' } };
const MARBLE = { albedo: 0.05, pattern: 'noise', material: { profile: 'marble' } };
// widthMm 2 at 3 px per mm: kernels of about 26 px, well inside each 96 px half.
const frame = (sides, extra = {}) => runLab(page, { scene: 'sideBySide', sides, widthMm: 2, reads: ['output'], ...extra });

/** The largest |a − b| over RGB in columns [x0, x1) of every row. */
function worstIn(r, a, b, x0, x1) {
  let worst = 0;
  for (let y = 0; y < r.height; y++) for (let x = x0; x < x1; x++) {
    for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(a[at(r.width, x, y) + c] - b[at(r.width, x, y) + c]));
  }
  return worst;
}

describe('skin and marble in one pipeline', () => {
  let two, skinAlone, marbleAlone, seam;
  beforeAll(async () => {
    two = await frame([SKIN, MARBLE]);
    skinAlone = await frame([SKIN, null]);
    marbleAlone = await frame([null, MARBLE]);
    seam = two.width / 2;
  });

  it('blurs each side as a one-profile pipeline of its profile blurs it alone (half-float rounding)', async () => {
    expect([two.profileCount, two.surfaceChannels, two.glError]).toEqual([2, 4, 0]);
    // Whole halves, up to the seam: another profile's pixel is dropped like one off the mask.
    // 1e-3 of the lit level (about 1) is a tenth of a half float's step there; measured 0.
    expect(worstIn(two, two.output, skinAlone.output, 0, seam)).toBeLessThan(1e-3);
    expect(worstIn(two, two.output, marbleAlone.output, seam, two.width)).toBeLessThan(1e-3);
    // And each pixel took its own profile: the marble half blurred as skin differs by far more.
    const marbleAsSkin = await frame([null, { ...MARBLE, material: { profile: 'skin' } }]);
    expect(worstIn(two, marbleAsSkin.output, marbleAlone.output, seam, two.width)).toBeGreaterThan(5e-3);
  });

  it('lets no light cross where they touch at the same depth', async () => {
    // Control: both halves in one profile, the bright skin's light crosses onto the dark side
    // (measured 0.24 above the marble alone in the 8 columns next to the seam; with two profiles, 0).
    const oneProfile = await frame([SKIN, { ...MARBLE, material: { profile: 'skin' } }]);
    const near = [seam, seam + 8]; // the 8 columns next to the seam on the marble side
    expect(worstIn(two, oneProfile.output, marbleAlone.output, ...near)).toBeGreaterThan(0.1);
    expect(worstIn(two, two.output, marbleAlone.output, ...near)).toBeLessThan(1e-3);
  });

  it("gives each half its one-profile frame with method 'marginal' too (each slot's fixed-tap kernel)", async () => {
    const marginal = { sss: { method: 'marginal' } };
    const both = await frame([SKIN, MARBLE], marginal);
    expect(both.glError).toBe(0);
    expect(worstIn(two, both.output, (await frame([SKIN, null], marginal)).output, 0, seam)).toBeLessThan(1e-3);
    expect(worstIn(two, both.output, (await frame([null, MARBLE], marginal)).output, seam, two.width)).toBeLessThan(1e-3);
  });

  it("parts them with method 'reference' too (its built-in kernel on both sides)", async () => {
    const reference = { sss: { method: 'reference' } };
    const both = await frame([SKIN, MARBLE], reference);
    expect(worstIn(two, both.output, (await frame([null, MARBLE], reference)).output, seam, two.width)).toBeLessThan(1e-3);
  });

  it('with MSAA gives the same halves, and a pixel both profiles share passes no light across', async () => {
    // The seam on a pixel edge: no pixel is shared, the resolved slots are whole numbers and the
    // frame must equal the one without MSAA within half-float rounding (2e-3 of the lit level).
    const msaa = await frame([SKIN, MARBLE], { samples: 4 });
    expect(msaa.glError).toBe(0);
    expect(worstIn(two, msaa.output, two.output, 0, two.width)).toBeLessThan(2e-3);
    // The seam through the middle of a column (half a pixel, 6.27 / 192 / 2 world units): that
    // column holds both profiles, their light mixed. Uniform halves, bright skin and dark marble:
    // beyond it the marble half must stay at its own level (alone, a blurred uniform half is
    // uniform). Counting the shared column by how near its mean slot is (half, here) let 0.045 of
    // the lit level through, against the marble's own 0.058 (measured); dropping it, 0.
    const shared = { samples: 4, seamShiftWorld: 6.27 / 192 / 2 };
    const flat = (side) => ({ ...side, pattern: 'uniform' });
    const both = await frame([flat(SKIN), flat(MARBLE)], shared);
    const alone = await frame([null, flat(MARBLE)], shared);
    expect(worstIn(two, both.output, alone.output, seam + 1, seam + 8)).toBeLessThan(2e-4);
  });

  it('with MSAA and three profiles, a pixel slots 0 and 2 share sends no light into slot 1 (their mean slot)', async () => {
    // Skin (slot 0) and marble (slot 2) over the upper half, their seam through a column's middle;
    // a dark milk band (slot 1) over the lower half. The shared column's mean slot is 1, milk's;
    // only its spread (the slot's square in the surface's alpha) tells it from milk. The band's
    // rows next to it must stay as the band alone gives them.
    const MILK = { albedo: 0.05, pattern: 'uniform', material: { profile: 'milk' } };
    const shared = { samples: 4, seamShiftWorld: 6.27 / 192 / 2, band: MILK };
    const flat = (side) => ({ ...side, pattern: 'uniform' });
    const three = await frame([flat(SKIN), flat(MARBLE)], shared);
    const bandAlone = await frame([null, null], shared);
    expect([three.profileCount, three.glError]).toEqual([3, 0]);
    // The band's top rows (y < 54 is the lower half in read-back rows), the columns around the seam.
    let worst = 0;
    for (let y = 44; y < 54; y++) for (let x = seam - 3; x < seam + 4; x++) {
      for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(three.output[at(three.width, x, y) + c] - bandAlone.output[at(three.width, x, y) + c]));
    }
    expect(worst).toBeLessThan(2e-4);
  });

  it("shines through with the material's own profile (its transmittance table)", async () => {
    // A 3 mm slab lit from behind: the transmitted light is T(thickness) of the material's profile.
    // A 64-texel light depth map is plenty for a flat slab.
    const backlit = (sss, material = {}) => runLab(page, {
      scene: 'backlit', thicknessMm: 3, transmittance: true, reads: ['output'], sss: { lightDepthSize: 64, ...sss }, material,
    });
    const named = await backlit({}, { profile: 'marble' });
    const byPipeline = await backlit({ profile: 'marble' });
    const skin = await backlit({});
    expect(worstIn(named, named.output, byPipeline.output, 0, named.width)).toBe(0);
    expect(worstIn(named, named.output, skin.output, 0, named.width)).toBeGreaterThan(0.01); // measured 0.086
  });

  it('keeps a frame of one profile as before: PROFILE_COUNT 1, a two-channel surface, the same pixels whichever way the profile is named', async () => {
    expect([skinAlone.profileCount, skinAlone.surfaceChannels, marbleAlone.profileCount, marbleAlone.surfaceChannels]).toEqual([1, 2, 1, 2]);
    // The marble half named by its material (the pipeline's profile skin) and by the pipeline.
    const byPipeline = await frame([null, { ...MARBLE, material: {} }], { sss: { profile: 'marble' } });
    expect(worstIn(two, byPipeline.output, marbleAlone.output, 0, two.width)).toBe(0);
  });
});
