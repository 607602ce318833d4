// The subsurface pixels' screen box (src/2-scene-split/subsurfaceScreenBox.js), against an
// independent oracle: every vertex of the meshes projected one by one (Vector3.project) and the
// pixel it falls in, which must lie inside the box, and the box no bigger than those pixels plus
// its margin where the meshes' vertices are their bounding boxes' corners.
import { describe, it, expect } from 'vitest';
import {
  ArrayCamera, Bone, BoxGeometry, Float32BufferAttribute, Mesh, MeshStandardMaterial, OrthographicCamera, PerspectiveCamera, Skeleton, SkinnedMesh, Texture, Uint16BufferAttribute, Vector3,
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

/**
 * An arm: a box 2 long along y, skinned to two bones (the elbow at y = 0), each vertex blended
 * between them by its height; the forearm bent by `bend` radians about z, the whole moved.
 */
function arm(bend) {
  const geometry = new BoxGeometry(0.4, 2, 0.4, 1, 16, 1).translate(0, 0, 0);
  const { count } = geometry.attributes.position;
  const indices = new Uint16Array(count * 4);
  const weights = new Float32Array(count * 4);
  for (let i = 0; i < count; i++) {
    const w = Math.min(1, Math.max(0, geometry.attributes.position.getY(i) + 0.5)); // 0 below -0.5, 1 above 0.5
    indices.set([0, 1, 0, 0], i * 4);
    weights.set([1 - w, w, 0, 0], i * 4);
  }
  geometry.setAttribute('skinIndex', new Uint16BufferAttribute(indices, 4));
  geometry.setAttribute('skinWeight', new Float32BufferAttribute(weights, 4));
  const upper = new Bone();
  const fore = new Bone();
  upper.position.y = -1;
  fore.position.y = 1;
  upper.add(fore);
  const skinned = new SkinnedMesh(geometry, new MeshStandardMaterial());
  skinned.add(upper);
  skinned.position.set(0.4, -0.2, 0.5);
  skinned.updateMatrixWorld(true);
  skinned.bind(new Skeleton([upper, fore]));
  fore.rotation.z = bend;
  skinned.updateMatrixWorld(true);
  return skinned;
}

describe('subsurfaceScreenBox', () => {
  it('bounds a skinned mesh in its pose (from its bones): every posed vertex\'s pixel inside, at most twice the exact box\'s area', () => {
    const cam = camera();
    for (const bend of [0, 1.2, -2.5]) {
      const skinned = arm(bend);
      const box = subsurfaceScreenBox([skinned], cam, WIDTH, HEIGHT);
      // The oracle: three's own CPU skinning of every vertex (SkinnedMesh.getVertexPosition).
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      const p = new Vector3();
      for (let i = 0; i < skinned.geometry.attributes.position.count; i++) {
        skinned.getVertexPosition(i, p).applyMatrix4(skinned.matrixWorld).project(cam);
        const x = Math.floor((p.x * 0.5 + 0.5) * WIDTH);
        const y = Math.floor((p.y * 0.5 + 0.5) * HEIGHT);
        x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
      }
      expect(box, `bend ${bend}`).not.toBeNull();
      expect(box.x).toBeLessThanOrEqual(x0);
      expect(box.y).toBeLessThanOrEqual(y0);
      expect(box.x + box.width).toBeGreaterThan(x1);
      expect(box.y + box.height).toBeGreaterThan(y1);
      expect(box.width * box.height, `bend ${bend}`).toBeLessThan(2 * (x1 - x0 + 3) * (y1 - y0 + 3));
    }
  });


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
    const unskinned = new SkinnedMesh(new BoxGeometry(), new MeshStandardMaterial()); // no skeleton, no weights
    unskinned.updateMatrixWorld();
    expect(subsurfaceScreenBox([unskinned], cam, WIDTH, HEIGHT)).toBeNull();
    const unnormalised = arm(0.5);
    unnormalised.geometry.attributes.skinWeight.setX(0, 0.5); // weights summing to 0.5 + the rest
    expect(subsurfaceScreenBox([unnormalised], cam, WIDTH, HEIGHT)).toBeNull();
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
