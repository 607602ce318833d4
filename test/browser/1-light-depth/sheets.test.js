// Thin things glow (issue 41): a sheet of no thickness (a leaf: one DoubleSide plane, alpha-tested)
// lit from behind shows the light that entered it, T(0) = 1 of it (docs/ARCHITECTURE.md,
// "Transmittance"), against the float64 oracle (sheetCases.js). Version 0.3 showed 1/1,700 of it at
// an angle (the fade over the first shrink took it) and, face-on to the light, none, with a warning
// that the light's near was NaN (the fit of a flat mesh).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openLabPage, closeCheckedPage, runLab } from '../../harness/page.js';
import { at } from '../../harness/images.js';
import { SHEET_WORLD_UNIT_IN_MM, expectedSheet } from './sheetCases.js';

const warnings = [];
let page;
beforeAll(async () => { page = await openLabPage(warnings); });
afterAll(async () => closeCheckedPage(page));

const SIZE = { width: 96, height: 54 };
/** The lower left quarter as the camera sees it (the sheet kept there), and the upper right (cut away). */
const KEPT = { x0: 8, x1: SIZE.width / 2 - 8, y0: 6, y1: SIZE.height / 2 - 6 };
const CUT = { x0: SIZE.width / 2 + 8, x1: SIZE.width - 8, y0: SIZE.height / 2 + 6, y1: SIZE.height - 6 };

function mean(rgba, { x0, x1, y0, y1 }) {
  const sums = [0, 0, 0];
  let n = 0;
  for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) {
    for (let c = 0; c < 3; c++) sums[c] += rgba[at(SIZE.width, x, y) + c];
    n++;
  }
  return sums.map((s) => s / n);
}

const sheet = (lightAzimuthDeg, shrinkMm = 0.6, extra = {}) => runLab(page, {
  scene: 'backlit', sheet: true, ...SIZE, worldUnitInMm: SHEET_WORLD_UNIT_IN_MM, transmittance: true, type: 'float',
  material: { shrinkMm }, reads: ['diffuse'], lightAzimuthDeg, ...extra,
});

describe('a sheet of no thickness lit from behind', () => {
  it('face-on to the light (straight behind): all the light that enters comes through, the albedo, within 1 %; no warning (0.3: none, and "near NaN")', async () => {
    const r = await sheet(0);
    const t = expectedSheet(0);
    t.forEach((v) => expect(v).toBeCloseTo(1, 9)); // white, T(0) = 1, cos 0 = 1, wrap 1
    mean(r.diffuse, KEPT).forEach((v, c) => expect(Math.abs(v / t[c] - 1), `channel ${c}: ${v}`).toBeLessThan(0.01));
    // The cut-out quarter stays a hole: nothing drawn there.
    mean(r.diffuse, CUT).forEach((v) => expect(v).toBe(0));
    expect(r.glError).toBe(0);
    expect(warnings).toEqual([]);
  });

  it('lit at 60° from behind: cos 60° of it enters, the wrap lets 0.8 out (0.4), within 2 %, whatever the shrink (0.3: 1/1,700 of shrinkMm 0)', async () => {
    const t = expectedSheet(60);
    t.forEach((v) => expect(v).toBeCloseTo(0.4, 9));
    for (const shrinkMm of [0, 0.6, 2]) {
      const r = await sheet(60, shrinkMm);
      expect(expectedSheet(60, { shrinkMm })).toEqual(t);
      mean(r.diffuse, KEPT).forEach((v, c) => expect(Math.abs(v / t[c] - 1), `shrinkMm ${shrinkMm}, channel ${c}: ${v}`).toBeLessThan(0.02));
    }
    expect(warnings).toEqual([]);
  });
});
