// Stage 3 of the frame, in Node: the 'auto' taps (autoSampleCount) and the
// on-screen scale it is decided from (estimatePixelsPerMm), against hand-computed values.
import { describe, it, expect } from 'vitest';
import { Mesh, MeshStandardMaterial, MeshBasicMaterial, OrthographicCamera, PerspectiveCamera, PlaneGeometry } from 'three';
import { estimatePixelsPerMm } from '../../src/framePlan.js';
import { autoSampleCount } from '../../src/3-blur/blurPlan.js';
import { AUTO_SAMPLES, AUTO_REACH } from '../../src/options.js';

describe('autoSampleCount', () => {
  it('is the smallest level that reaches, for every level, and the largest beyond them all', () => {
    AUTO_SAMPLES.forEach((n, i) => {
      const reach = (n - 3) / 2 / AUTO_REACH; // the largest radius n taps resolve
      expect(autoSampleCount(reach * (1 - 1e-9))).toBe(n);
      if (i + 1 < AUTO_SAMPLES.length) expect(autoSampleCount(reach * (1 + 1e-9))).toBe(AUTO_SAMPLES[i + 1]);
    });
    expect(autoSampleCount(0)).toBe(AUTO_SAMPLES[0]);
    expect(autoSampleCount(1e6)).toBe(AUTO_SAMPLES[AUTO_SAMPLES.length - 1]);
  });
});

describe('estimatePixelsPerMm', () => {
  const width = 400;
  const height = 200;
  const subsurface = new MeshStandardMaterial();
  const plain = new MeshBasicMaterial();
  const widthWorldOf = (m) => (m === subsurface ? 0.001 : undefined); // 1 mm per profile mm at 1 unit = 1 m

  it('uses the nearest bounding-box corner and the larger of the x and y scales (perspective)', () => {
    const camera = new PerspectiveCamera(90, width / height, 0.1, 100); // P5 = 1, P0 = 1 / aspect = 0.5
    camera.position.z = 5;
    camera.updateMatrixWorld();
    const mesh = new Mesh(new PlaneGeometry(2, 2), subsurface); // at z = 0: 5 units away
    mesh.updateMatrixWorld();
    // x: 0.001 * 0.5 / (2 * 5) * 400 = 0.02; y: 0.001 * 1 / 10 * 200 = 0.02
    expect(estimatePixelsPerMm([mesh], camera, { width, height }, widthWorldOf)).toBeCloseTo(0.02, 12);
    mesh.rotation.x = Math.PI / 2; // edge-on: the box is still 2 deep, its nearest corner 4 units away
    mesh.updateMatrixWorld();
    expect(estimatePixelsPerMm([mesh], camera, { width, height }, widthWorldOf)).toBeCloseTo(0.025, 12);
  });

  it('ignores materials that do not scatter, and is 0 without meshes', () => {
    const camera = new PerspectiveCamera(90, 2, 0.1, 100);
    camera.position.z = 5;
    camera.updateMatrixWorld();
    const mesh = new Mesh(new PlaneGeometry(2, 2), plain);
    mesh.updateMatrixWorld();
    expect(estimatePixelsPerMm([mesh], camera, { width, height }, widthWorldOf)).toBe(0);
    expect(estimatePixelsPerMm([], camera, { width, height }, widthWorldOf)).toBe(0);
  });

  it('does not shrink with distance for an orthographic camera', () => {
    const camera = new OrthographicCamera(-2, 2, 1, -1, 0.1, 100); // P0 = 0.5, P5 = 1
    camera.position.z = 50;
    camera.updateMatrixWorld();
    const mesh = new Mesh(new PlaneGeometry(1, 1), subsurface);
    mesh.updateMatrixWorld();
    // x: 0.001 * 0.5 / 2 * 400 = 0.1; y: 0.001 * 1 / 2 * 200 = 0.1
    expect(estimatePixelsPerMm([mesh], camera, { width, height }, widthWorldOf)).toBeCloseTo(0.1, 12);
  });
});
