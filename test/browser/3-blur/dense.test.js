// The dense 2D reference (DenseSubsurfacePass) on the GPU against the float64 oracle
// (denseConvolutionOracle): same pixel energies, radius, mask and depth rules. Small images of the
// bench's scenes (bench/scenes.js, through bench/lab.js) with wide kernels, float targets.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';
import { rgb, channel } from '../../harness/images.js';
import { denseConvolutionOracle, surfaceSlopeOracle } from '../../oracle/convolution.js';
import { getProfile } from '../../../src/profiles/presets.js';
import { MAX_SLOPE } from '../../../src/3-blur/samplingModel.js';

const W = 96;
const H = 54;

let page;
beforeAll(async () => { page = await openPage('/bench/index.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.evaluate(() => window.bench.close());
  await page.close();
});

/** Renders `scene` through the dense pass (`options`: readDense's) at W × H with float targets. */
async function renderDense({ scene, widthMm, tiltDeg, ...options }) {
  await page.evaluate((o) => window.bench.open(o), { scene, width: W, height: H, float: true, widthMm, tiltDeg });
  return evaluateFloats(page, (o) => window.bench.readDense(o), options);
}

/** denseAgainstOracle's results by its arguments: a case that needs one already run reads it (the oracle is most of the cost). */
const againstOracle = new Map();

/**
 * Renders `scene` through the dense pass without the grazing-angle correction (the oracle's model)
 * and the oracle; returns the worst difference and more.
 */
function denseAgainstOracle({ scene, profile, widthMm, followSurface = 'drop' }) {
  const key = JSON.stringify([scene, profile, widthMm, followSurface]);
  if (!againstOracle.has(key)) againstOracle.set(key, renderAgainstOracle({ scene, profile, widthMm, followSurface }));
  return againstOracle.get(key);
}

async function renderAgainstOracle({ scene, profile, widthMm, followSurface }) {
  const r = await renderDense({ scene, widthMm, profile, followSurface, foreshortening: false });
  const depth = channel(r.surface, 0);
  const widthWorld = channel(r.surface, 1);
  const oracle = denseConvolutionOracle({
    width: W, height: H, diffuse: rgb(r.diffuse), depth, widthWorld, profile,
    projectionScale: r.projectionScale, followSurface, depthThresholdWorld: r.depthThresholdWorld,
  });
  let worst = 0, lit = 0, changed = 0, pxPerMm = 0;
  for (let i = 0; i < W * H; i++) {
    if (widthWorld[i] > 0) pxPerMm = Math.max(pxPerMm, (widthWorld[i] * r.projectionScale[0] * W) / (2 * depth[i]));
    for (let c = 0; c < 3; c++) {
      lit = Math.max(lit, r.diffuse[i * 4 + c]);
      worst = Math.max(worst, Math.abs(r.output[i * 4 + c] - oracle[i * 3 + c]));
      changed = Math.max(changed, Math.abs(r.output[i * 4 + c] - r.diffuse[i * 4 + c]));
    }
  }
  const radiusPx = Math.max(...getProfile(profile).radiusMm(0.997)) * pxPerMm;
  return { ...r, oracle, worst, lit, changed, radiusPx };
}

describe('DenseSubsurfacePass (no grazing-angle correction) matches the float64 dense oracle within 1e-3 of the lit level', () => {
  const cases = [
    // scene, profile, widthMm (wide kernels on a small image), what it exercises
    ['slab', 'skin', 12, 'a hard light edge, Gaussian sum (narrow centre)'],
    ['slab', 'skinBurley', 12, 'Burley: 1/r centre, exponential tail'],
    ['slab', 'milk', 2, 'the dipole: long tail'],
    ['depthEdge', 'skin', 12, 'a depth edge, drop rule'],
    ['grazing', 'skin', 8, 'depth and scale varying per pixel'],
  ];
  for (const [scene, profile, widthMm, what] of cases) {
    it(`${scene}, ${profile}: ${what}`, async () => {
      const r = await denseAgainstOracle({ scene, profile, widthMm });
      expect(r.glError).toBe(0);
      expect(r.radiusPx).toBeGreaterThan(8); // the kernel spans many pixels: a real test
      expect(r.changed).toBeGreaterThan(0.02); // and it moved light
      expect(r.worst / r.lit).toBeLessThan(1e-3);
    });
  }

  it("without the depth rule ('off') light crosses the depth edge, and the oracle agrees", async () => {
    const drop = await denseAgainstOracle({ scene: 'depthEdge', profile: 'skin', widthMm: 12 });
    const off = await denseAgainstOracle({ scene: 'depthEdge', profile: 'skin', widthMm: 12, followSurface: 'off' });
    expect(off.worst / off.lit).toBeLessThan(1e-3);
    // On the dim far slab next to the step, 'off' brings in the near slab's light; 'drop' does not.
    const y = H >> 1;
    const x = W / 2 + 2; // the step is at the centre column (near slab on the left)
    const i = (y * W + x) * 4;
    expect(off.output[i] - drop.output[i]).toBeGreaterThan(0.05);
    expect(Math.abs(drop.output[i] - drop.diffuse[i])).toBeLessThan(1e-3 * drop.lit);
  });
});

describe('DenseSubsurfacePass with the grazing-angle correction (the bench\'s setting)', () => {
  // 84°: past the 76° of MAX_SLOPE, where the slope rule used to take the plane for a depth edge.
  for (const tiltDeg of [75, 84]) it(`on a plane tilted ${tiltDeg}°, each pixel matches the oracle run with its foreshortened scales and plane-relative depths`, async () => {
    const profile = 'skin';
    const r = await renderDense({ scene: 'grazing', tiltDeg, widthMm: 8, profile, followSurface: 'drop', foreshortening: true });
    const image = { depth: channel(r.surface, 0), widthWorld: channel(r.surface, 1) };
    const diffuse = rgb(r.diffuse);
    const radiusMm = Math.max(...getProfile(profile).radiusMm(0.997));
    const [P0, P5] = r.projectionScale;
    let lit = 0;
    for (let i = 0; i < W * H; i++) lit = Math.max(lit, r.diffuse[i * 4]);
    let worst = 0, checked = 0, smallestCos = 1, steeperThanMaxSlope = 0;
    for (let j = 2; j < H; j += 5) {
      for (let i = 3; i < W; i += 9) {
        const c = j * W + i;
        if (!(image.widthWorld[c] > 0)) continue;
        // The pixel's scales and slopes as the shader finds them.
        const zc = image.depth[c];
        const pixelWorld = [(2 * zc) / (P0 * W), (2 * zc) / (P5 * H)];
        const slope = [0, 1].map((axis) => surfaceSlopeOracle({ width: W, height: H, ...image }, i, j, axis, pixelWorld[axis]));
        const cos = slope.map((s, axis) => 1 / Math.sqrt(1 + (s / pixelWorld[axis]) ** 2));
        smallestCos = Math.min(smallestCos, ...cos);
        if (slope.some((sl, axis) => Math.abs(sl) > MAX_SLOPE * pixelWorld[axis])) steeperThanMaxSlope++;
        const reach = cos.map((k, axis) => Math.ceil(radiusMm * ((image.widthWorld[c] * [P0, P5][axis] * [W, H][axis]) / (2 * zc)) * k) + 1);
        // A window centred on the pixel: off-image pixels masked, depths relative to the pixel's
        // plane, projection scales that give the foreshortened pixels per mm at the window's size.
        const [ww, wh] = [2 * reach[0] + 1, 2 * reach[1] + 1];
        const window = { diffuse: new Float64Array(ww * wh * 3), depth: new Float64Array(ww * wh).fill(zc), widthWorld: new Float64Array(ww * wh) };
        for (let y = 0; y < wh; y++) {
          for (let x = 0; x < ww; x++) {
            const [di, dj] = [x - reach[0], y - reach[1]];
            const [ii, jj] = [i + di, j + dj];
            if (ii < 0 || ii >= W || jj < 0 || jj >= H) continue;
            const t = jj * W + ii;
            const k = y * ww + x;
            window.widthWorld[k] = image.widthWorld[t];
            window.depth[k] = image.depth[t] - slope[0] * di - slope[1] * dj;
            window.diffuse.set(diffuse.subarray(3 * t, 3 * t + 3), 3 * k);
          }
        }
        const oracle = denseConvolutionOracle({
          width: ww, height: wh, ...window, profile, followSurface: 'drop', depthThresholdWorld: r.depthThresholdWorld,
          projectionScale: [(P0 * cos[0] * W) / ww, (P5 * cos[1] * H) / wh],
        });
        const centre = reach[1] * ww + reach[0];
        for (let ch = 0; ch < 3; ch++) worst = Math.max(worst, Math.abs(r.output[c * 4 + ch] - oracle[centre * 3 + ch]));
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(30);
    expect(smallestCos).toBeLessThan(0.5); // the correction matters there
    // Past 76° the plane is followed where it is steeper than MAX_SLOPE (it used to count as an edge).
    if (tiltDeg > 80) expect(steeperThanMaxSlope).toBeGreaterThan(10);
    expect(worst / lit).toBeLessThan(1e-3);
  });
});
