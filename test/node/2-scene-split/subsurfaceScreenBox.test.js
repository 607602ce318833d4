// The subsurface pixels' screen box (src/2-scene-split/subsurfaceScreenBox.js), against an
// independent oracle: every vertex of the meshes projected one by one (Vector3.project) and the
// pixel it falls in, which must lie inside the box, and the box no bigger than those pixels plus
// its margin where the meshes' vertices are their bounding boxes' corners.
import { describe, it, expect } from 'vitest';
import {
  ArrayCamera, BoxGeometry, Mesh, MeshStandardMaterial, OrthographicCamera, PerspectiveCamera, SkinnedMesh, Texture, Vector3,
} from 'three';
import { subsurfaceScreenBox } from '../../../src/2-scene-split/subsurfaceScreenBox.js';

const WIDTH = 320, HEIGHT = 180;

function camera() {
  const c = new PerspectiveCamera(40, WIDTH / HEIGHT, 0.1, 100);
  c.position.set(0.3, 0.2, 6);
  c.lookAt(0, 0, 0);
  c.updateMatrixWorld();
  return c;
}

function mesh(position, rotation = 0, size = [1, 0.6, 0.8]) {
  const m = new Mesh(new BoxGeometry(...size), new MeshStandardMaterial());
  m.position.set(...position);
  m.rotation.set(rotation, 2 * rotation, 0);
  m.updateMatrixWorld();
  return m;
}

/** The pixels (x, y from the bottom left) every vertex of `meshes` projects into: their bounds. */
function projectedPixels(meshes, cam) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const p = new Vector3();
  for (const m of meshes) {
    const position = m.geometry.attributes.position;
    for (let i = 0; i < position.count; i++) {
      p.fromBufferAttribute(position, i).applyMatrix4(m.matrixWorld).project(cam);
      const x = Math.floor((p.x * 0.5 + 0.5) * WIDTH);
      const y = Math.floor((p.y * 0.5 + 0.5) * HEIGHT);
      x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
    }
  }
  return { x0, y0, x1, y1 };
}

describe('subsurfaceScreenBox', () => {
  it('holds every vertex\'s pixel of boxes turned any way, within the margin of their bounds', () => {
    const cam = camera();
    for (const [meshes, what] of [
      [[mesh([0, 0, 0])], 'one box at the centre'],
      [[mesh([-1.2, 0.5, -1], 0.4), mesh([1, -0.4, 1], 1.1)], 'two boxes, turned'],
    ]) {
      const box = subsurfaceScreenBox(meshes, cam, WIDTH, HEIGHT);
      const oracle = projectedPixels(meshes, cam);
      expect(box, what).not.toBeNull();
      expect(box.x, what).toBeLessThanOrEqual(oracle.x0);
      expect(box.y, what).toBeLessThanOrEqual(oracle.y0);
      expect(box.x + box.width, what).toBeGreaterThan(oracle.x1);
      expect(box.y + box.height, what).toBeGreaterThan(oracle.y1);
      if (meshes.length === 1 && meshes[0].rotation.x === 0) {
        // Unturned, the vertices include the box's corners: the box is theirs plus a pixel a side.
        expect(oracle.x0 - box.x).toBeLessThanOrEqual(2);
        expect(box.x + box.width - 1 - oracle.x1).toBeLessThanOrEqual(2);
      }
    }
  });

  it('is in device pixels of the size given and clamped to the frame', () => {
    const cam = camera();
    const box = subsurfaceScreenBox([mesh([3.8, 0, 0])], cam, WIDTH, HEIGHT); // across the right edge (the view is ±3.9 wide there)
    expect(box.x + box.width).toBe(WIDTH);
    const double = subsurfaceScreenBox([mesh([0, 0, 0])], cam, 2 * WIDTH, 2 * HEIGHT);
    const single = subsurfaceScreenBox([mesh([0, 0, 0])], cam, WIDTH, HEIGHT);
    expect(Math.abs(double.width - 2 * single.width)).toBeLessThanOrEqual(4);
  });

  it('is empty (0 × 0) with no mesh or none on screen, and the whole frame (null) where the bounds cannot be trusted', () => {
    const cam = camera();
    expect(subsurfaceScreenBox([], cam, WIDTH, HEIGHT)).toEqual({ x: 0, y: 0, width: 0, height: 0 });
    expect(subsurfaceScreenBox([mesh([40, 0, 0])], cam, WIDTH, HEIGHT)).toEqual({ x: 0, y: 0, width: 0, height: 0 });
    const unculled = mesh([0, 0, 0]);
    unculled.frustumCulled = false;
    expect(subsurfaceScreenBox([unculled], cam, WIDTH, HEIGHT)).toBeNull();
    const displaced = mesh([0, 0, 0]);
    displaced.material.displacementMap = new Texture();
    expect(subsurfaceScreenBox([displaced], cam, WIDTH, HEIGHT)).toBeNull();
    const skinned = new SkinnedMesh(new BoxGeometry(), new MeshStandardMaterial());
    skinned.updateMatrixWorld();
    expect(subsurfaceScreenBox([skinned], cam, WIDTH, HEIGHT)).toBeNull();
    expect(subsurfaceScreenBox([mesh([0, 0, 6])], cam, WIDTH, HEIGHT)).toBeNull(); // around the camera
    expect(subsurfaceScreenBox([mesh([0, 0, 0], 0, [20, 20, 1])], cam, WIDTH, HEIGHT)).toBeNull(); // fills the frame
    expect(subsurfaceScreenBox([mesh([0, 0, 0])], new ArrayCamera([cam]), WIDTH, HEIGHT)).toBeNull();
  });

  it('works with an orthographic camera', () => {
    const cam = new OrthographicCamera(-4, 4, 2.25, -2.25, 0.1, 100);
    cam.position.set(0, 0, 10);
    cam.updateMatrixWorld();
    const meshes = [mesh([1, 0.5, 0], 0.3)];
    const box = subsurfaceScreenBox(meshes, cam, WIDTH, HEIGHT);
    const oracle = projectedPixels(meshes, cam);
    expect(box.x).toBeLessThanOrEqual(oracle.x0);
    expect(box.x + box.width).toBeGreaterThan(oracle.x1);
    expect(box.y).toBeLessThanOrEqual(oracle.y0);
    expect(box.y + box.height).toBeGreaterThan(oracle.y1);
  });
});
