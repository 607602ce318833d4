// The scene's side of a frame's plan: how large a profile millimetre is on screen over the
// subsurface meshes drawn (estimatePixelsPerMm), the one input the blur stage's own plan takes
// from outside it (src/3-blur/blurPlan.js), and the nearest depth of a mesh, which the light's
// side test shares. Both only read the scene graph and run in Node (test/node/framePlan.test.js).
import { Vector3 } from 'three';
import { isPerspective, pixelsPerMm } from './support/screenScale.js';

const _corner = new Vector3();

/**
 * The view depth of `mesh`'s bounding box corner nearest the camera: no point of the mesh is
 * nearer (world units; instanced and skinned meshes use their own boxes: all instances, the posed
 * skin). The one place both frame-level bounds (the kernel's reach, whether light can come
 * through from behind) take a mesh's extent from.
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
 * An upper bound on the on-screen size of a profile millimetre over `meshes`: each mesh's
 * bounding box corner nearest the camera, with the largest width its subsurface materials write.
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
