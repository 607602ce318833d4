// The procedural stand-in bust (demo/standInBust.js): frame and size of the scan, clean attributes,
// thin ears (so back-lit transmittance shows) and a thick skull, deterministic textures.

import { NoColorSpace, SRGBColorSpace } from 'three';
import { describe, expect, it } from 'vitest';

import { STAND_IN_LAYOUT, createStandInBust, createStandInTextures } from '../../../demo/standInBust.js';

const SCAN_SIZE = [8.55, 7.95, 5.18]; // LeePerrySmith.glb bounding box (REFERENCE section 9)

const geometry = createStandInBust();
const P = geometry.attributes.position.array;
const N = geometry.attributes.normal.array;
const I = geometry.index.array;

/** Byte-wise equality of two typed arrays. */
const same = (a, b) => Buffer.from(a.buffer, a.byteOffset, a.byteLength).equals(Buffer.from(b.buffer, b.byteOffset, b.byteLength));

/** All hit distances along the ray o + t*dir (t > 0), sorted (Moller-Trumbore, both faces). */
function rayHits(o, dir) {
  const hits = [];
  for (let t = 0; t < I.length; t += 3) {
    const a = I[t] * 3;
    const b = I[t + 1] * 3;
    const c = I[t + 2] * 3;
    const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const p = [dir[1] * e2[2] - dir[2] * e2[1], dir[2] * e2[0] - dir[0] * e2[2], dir[0] * e2[1] - dir[1] * e2[0]];
    const det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (Math.abs(det) < 1e-12) continue;
    const inv = 1 / det;
    const s = [o[0] - P[a], o[1] - P[a + 1], o[2] - P[a + 2]];
    const u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    if (u < 0 || u > 1) continue;
    const q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]];
    const v = (dir[0] * q[0] + dir[1] * q[1] + dir[2] * q[2]) * inv;
    if (v < 0 || u + v > 1) continue;
    const dist = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    if (dist > 0) hits.push(dist);
  }
  hits.sort((x, y) => x - y);
  // merge duplicates from rays through shared edges
  return hits.filter((h, i) => i === 0 || h - hits[i - 1] > 1e-6);
}

/** Points on the free (back) part of the right ear, in world space. */
function earSamples() {
  const E = STAND_IN_LAYOUT.ear;
  const pts = [];
  for (const fw of [0.15, 0.35, 0.55, 0.7]) {
    for (const fh of [-0.6, -0.3, 0, 0.3, 0.6]) {
      if (fw * fw + fh * fh > 0.7) continue; // keep clear of the rim
      const w = fw * E.halfWidth;
      pts.push([E.center[0] + w * E.uW[0], E.center[1] + fh * E.halfHeight, E.center[2] + w * E.uW[2]]);
    }
  }
  return pts;
}

describe('createStandInBust', () => {
  it('is an indexed geometry with position, normal, uv and tangent, under ~40k triangles', () => {
    expect(geometry.index).not.toBeNull();
    const count = geometry.attributes.position.count;
    for (const [name, size] of [['position', 3], ['normal', 3], ['uv', 2], ['tangent', 4]]) {
      expect(geometry.attributes[name].itemSize).toBe(size);
      expect(geometry.attributes[name].count).toBe(count);
    }
    expect(I.length % 3).toBe(0);
    expect(I.length / 3).toBeLessThan(40000);
    expect(Math.max(...I)).toBeLessThan(count);
  });

  it('matches the scan frame: bounding box within 10 % of 8.55 x 7.95 x 5.18, centred, facing +Z', () => {
    geometry.computeBoundingBox();
    const { min, max } = geometry.boundingBox;
    const size = [max.x - min.x, max.y - min.y, max.z - min.z];
    size.forEach((s, i) => expect(Math.abs(s / SCAN_SIZE[i] - 1)).toBeLessThan(0.1));
    for (const c of [(max.x + min.x) / 2, (max.y + min.y) / 2, (max.z + min.z) / 2]) expect(Math.abs(c)).toBeLessThan(0.2);
    // the front-most point is the nose tip, on the head (upper half), facing +Z
    let front = 0;
    for (let i = 0; i < P.length; i += 3) if (P[i + 2] > P[front + 2]) front = i;
    expect(Math.abs(P[front])).toBeLessThan(0.1);
    expect(P[front + 1]).toBeGreaterThan(0.5);
    expect(P[front + 1]).toBeLessThan(2);
  });

  it('has no NaN in any attribute, unit normals and unit tangents orthogonal to them', () => {
    for (const name of ['position', 'normal', 'uv', 'tangent']) {
      expect(geometry.attributes[name].array.every(Number.isFinite)).toBe(true);
    }
    const T = geometry.attributes.tangent.array;
    for (let i = 0, j = 0; i < N.length; i += 3, j += 4) {
      expect(Math.abs(Math.hypot(N[i], N[i + 1], N[i + 2]) - 1)).toBeLessThan(1e-4);
      expect(Math.abs(Math.hypot(T[j], T[j + 1], T[j + 2]) - 1)).toBeLessThan(1e-4);
      expect(Math.abs(N[i] * T[j] + N[i + 1] * T[j + 1] + N[i + 2] * T[j + 2])).toBeLessThan(1e-4);
      expect(Math.abs(T[j + 3])).toBe(1);
    }
  });

  it('winds every triangle outward (face normal agrees with the vertex normals)', () => {
    let bad = 0;
    for (let t = 0; t < I.length; t += 3) {
      const [a, b, c] = [I[t] * 3, I[t + 1] * 3, I[t + 2] * 3];
      const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
      const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
      const f = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
      if (Math.hypot(...f) < 1e-10) continue; // degenerate sliver at a pole
      const n = [0, 1, 2].map((k) => N[a + k] + N[b + k] + N[c + k]);
      if (f[0] * n[0] + f[1] * n[1] + f[2] * n[2] <= 0) bad++;
    }
    expect(bad).toBe(0);
  });

  it('is deterministic', () => {
    const again = createStandInBust();
    expect(same(again.attributes.position.array, geometry.attributes.position.array)).toBe(true);
    expect(same(again.attributes.tangent.array, geometry.attributes.tangent.array)).toBe(true);
    expect(same(again.index.array, geometry.index.array)).toBe(true);
  });

  it('has thin ears: rays along X through the free part of each ear cross at most 0.15 units', () => {
    let maxThickness = 0;
    for (const side of [1, -1]) {
      for (const [x, y, z] of earSamples()) {
        // start outside the bust on this side and shoot towards the head (the left ear mirrors the right)
        const hits = rayHits([side * 6, y, z], [-side, 0, 0]);
        expect(hits.length).toBeGreaterThanOrEqual(4); // ear in/out, then head in/out
        const thickness = hits[1] - hits[0];
        maxThickness = Math.max(maxThickness, thickness);
        expect(thickness).toBeLessThanOrEqual(0.15);
        expect(thickness).toBeGreaterThan(0.02); // it is a real shell, not a single sheet
        // the entry lies on the ear (near the sample point), and air separates ear and skull
        expect(Math.abs(6 - hits[0] - x)).toBeLessThan(0.2); // |x| of the entry point
        expect(hits[2] - hits[1]).toBeGreaterThan(0.005);
      }
    }
    expect(maxThickness).toBeGreaterThan(0.05);
  });

  it('has a thick skull: at least 2 units across along X and along Z', () => {
    const { center } = STAND_IN_LAYOUT.head;
    for (const [o, dir] of [
      [[6, center[1] + 0.8, center[2]], [-1, 0, 0]],
      [[6, center[1] + 1.5, center[2] - 0.5], [-1, 0, 0]],
      [[0.3, center[1] + 1, 6], [0, 0, -1]],
    ]) {
      const hits = rayHits(o, dir);
      expect(hits.length).toBeGreaterThanOrEqual(2);
      expect(hits[hits.length - 1] - hits[0]).toBeGreaterThanOrEqual(2);
      // and it is solid: the first segment (entry to first exit) is already that thick
      expect(hits[1] - hits[0]).toBeGreaterThanOrEqual(2);
    }
  });
});

