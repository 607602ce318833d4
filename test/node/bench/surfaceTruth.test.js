// The bench's surface-space truth (bench/surfaceTruth/scatter.js) against closed forms: its pieces'
// areas against the mesh's, a step of light on an irregularly triangulated plane (each Gaussian's
// share beyond the line: erfc), uniform light on a sphere (the 3D distance through it: each
// Gaussian keeps 1 − exp(−2ρ²/v)), and the profile's scale.
import { describe, it, expect } from 'vitest';
import { forEachPiece, surfaceTruth, triangleArea, LOCAL_SIGMA_PER_PIXEL } from '../../../bench/surfaceTruth/scatter.js';
import { GAUSSIANS, erfc } from '../../oracle/closedForms.js';
import { mulberry32 } from '../../../demo/seededRandom.js';

const SKIN = GAUSSIANS.skin;

/**
 * A plane z = 0 from −half to half mm, in cells of `cellMm` split in two triangles, inner corners
 * moved by up to 30 % of a cell (corners on x = 0 only along y: the line stays an edge).
 */
function jitteredPlane(cellMm, halfMm, seed = 1) {
  const n = Math.round((2 * halfMm) / cellMm);
  const next = mulberry32(seed);
  const corner = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) {
    const inner = i > 0 && j > 0 && i < n && j < n;
    const x = -halfMm + i * cellMm;
    const dx = inner && Math.abs(x) > 1e-9 ? (next() - 0.5) * 0.6 * cellMm : 0;
    const dy = inner ? (next() - 0.5) * 0.6 * cellMm : 0;
    corner.push([x + dx, -halfMm + j * cellMm + dy, 0]);
  }
  const positions = [];
  const at = (i, j) => corner[j * (n + 1) + i];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    positions.push(...at(i, j), ...at(i + 1, j), ...at(i + 1, j + 1), ...at(i, j), ...at(i + 1, j + 1), ...at(i, j + 1));
  }
  return { positionMm: Float64Array.from(positions), uv: new Float64Array((positions.length / 9) * 6) };
}

/** An icosphere of radius rho mm, `levels` times split (its corners on the sphere). */
function icosphere(rho, levels) {
  const t = (1 + Math.sqrt(5)) / 2;
  let vertices = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]];
  let faces = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]];
  const unit = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
  vertices = vertices.map(unit);
  for (let l = 0; l < levels; l++) {
    const cache = new Map();
    const middle = (a, b) => {
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      if (!cache.has(key)) { vertices.push(unit(vertices[a].map((x, k) => (x + vertices[b][k]) / 2))); cache.set(key, vertices.length - 1); }
      return cache.get(key);
    };
    faces = faces.flatMap(([a, b, c]) => { const [ab, bc, ca] = [middle(a, b), middle(b, c), middle(c, a)]; return [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]; });
  }
  const positionMm = Float64Array.from(faces.flatMap((f) => f.flatMap((v) => vertices[v].map((x) => x * rho))));
  return { positionMm, uv: new Float64Array(faces.length * 6) };
}

const meshArea = ({ positionMm: p }) => {
  let sum = 0;
  for (let t = 0; t < p.length / 9; t++) sum += triangleArea(...[0, 1, 2].map((k) => [p[9 * t + 3 * k], p[9 * t + 3 * k + 1], p[9 * t + 3 * k + 2]]));
  return sum;
};

