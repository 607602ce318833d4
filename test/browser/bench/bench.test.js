// The bench's side-by-side (bench/peers.js) is only a comparison if its parts are what they claim:
// Babylon.js must draw the same head, view and light as three.js (its plain frame against
// three's), its SSS must change the image, and the blur's floor must be a 17-tap box filter of
// the diffuse light over the subsurface pixels (against that filter computed here).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';

let page;
beforeAll(async () => {
  page = await openPage('/bench/index.html');
  await page.evaluate(() => window.bench.open({ scene: 'head', width: 320, height: 180 }));
});
afterAll(async () => {
  await page.evaluate(() => window.bench.close());
  expect(page.problems).toEqual([]);
  await page.close();
});

describe('the bench side-by-side', () => {
  it('Babylon.js draws the head where three.js does, as bright, and its SSS changes it', async () => {
    const r = await page.evaluate(async () => {
      const { plain, withSss, sssChange } = await window.bench.peerImages();
      return { plain, withSss, sssChange };
    });
    if (r.plain.silhouetteIoU === undefined) throw new Error('no images');
    // A camera or handedness mistake moves or mirrors the head (an IoU far below 0.9); a light
    // mistake changes the mean luma by tens of percent.
    expect(r.plain.silhouetteIoU).toBeGreaterThan(0.95);
    expect(Math.abs(r.plain.lumaRatio - 1)).toBeLessThan(0.05);
    expect(r.withSss.silhouetteIoU).toBeGreaterThan(0.95);
    // Both scatterings soften the skin: the mean luma over the head moves (not 0: the SSS ran). At
    // 320×180 ours moves it by about 0.14 steps of 8 bits (a kernel of 2 px); Babylon's by about 6.5
    // (its 40 samples spread over the profile's 99.7 % radius, and its background goes through its
    // image processing); before its post-process had compiled, Babylon's moved it by 0.
    expect(r.sssChange.three).toBeGreaterThan(0.05);
    expect(r.sssChange.babylon).toBeGreaterThan(1);
  }, 240_000);

  it('the floor is the 17-tap box filter of the diffuse light, horizontally then vertically, on subsurface pixels only', async () => {
    const r = await evaluateFloats(page, () => window.bench.peerFloorImages());
    const { width: W, height: H, diffuse, horizontal, output } = r;
    const at = (x, y) => (y * W + x) * 4;
    const clampX = (x) => Math.min(Math.max(x, 0), W - 1);
    const clampY = (y) => Math.min(Math.max(y, 0), H - 1);
    // The oracle: a box of 17 along x over the diffuse attachment (edge texels repeated), then along y.
    let worstH = 0, worstV = 0, covered = 0, untouched = 0;
    const expectedH = new Float64Array(W * H * 4);
    for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) {
      const i = at(x, y);
      if (!(diffuse[i + 3] > 0)) { for (let c = 0; c < 4; c++) expectedH[i + c] = diffuse[i + c]; continue; }
      for (let c = 0; c < 3; c++) {
        let sum = 0;
        for (let k = -8; k <= 8; k++) sum += diffuse[at(clampX(x + k), y) + c];
        expectedH[i + c] = sum / 17;
      }
      expectedH[i + 3] = diffuse[i + 3];
    }
    for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) {
      const i = at(x, y);
      for (let c = 0; c < 3; c++) worstH = Math.max(worstH, Math.abs(horizontal[i + c] - expectedH[i + c]) / Math.max(1e-3, Math.abs(expectedH[i + c])));
      if (!(horizontal[i + 3] > 0)) {
        if (output[i] === horizontal[i] && output[i + 1] === horizontal[i + 1]) untouched++;
        continue;
      }
      covered++;
      for (let c = 0; c < 3; c++) {
        let sum = 0;
        for (let k = -8; k <= 8; k++) sum += horizontal[at(x, clampY(y + k)) + c];
        worstV = Math.max(worstV, Math.abs(output[i + c] - sum / 17) / Math.max(1e-3, sum / 17));
      }
    }
    expect(covered).toBeGreaterThan(1000); // the head covers part of the image
    expect(untouched).toBeGreaterThan(1000); // the background passes through
    // Half-float targets: 2^-11 relative per value, a few roundings.
    expect(worstH).toBeLessThan(3e-3);
    expect(worstV).toBeLessThan(3e-3);
  }, 240_000);

  it('every peer measure gives one finite time per frame', async () => {
    const r = await page.evaluate(async () => {
      const out = {};
      for (const measure of ['threePlain', 'ours', 'babylonPlain', 'babylonSss', 'blur', 'floor']) {
        out[measure] = (await window.bench.peerMeasure({ measure, frames: 2, warmUp: 1 }))[measure];
      }
      out.stages = await window.bench.peerMeasure({ measure: 'stages', frames: 1 });
      out.msaa = await window.bench.peerMeasure({ measure: 'stages', frames: 1, feature: 'msaa4' });
      out.coverage = await window.bench.peerCoverage();
      return out;
    });
    for (const measure of ['threePlain', 'ours', 'babylonPlain', 'babylonSss', 'blur', 'floor']) {
      expect(r[measure], measure).toHaveLength(2);
      for (const ms of r[measure]) expect(ms, measure).toBeGreaterThan(0);
    }
    expect(r.stages.scene[0]).toBeGreaterThan(0);
    expect(r.stages.blurH[0]).toBeGreaterThan(0);
    expect(r.msaa.scene[0]).toBeGreaterThan(0);
    // The head is lit from the camera's side: its light depth pass is skipped.
    expect(r.stages.lightDepth).toEqual([]);
    // The cost model's inputs: the head covers part of the frame, its screen box more, not all of it.
    const { pixels, subsurfacePixels, boxPixels, taps } = r.coverage;
    expect(subsurfacePixels).toBeGreaterThan(0.05 * pixels);
    expect(boxPixels).toBeGreaterThan(subsurfacePixels);
    expect(boxPixels).toBeLessThan(pixels);
    expect(taps.mean).toBeGreaterThan(1);
  }, 240_000);
});
