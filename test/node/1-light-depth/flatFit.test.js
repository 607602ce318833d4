// The light's fit (LightDepthView.fit) for a flat mesh: a leaf or a card face-on to the light has
// the same near and far corner depth, which version 0.3 fitted to near NaN ("near NaN is not above
// 0", no transmittance). Every light kind, on both renderers' LightDepthView, with closed forms.
import { describe, it, expect } from 'vitest';
import * as THREE from 'three';
import { LightDepthTarget } from '../../../src/1-light-depth/LightDepthTarget.js';
import { FIT } from '../../../src/1-light-depth/LightDepthView.js';
import { FrameMeshes } from '../../../src/frameMeshes.js';

/** A 0.2 × 0.1 leaf at the origin, facing +z, and `light` at `distance` along +z aimed at it. */
function leafFacing(light, distance) {
  const scene = new THREE.Scene();
  const leaf = new THREE.Mesh(new THREE.PlaneGeometry(0.2, 0.1), new THREE.MeshStandardMaterial({ side: THREE.DoubleSide }));
  light.position.set(0, 0, distance);
  scene.add(leaf, light);
  if (light.target) scene.add(light.target);
  Object.assign(light.shadow.camera, { left: -0.2, right: 0.2, bottom: -0.2, top: 0.2 });
  scene.updateMatrixWorld();
  return { scene, leaf };
}

const transmits = (material) => material.isMeshStandardMaterial === true;

/** What a frame covers (src/frameMeshes.js) for a camera on the leaf's far side, looking at it. */
function frameOf(scene) {
  scene.updateMatrixWorld();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 10);
  camera.position.set(0, 0, -1);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld();
  return new FrameMeshes().update(scene, camera, transmits);
}

describe("a flat mesh face-on to the light has a fit around it", () => {
  for (const [kind, make] of [
    ['directional', () => new THREE.DirectionalLight()],
    ['spot', () => new THREE.SpotLight(0xffffff, 1, 0, Math.PI / 6)],
    ['point (aimed)', () => new THREE.PointLight()],
  ]) {
    it(`${kind}: near and far finite, the leaf's depth between them with the margin, no frustum problem`, () => {
      const distance = 0.5;
      const target = new LightDepthTarget(make(), { size: 16 });
      const { scene } = leafFacing(target.light, distance);
      expect(target.fit(frameOf(scene), transmits)).toBe(null);
      expect(target.frustumProblem()).toBe(null);
      const { near, far } = target.camera;
      // The leaf's corners all lie at `distance` along the light's view axis (a plane square to it).
      expect(Number.isFinite(near) && Number.isFinite(far)).toBe(true);
      expect(near).toBeCloseTo(distance * (1 - FIT.MARGIN), 12);
      expect(far).toBeCloseTo(distance * (1 + FIT.MARGIN), 12);
      target.dispose();
    });
  }

  it('a directional light in the leaf\'s own plane (depth 0): a margin of FIT.MARGIN world units either side', () => {
    const target = new LightDepthTarget(new THREE.DirectionalLight(), { size: 16 });
    const { scene, leaf } = leafFacing(target.light, 0.5);
    leaf.position.z = 0.5; // the light's plane
    target.fit(frameOf(scene), transmits);
    expect(target.frustumProblem()).toBe(null);
    expect([target.camera.near, target.camera.far]).toEqual([-FIT.MARGIN, FIT.MARGIN]);
    target.dispose();
  });
});
