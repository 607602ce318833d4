// The bench's cost model (bench/costModel.js) against sums worked out by hand from the formats
// (RGBA16F 8 B, RG32F 8 B, 24-bit depth 4 B) and the passes, and the issue's ratios
// (bench/costReport.js) against rounds made up for the test.
import { describe, it, expect } from 'vitest';
import { AFTER, BEFORE, NOT_BUILT, ISOTROPIC, TEXEL_BYTES, frameTraffic, targetMemory } from '../../../bench/costModel.js';
import { issueRatios, msaaRatio } from '../../../bench/costReport.js';

describe('cost model', () => {
  it('targets at 1920×1080: RGBA16F + RGBA32F (the depth carried) + RG32F + depth in the multi-target, RGBA32F + RGBA16F for the blur, 2 × RGBA32UI for its groups', () => {
    const pixels = 1920 * 1080;
    expect(targetMemory(1920, 1080).bytes).toBe(pixels * (8 + 16 + 8 + 4 + 16 + 8 + 32));
    expect(targetMemory(1920, 1080, { groups: false }).bytes).toBe(pixels * (8 + 16 + 8 + 4 + 16 + 8));
    expect(targetMemory(1920, 1080, { groups: false, carriesDepth: false }).bytes).toBe(pixels * (8 + 8 + 8 + 4 + 8 + 8));
    // MSAA 4: a 4-sample renderbuffer per multi-target attachment besides its resolved texture; the
    // diffuse holds the coverage then (half float), the horizontal blur still carries the depth.
    expect(targetMemory(1920, 1080, { samples: 4 }).bytes).toBe(pixels * ((8 + 8 + 8 + 4) * 5 + 16 + 8 + 32));
    expect(TEXEL_BYTES.rg32f).toBe(8);
  });

  it('an empty frame: only the clears, the blur passes\' centres and the compose', () => {
    const t = frameTraffic(BEFORE, { subsurface: 0, box: 0, taps: 11 });
    expect(t.scene).toEqual({ written: 28, read: 0, fetched: 0, fetches: 0 });
    expect(t.blurH).toEqual({ written: 8, read: 16, fetched: 16, fetches: 2 }); // the centre's light and surface
    expect(t.compose).toEqual({ written: 12, read: 20, fetched: 20, fetches: 3 }); // depth, colour, diffuse
    // Scissored to an empty box the blur passes cost nothing.
    const after = frameTraffic(AFTER, { subsurface: 0, box: 0, taps: 11 });
    expect(after.blurH).toEqual({ written: 0, read: 0, fetched: 0, fetches: 0 });
    expect(after.scene.written).toBe(8 + 16 + 8 + 4); // the diffuse attachment RGBA32F (it carries the depth)
    expect(after.compose.read).toBe(4 + 8); // depth, colour; the mask from the scattered light, in the (empty) box
    expect(after.total.written).toBe(36 + 12);
  });

  it('a mask pixel: the split writes 28 B, a blur tap fetches two texels of diffuse and surface', () => {
    const s = 0.25;
    const t = frameTraffic(BEFORE, { subsurface: s, box: 0.5, taps: 9 });
    // Scene: clears 28, prepass depth 4 (write) + 4 (test), split depth 4 + 4, colour, diffuse, surface 24.
    expect(t.scene.written).toBeCloseTo(28 + s * (4 + 4 + 24), 12);
    expect(t.scene.read).toBeCloseTo(s * (4 + 4), 12);
    // Fetched per mask pixel: centre 16, slope 2 × 8, 9 taps (the centre and 8 others) → 8 × 2 texels × 16.
    expect(t.blurV.fetched).toBeCloseTo(16 + s * (16 + 8 * 2 * 16), 12);
    const after = frameTraffic(AFTER, { subsurface: s, box: 0.5, taps: 9 });
    // After: clears 36 (the diffuse RGBA32F), no prepass; split depth 4 + 4, colour 8, diffuse 16, surface 8.
    expect(after.scene.written).toBeCloseTo(36 + s * (4 + 8 + 16 + 8), 12);
    expect(after.blurH.written).toBeCloseTo(0.5 * 16, 12); // the box only, RGBA32F (the depth carried)
    // Centre 16 + 8, slope 2 × 8, 8 taps × 2 texels × 16 (light and depth in one texel).
    expect(after.blurH.fetched).toBeCloseTo(0.5 * 24 + s * (16 + 8 * 2 * 16), 12);
    // The vertical taps fetch the carried light alone (16 B), the centre its light and surface.
    expect(after.blurV.fetched).toBeCloseTo(0.5 * 24 + s * (16 + 8 * 2 * 16), 12);
    // Without the depth carried (the two float layouts' extra bytes), after moves less than before.
    const apart = frameTraffic({ ...AFTER, lightCarriesDepth: false, diffuseCarriesDepth: false }, { subsurface: s, box: 0.5, taps: 9 });
    expect(apart.total.written + apart.total.read).toBeLessThan(t.total.written + t.total.read);
  });

  it('the isotropic groups: the horizontal pass writes 32 B (two RGBA32UI), the vertical one reads 32 B of light per texel and, with the depth in their alphas, no surface', () => {
    const s = 0.25;
    const scene = { subsurface: s, box: 0.5, taps: 9 };
    const grouped = frameTraffic(ISOTROPIC, scene);
    const one = frameTraffic(AFTER, scene);
    expect(grouped.blurH.written).toBeCloseTo(0.5 * 32, 12);
    expect(grouped.blurH.fetched).toBeCloseTo(one.blurH.fetched, 12); // it reads the diffuse light as before
    // Vertical: centre 32 + 8, slope 2 × 8, 8 taps × 2 texels × 32 (the groups carry the depth:
    // no surface per tap); fetch instructions: centre 3 (two attachments, the surface), slope 2,
    // 16 texels × 2 attachments, tables 12 (profile, footprints) + 6 (fractions: centre, near
    // count, 4 footprints).
    expect(grouped.blurV.fetched).toBeCloseTo(0.5 * 40 + s * (16 + 8 * 2 * 32), 12);
    expect(grouped.blurV.fetches).toBeCloseTo(0.5 * 3 + s * (2 + 16 * 2 + 12 + 6), 12);
    expect(grouped.blurH.fetches - one.blurH.fetches).toBeCloseTo(s * 6, 12); // the fractions
    expect(grouped.blurV.written).toBe(one.blurV.written);
    // Without it (as before): a surface texel more per tap texel.
    const surfaceRead = frameTraffic({ ...ISOTROPIC, groupsCarryDepth: false }, scene);
    expect(surfaceRead.blurV.fetched).toBeCloseTo(0.5 * 40 + s * (16 + 8 * 2 * 40), 12);
    expect(surfaceRead.blurV.fetches - grouped.blurV.fetches).toBeCloseTo(s * 16, 12);
  });

  it('the depth carried in the light: the same bytes a vertical tap reads, in one fetch instead of two; 8 B more written and read per box pixel', () => {
    const s = 0.25;
    const scene = { subsurface: s, box: 0.5, taps: 9 };
    const carried = frameTraffic(AFTER, scene);
    const apart = frameTraffic({ ...AFTER, lightCarriesDepth: false }, scene);
    expect(carried.blurH.written - apart.blurH.written).toBeCloseTo(0.5 * 8, 12);
    expect(carried.blurV.read - apart.blurV.read).toBeCloseTo(0.5 * 8, 12);
    expect(carried.blurV.fetched - apart.blurV.fetched).toBeCloseTo(0.5 * 8, 12); // per tap 16 B either way
    expect(carried.blurH.fetched).toBeCloseTo(apart.blurH.fetched, 12);
    // Fetches, counted: 1 per vertical tap texel instead of 2 (light and surface).
    expect(apart.blurV.fetched - 0.5 * 16).toBeCloseTo(s * (16 + 16 * 16), 12);
    // Instructions: centre 2 and slope 2, 16 tap texels × 2 (apart) or × 1 (carried), the tables
    // 3 × 4 footprints (the centre's two profile texels, none for the tail).
    expect(apart.blurV.fetches).toBeCloseTo(0.5 * 2 + s * (2 + 32 + 12), 12);
    expect(carried.blurV.fetches).toBeCloseTo(0.5 * 2 + s * (2 + 16 + 12), 12);
  });

  it('the depth carried in the diffuse attachment: 8 B more cleared, written and read for the mask; the horizontal taps fetch the same bytes in one texel', () => {
    const s = 0.25;
    const scene = { subsurface: s, box: 0.5, taps: 9 };
    const carried = frameTraffic(AFTER, scene);
    const apart = frameTraffic({ ...AFTER, diffuseCarriesDepth: false }, scene);
    expect(carried.scene.written - apart.scene.written).toBeCloseTo(8 + 8 * s, 12);
    const composeApart = (d) => frameTraffic({ ...AFTER, diffuseCarriesDepth: d, composeMaskFromScattered: false }, scene).compose.read;
    expect(composeApart(true) - composeApart(false)).toBeCloseTo(8, 12); // the diffuse read for the mask
    expect(carried.compose.read).toBeCloseTo(apart.compose.read, 12); // not read with the mask from the scattered light
    expect(carried.blurH.read - apart.blurH.read).toBeCloseTo(0.5 * 8, 12); // the centre's light
    expect(carried.blurH.fetched - apart.blurH.fetched).toBeCloseTo(0.5 * 8, 12); // per tap 16 B either way
    expect(carried.blurV).toEqual(apart.blurV);
  });

  it('the compose\'s mask from the scattered light: 8 B in the box instead of the diffuse everywhere and the scattered light on the mask', () => {
    const s = 0.25;
    const scene = { subsurface: s, box: 0.5, taps: 9 };
    const fromScattered = frameTraffic(AFTER, scene).compose;
    const fromDiffuse = frameTraffic({ ...AFTER, composeMaskFromScattered: false }, scene).compose;
    expect(fromScattered.read).toBeCloseTo(4 + 8 + 0.5 * 8, 12);
    expect(fromDiffuse.read).toBeCloseTo(4 + 8 + 16 + s * 8, 12);
    expect(fromScattered.written).toBe(fromDiffuse.written);
  });

  it('taps on a texel centre fetch one texel with skipsEmptyTexels (after), two without (before); memory traffic unchanged', () => {
    const s = 0.25;
    const scene = { subsurface: s, box: 0.5, taps: 9, centred: 4 };
    const before = frameTraffic(BEFORE, scene);
    const after = frameTraffic(AFTER, scene);
    expect(before.blurH.fetched).toBeCloseTo(16 + s * (16 + 8 * 2 * 16), 12); // the box is not confined before
    expect(after.blurH.fetched).toBeCloseTo(0.5 * 24 + s * (16 + (8 * 2 - 4) * 16), 12);
    expect(after.blurV.read).toBeCloseTo(frameTraffic(AFTER, { ...scene, centred: 0 }).blurV.read, 12);
  });

  it('the directions not built: no surface attachment saves its 8 B clear; the compose in the blur its pass', () => {
    const scene = { subsurface: 0, box: 0.5, taps: 9 };
    const after = frameTraffic(AFTER, scene);
    expect(after.scene.written - frameTraffic(NOT_BUILT.surfaceFromDepth, scene).scene.written).toBe(8);
    expect(frameTraffic(NOT_BUILT.surfaceFromDepth, scene).blurH.read).toBeCloseTo(0.5 * (16 + 4), 12); // the carried light 16 B, depth 4 B
    const folded = frameTraffic(NOT_BUILT.composeInBlur, scene);
    expect(folded.compose).toEqual({ written: 0, read: 0, fetched: 0, fetches: 0 });
    // The vertical pass over the whole frame: centre 24 (the carried light 16, surface 8) + colour 8 + depth 4 read, colour + depth out.
    expect(folded.blurV).toEqual({ written: 12, read: 36, fetched: 36, fetches: 4 });
  });
});

describe('issue 19 ratios', () => {
  const round = (k) => ({
    none: { stages: { scene: 10, blurH: 5 }, threePlain: { timerMs: 10 } },
    msaa4: { stages: { scene: 10 + 2 * k, blurH: 5 }, threePlain: { timerMs: 10 + k } },
  });

  it('MSAA: ours added over the plain frame added, per round, then median and range', () => {
    expect(msaaRatio([round(1), round(2), round(4)])).toMatchObject({ median: 2, min: 2, max: 2 });
    expect(msaaRatio(undefined)).toBeNull();
  });

  it('the four ratios of a peers entry', () => {
    const entry = {
      summary: { overhead: { timer: { ratio: { median: 0.8 } } }, nonBlurShare: { median: 1.2 }, blurOverFloor: { timer: { median: 3 } } },
      features: [round(1)],
    };
    const r = issueRatios(entry);
    expect(r.overhead.median).toBe(0.8);
    expect(r.nonBlur.median).toBe(1.2);
    expect(r.blurOverFloor.median).toBe(3);
    expect(r.msaa.median).toBe(2);
  });
});