describe('surface truth', () => {
  it('the pieces a mesh is split into (to 0.3 mm, from triangles of 4 mm) are no longer than that, and their areas sum to the mesh\'s (1e-9)', () => {
    for (const mesh of [jitteredPlane(4, 10), icosphere(10, 2)]) {
      let leaves = 0;
      let area = 0;
      let longest = 0;
      forEachPiece(mesh, {
        split: (p) => p.edgeMm > 0.3,
        leaf: (p) => { leaves++; area += p.areaMm2; longest = Math.max(longest, p.edgeMm); return [0, 0, 0]; },
        emit: () => {},
      });
      expect(Math.abs(area / meshArea(mesh) - 1)).toBeLessThan(1e-9);
      expect(longest).toBeLessThanOrEqual(0.3);
      expect(leaves).toBeGreaterThan(meshArea(mesh) / 0.3 ** 2);
    }
  });

  it('a split piece\'s light is the area mean of its leaves\' (a linear light is read exactly at the centroids)', () => {
    const mesh = jitteredPlane(4, 4, 3);
    let total = 0;
    let rootSum = 0;
    forEachPiece(mesh, {
      split: (p) => p.depth < 3,
      leaf: (p) => [p.centroid[0], 0, 0],
      emit: (p, light) => {
        if (p.depth === 3) total += p.areaMm2 * p.centroid[0];
        if (p.depth === 0) { rootSum += p.areaMm2 * light[0]; expect(light[0]).toBeCloseTo(p.centroid[0], 9); }
      },
    });
    expect(rootSum).toBeCloseTo(total, 9);
  });

  it('a step of light on an irregularly triangulated plane (triangles of 4 mm): within 2e-3 of the closed form (1.4e-3 measured), the narrowest Gaussian kept local (σ below 0.25 of a 0.5 mm pixel)', () => {
    const mesh = jitteredPlane(4, 28);
    const step = (x) => (x < 0 ? 1 : 0);
    const xs = [-3, -1, -0.31, -0.07, 0.13, 0.5, 1.7, 4];
    const queryMm = Float64Array.from(xs.flatMap((x) => [x, 0.37, 0]));
    const queryLight = Float64Array.from(xs.flatMap((x) => [step(x), step(x), step(x)]));
    const pixelMm = 0.5;
    const truth = surfaceTruth({
      triangles: mesh, lightAt: ([x]) => [step(x), step(x), step(x)], queryMm, queryLight,
      queryPixelMm: new Float64Array(xs.length).fill(pixelMm), gaussians: SKIN,
    });
    const local = SKIN.map(([v]) => Math.sqrt(v) < LOCAL_SIGMA_PER_PIXEL * pixelMm);
    expect(local).toEqual([true, false, false, false, false, false]);
    expect(truth.localShare).toEqual([1, 0, 0, 0, 0, 0]);
    let worst = 0;
    xs.forEach((x, q) => {
      for (let c = 0; c < 3; c++) {
        const expected = SKIN.reduce((s, [v, w], m) => s + w[c] * (local[m] ? step(x) : erfc(x / Math.sqrt(2 * v)) / 2), 0);
        worst = Math.max(worst, Math.abs(truth.light[3 * q + c] - expected));
      }
    });
    expect(worst).toBeLessThan(2e-3);
  });

  it('uniform light on a sphere of radius 3 mm: each Gaussian keeps 1 − exp(−2ρ²/v) of it (the 3D distance, through the sphere), within 5e-4 (1.6e-4 measured)', () => {
    const rho = 3;
    const mesh = icosphere(rho, 5); // 20480 facets, edge 0.1 mm: the facets' area is 2e-4 below the sphere's
    const queryMm = Float64Array.from([0, 0, rho, rho, 0, 0, 0, -rho * Math.SQRT1_2, rho * Math.SQRT1_2]);
    const truth = surfaceTruth({
      triangles: mesh, lightAt: () => [1, 1, 1], queryMm, queryLight: new Float64Array(9).fill(1),
      queryPixelMm: new Float64Array(3), gaussians: SKIN,
    });
    expect(truth.localShare).toEqual([0, 0, 0, 0, 0, 0]);
    for (let q = 0; q < 3; q++) {
      for (let c = 0; c < 3; c++) {
        const expected = SKIN.reduce((s, [v, w]) => s + w[c] * (1 - Math.exp((-2 * rho * rho) / v)), 0);
        expect(Math.abs(truth.light[3 * q + c] - expected), `point ${q}, channel ${c}`).toBeLessThan(5e-4);
      }
    }
  });

  it('ideal blurs of what is seen, on a plane: light the camera does not see beyond a line is missing from both, each Gaussian averaging the light it sees, not the point\'s own (1e-3 of the closed forms); with everything seen the true-area blur is the truth', () => {
    const mesh = jitteredPlane(4, 28, 5);
    const xs = [0.05, 0.4, 1.3, 3];
    const queryMm = Float64Array.from(xs.flatMap((x) => [x, -0.23, 0]));
    // Seen (x ≥ 0): a ramp 0.2 + 0.05 x; unseen (x < 0): lit at 1. The points' own light is kept
    // apart (0.5): a blur that took it in place of the seen mean would fail.
    const seenLight = (x) => 0.2 + 0.05 * x;
    const queryLight = new Float64Array(3 * xs.length).fill(0.5);
    // Light read on pieces of 0.1 mm (a ramp read once per 4 mm triangle would be a staircase).
    const common = { triangles: mesh, queryMm, queryLight, queryPixelMm: new Float64Array(xs.length).fill(0.5), gaussians: SKIN, idealBlurs: true, lightEdgeMm: 0.1 };
    const hidden = surfaceTruth({ ...common, lightAt: ([x]) => (x < 0 ? [1, 1, 1, 0] : [seenLight(x), seenLight(x), seenLight(x), 1]) });
    const gauss = (v) => (d) => Math.exp((-d * d) / (2 * v)) / Math.sqrt(2 * Math.PI * v);
    xs.forEach((x, q) => {
      for (let c = 0; c < 3; c++) {
        // Gaussian m across the line: the seen part's mean of the ramp, ∫_0^∞ g(u − x)(0.2 + 0.05u) du / ∫_0^∞ g(u − x) du.
        let seen = 0;
        SKIN.forEach(([v, w], m) => {
          if (m === 0) { seen += w[c] * 0.5; return; } // kept local: the point's own light
          const mass = 1 - erfc(x / Math.sqrt(2 * v)) / 2;
          const firstMoment = x * mass + v * gauss(v)(x); // ∫_0^∞ u g(u − x) du
          seen += w[c] * (0.2 * mass + 0.05 * firstMoment) / mass;
        });
        expect(Math.abs(hidden.idealBlurs.seen[3 * q + c] - seen), `seen at ${x} mm`).toBeLessThan(1e-3);
        // On a plane the true area within reach is the kernel's own: both blurs agree.
        expect(Math.abs(hidden.idealBlurs.seenTrueArea[3 * q + c] - seen), `seen, true area, at ${x} mm`).toBeLessThan(1e-3);
      }
    });
    const seen = surfaceTruth({ ...common, lightAt: ([x]) => [x < 0 ? 1 : 0.2, 0.2, 0.2] });
    seen.light.forEach((value, k) => expect(Math.abs(seen.idealBlurs.seenTrueArea[k] - value)).toBeLessThan(1e-12));
  });

  it('ideal blurs of what is seen, on a sphere of radius 3 mm whose far half is unseen and three times as bright: each Gaussian averages the near half\'s light (1); with the true area it keeps 1 − exp(−2ρ²/v) of it, what the truth keeps of uniform light (5e-4)', () => {
    const rho = 3;
    const mesh = icosphere(rho, 5);
    const queryMm = Float64Array.from([0, 0, rho, rho * Math.SQRT1_2, 0, rho * Math.SQRT1_2]);
    const blurs = surfaceTruth({
      triangles: mesh, lightAt: ([, , z]) => (z > 0 ? [1, 1, 1, 1] : [3, 3, 3, 0]), queryMm, queryLight: new Float64Array(6).fill(0.5),
      queryPixelMm: new Float64Array(2), gaussians: SKIN, idealBlurs: true,
    }).idealBlurs;
    for (let q = 0; q < 2; q++) {
      for (let c = 0; c < 3; c++) {
        const kept = SKIN.reduce((s, [v, w]) => s + w[c] * (1 - Math.exp((-2 * rho * rho) / v)), 0);
        expect(Math.abs(blurs.seen[3 * q + c] - 1), `point ${q}, channel ${c}`).toBeLessThan(1e-9);
        expect(Math.abs(blurs.seenTrueArea[3 * q + c] - kept), `point ${q}, channel ${c}`).toBeLessThan(5e-4);
      }
    }
  });

  it('widthMm scales the profile: at width 2 a step reads as the width-1 step at half the distance; twice the density moves it by < 1e-3', () => {
    const mesh = jitteredPlane(4, 40, 2);
    const at = (x, widthMm, density = 1) => surfaceTruth({
      triangles: mesh, lightAt: ([px]) => [px < 0 ? 1 : 0, 0, 0], queryMm: Float64Array.from([x, 0.21, 0]), queryLight: Float64Array.from([0, 0, 0]),
      queryPixelMm: Float64Array.from([0.5]), gaussians: SKIN, widthMm, density,
    }).light[0];
    expect(Math.abs(at(1.0, 2) - at(0.5, 1))).toBeLessThan(2e-3);
    expect(Math.abs(at(0.5, 1, 2) - at(0.5, 1))).toBeLessThan(1e-3);
  });
});
