// Transmittance on the GPU (stage 1 light depth + the chunk in the material), against the float64
// oracle: a back-lit slab shows T(d) of its thickness, thick slabs show none, and no acne.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { mat4 } from 'gl-matrix';
import { openPage, runLab } from '../harness/page.js';
import { at } from '../harness/images.js';
import { transmittanceOracle, thicknessFromLightDepth } from '../oracle/transmittance.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

const WORLD_UNIT_IN_MM = 10;
const SHRINK_MM = 0.6;

/** The oracle's expectation for the lab's back-lit slab: light straight behind, camera in front. */
function expected(thicknessMm) {
  const half = thicknessMm / WORLD_UNIT_IN_MM / 2;
  // Light at z = −10 looking at the origin: its view matrix, from gl-matrix.
  const lightView = mat4.lookAt(new Float64Array(16), [0, 0, -10], [0, 0, 0], [0, 1, 0]);
  const thicknessWorld = thicknessFromLightDepth({
    lightViewMatrix: lightView,
    pointWorld: [0.3, -0.2, half], // a point on the front face (seen by the camera)
    normalWorld: [0, 0, 1],
    shrinkWorld: SHRINK_MM / WORLD_UNIT_IN_MM,
    mapDepth: () => 10 - half, // the back face is the light's nearest surface
  });
  // Light intensity π, wrap saturate(0.3 + 1) = 1, white albedo: diffuse radiance = T.
  return transmittanceOracle({ thicknessMm: thicknessWorld * WORLD_UNIT_IN_MM, profile: 'skin' });
}

async function backlit(thicknessMm) {
  return runLab(page, {
    scene: 'backlit', thicknessMm, worldUnitInMm: WORLD_UNIT_IN_MM, transmittance: true, type: 'float',
    material: { shrinkMm: SHRINK_MM }, reads: ['diffuse', 'output'],
  });
}

describe('transmittance', () => {
  it('a back-lit slab 1 mm thick shows the oracle\'s T(d) colour within 2 %, uniformly (no acne)', async () => {
    const r = await backlit(1);
    const t = expected(1);
    expect(t[0]).toBeGreaterThan(0.3); // thin: visibly red
    const { width, height } = r;
    const sums = [0, 0, 0];
    const squares = [0, 0, 0];
    let n = 0;
    for (let y = 20; y < height - 20; y++) for (let x = 30; x < width - 30; x++) {
      const i = at(width, x, y);
      for (let c = 0; c < 3; c++) { sums[c] += r.diffuse[i + c]; squares[c] += r.diffuse[i + c] ** 2; }
      n++;
    }
    for (let c = 0; c < 3; c++) {
      const mean = sums[c] / n;
      const std = Math.sqrt(Math.max(squares[c] / n - mean * mean, 0));
      if (t[c] > 0.01) {
        expect(Math.abs(mean / t[c] - 1), `channel ${c}: GPU ${mean}, oracle ${t[c]}`).toBeLessThan(0.02);
        expect(std / mean, `channel ${c} uniformity`).toBeLessThan(0.01);
      } else {
        expect(Math.abs(mean - t[c])).toBeLessThan(2e-4);
      }
    }
    // Red through, blue stopped: the colour of back-lit skin.
    expect(sums[0]).toBeGreaterThan(5 * sums[2]);
  });

  it('turned off and on again, transmittance comes back the same', async () => {
    const once = await backlit(1);
    const toggled = await runLab(page, {
      scene: 'backlit', thicknessMm: 1, worldUnitInMm: WORLD_UNIT_IN_MM, transmittance: true, type: 'float',
      material: { shrinkMm: SHRINK_MM }, reads: ['diffuse'], toggleTransmittance: true,
    });
    let worst = 0;
    for (let i = 0; i < once.diffuse.length; i++) worst = Math.max(worst, Math.abs(once.diffuse[i] - toggled.diffuse[i]));
    expect(Math.max(...once.diffuse)).toBeGreaterThan(0.3);
    expect(worst).toBeLessThan(1e-6);
  });

  it('a 50 mm slab transmits nothing (< 1e-3)', async () => {
    const r = await backlit(50);
    expect(Math.max(...expected(50))).toBeLessThan(1e-6);
    let worst = 0;
    for (let y = 10; y < r.height - 10; y++) for (let x = 10; x < r.width - 10; x++) {
      for (let c = 0; c < 3; c++) worst = Math.max(worst, r.diffuse[at(r.width, x, y) + c]);
    }
    expect(worst).toBeLessThan(1e-3);
  });

  it('the light depth target stores linear depth and follows the light', async () => {
    const result = await page.evaluate(async () => {
      const { THREE, SSS, createRenderer, read } = window.lab;
      const renderer = createRenderer(16, 16);
      const scene = new THREE.Scene();
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(50, 50), new THREE.MeshBasicMaterial());
      scene.add(plane);
      const light = new THREE.SpotLight(0xffffff, 1, 0, Math.PI / 6);
      light.position.set(0, 0, 7);
      light.shadow.camera.near = 0.5;
      light.shadow.camera.far = 50;
      scene.add(light, light.target);
      const target = new SSS.LightDepthTarget(light, { size: 32 });
      target.render(renderer, scene);
      const first = await read(renderer, target.renderTarget);
      light.position.set(0, 0, 12); // move it
      target.render(renderer, scene);
      const second = await read(renderer, target.renderTarget);
      const centre = (d) => d[(16 * 32 + 16) * 4];
      const out = { first: centre(first), second: centre(second), cameraZ: target.camera.position.z, fov: target.camera.fov };
      target.dispose();
      renderer.dispose();
      return out;
    });
    // Linear distance along the light's axis, in world units: 7, then 12 after the move.
    expect(result.first).toBeCloseTo(7, 4);
    expect(result.second).toBeCloseTo(12, 4);
    expect(result.cameraZ).toBe(12);
    expect(result.fov).toBeCloseTo(60, 6);
  });
});
