// Stage 3 of the frame, in Node: what runs this frame (planFrame, autoSampleCount) and the
// on-screen scale it is decided from (estimatePixelsPerMm), against hand-computed values.
import { describe, it, expect } from 'vitest';
import { Mesh, MeshStandardMaterial, MeshBasicMaterial, OrthographicCamera, PerspectiveCamera, PlaneGeometry } from 'three';
import { planFrame, autoSampleCount, estimatePixelsPerMm } from '../../src/framePlan.js';
import { AUTO_SAMPLES, AUTO_REACH } from '../../src/options.js';

const fixed = (radiusMm) => () => radiusMm;

describe('planFrame', () => {
  it('skips the blur below half a pixel of on-screen reach, and runs it from half a pixel on', () => {
    expect(planFrame({ scattering: true, pixelsPerMm: 0.1, samples: 17, autoRadiusMm: 3, radiusMmOf: fixed(4.99) })).toEqual({ samples: 17, kernelPixels: 0.1 * 4.99, blur: false });
    expect(planFrame({ scattering: true, pixelsPerMm: 0.125, samples: 17, autoRadiusMm: 3, radiusMmOf: fixed(4) }).blur).toBe(true); // exactly 0.5 px
    expect(planFrame({ scattering: true, pixelsPerMm: 0, samples: 9, autoRadiusMm: 3, radiusMmOf: fixed(4) }).blur).toBe(false); // nothing drawn
  });

  it('never blurs when scattering is switched off, whatever the size', () => {
    expect(planFrame({ scattering: false, pixelsPerMm: 100, samples: 17, autoRadiusMm: 3, radiusMmOf: fixed(4) }).blur).toBe(false);
  });

  it("keeps a fixed tap count, and asks the kernel's reach for that count", () => {
    const asked = [];
    const plan = planFrame({ scattering: true, pixelsPerMm: 2, samples: 25, autoRadiusMm: 3, radiusMmOf: (n) => { asked.push(n); return n / 10; } });
    expect(asked).toEqual([25]);
    expect(plan).toEqual({ samples: 25, kernelPixels: 5, blur: true });
  });

  it("'auto' picks the fewest taps whose single-pixel footprints reach AUTO_REACH of the radius", () => {
    // radius 3 mm at 2 px/mm = 6 px; (n - 3) / 2 >= 0.92 * 6 = 5.52 first holds at n = 17 (7 >= 5.52; 13 gives 5).
    const plan = planFrame({ scattering: true, pixelsPerMm: 2, samples: 'auto', autoRadiusMm: 3, radiusMmOf: (n) => n });
    expect(plan.samples).toBe(17);
    expect(plan.kernelPixels).toBe(34); // the reach of the chosen count
  });
});

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