describe('createStandInTextures', () => {
  const tex = createStandInTextures();

  it('returns 256x256 RGBA DataTextures with the right colour spaces', () => {
    for (const t of [tex.map, tex.normalMap, tex.specularMap]) {
      expect(t.isDataTexture).toBe(true);
      expect(t.image.width).toBe(256);
      expect(t.image.height).toBe(256);
      expect(t.image.data.length).toBe(256 * 256 * 4);
    }
    expect(tex.map.colorSpace).toBe(SRGBColorSpace);
    expect(tex.normalMap.colorSpace).toBe(NoColorSpace);
    expect(tex.specularMap.colorSpace).toBe(NoColorSpace);
  });

  it('is deterministic (seeded)', () => {
    const again = createStandInTextures();
    expect(same(again.map.image.data, tex.map.image.data)).toBe(true);
    expect(same(again.normalMap.image.data, tex.normalMap.image.data)).toBe(true);
    expect(same(again.specularMap.image.data, tex.specularMap.image.data)).toBe(true);
    expect(same(createStandInTextures({ seed: 7 }).map.image.data, tex.map.image.data)).toBe(false);
  });

  it('has a skin-tone colour map with slight variation, a flat-ish normal map and a mid specular map', () => {
    const d = tex.map.image.data;
    const mean = [0, 0, 0];
    const lo = [255, 255, 255];
    const hi = [0, 0, 0];
    for (let i = 0; i < d.length; i += 4) {
      for (let k = 0; k < 3; k++) {
        mean[k] += d[i + k] / (d.length / 4);
        lo[k] = Math.min(lo[k], d[i + k]);
        hi[k] = Math.max(hi[k], d[i + k]);
      }
    }
    expect(mean[0]).toBeGreaterThan(mean[1]);
    expect(mean[1]).toBeGreaterThan(mean[2]);
    expect(mean[0]).toBeGreaterThan(150);
    expect(hi[0] - lo[0]).toBeGreaterThan(5); // varies
    expect(hi[0] - lo[0]).toBeLessThan(80); // but only slightly

    const n = tex.normalMap.image.data;
    let minZ = 1;
    let meanZ = 0;
    for (let i = 0; i < n.length; i += 4) {
      const v = [0, 1, 2].map((k) => (n[i + k] / 255) * 2 - 1);
      expect(Math.abs(Math.hypot(...v) - 1)).toBeLessThan(0.02);
      minZ = Math.min(minZ, v[2]);
      meanZ += v[2] / (n.length / 4);
    }
    expect(meanZ).toBeGreaterThan(0.97);
    expect(minZ).toBeGreaterThan(0.7);
    expect(minZ).toBeLessThan(0.999); // there are pores

    const s = tex.specularMap.image.data;
    let meanS = 0;
    for (let i = 0; i < s.length; i += 4) meanS += s[i] / 255 / (s.length / 4);
    expect(meanS).toBeGreaterThan(0.15);
    expect(meanS).toBeLessThan(0.6);
  });
});
