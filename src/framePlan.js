// The scene's side of a frame's plan, read from the scene graph only: the on-screen size of a
// profile millimetre, the one outside input of src/3-blur/blurPlan.js, and a mesh's nearest depth.
import { Vector3 } from 'three';
import { isPerspective, pixelsPerMm } from './support/screenScale.js';

const _corner = new Vector3();

/**
 * The view depth of `mesh`'s bounding box corner nearest the camera, world units: no point of the
 * mesh is nearer (instanced and skinned meshes use their own boxes).
 * @param {import('three').Mesh} mesh
 * @param {import('three').Camera} camera (matrixWorldInverse up to date)
 * @returns {number}
 */
export function nearestViewDepth(mesh, camera) {
  if (typeof mesh.computeBoundingBox === 'function' && !mesh.boundingBox) mesh.computeBoundingBox();
  if (!mesh.geometry.boundingBox) mesh.geometry.computeBoundingBox();
  const { min, max } = mesh.boundingBox ?? mesh.geometry.boundingBox;
  let nearest = Infinity;
  for (let corner = 0; corner < 8; corner++) {
    _corner.set(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z);
    _corner.applyMatrix4(mesh.matrixWorld).applyMatrix4(camera.matrixWorldInverse);
    nearest = Math.min(nearest, -_corner.z);
  }
  return nearest;
}

/**
 * An upper bound on the on-screen size of a profile millimetre over `meshes`.
 * @param {Iterable<import('three').Mesh>} meshes the meshes drawn with a subsurface material
 * @param {import('three').Camera} camera (matrixWorldInverse and projection up to date)
 * @param {{ width: number, height: number }} size the render target, pixels
 * @param {(material: import('three').Material) => number|undefined} widthWorldOf world units per
 *   profile mm a material writes; undefined for materials that do not scatter
 * @returns {number} pixels per profile mm (0 without subsurface meshes)
 */
export function estimatePixelsPerMm(meshes, camera, { width, height }, widthWorldOf) {
  const p = camera.projectionMatrix.elements;
  const perspective = isPerspective(camera);
  let largest = 0;
  for (const mesh of meshes) {
    const depth = perspective ? Math.max(nearestViewDepth(mesh, camera), camera.near ?? 1e-6) : 1;
    for (const material of Array.isArray(mesh.material) ? mesh.material : [mesh.material]) {
      const widthWorld = widthWorldOf(material);
      if (widthWorld === undefined) continue;
      largest = Math.max(largest,
        pixelsPerMm(widthWorld, depth, p[0], width, perspective),
        pixelsPerMm(widthWorld, depth, p[5], height, perspective));
    }
  }
  return largest;
}
