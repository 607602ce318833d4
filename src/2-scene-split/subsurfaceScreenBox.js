// The screen box of the subsurface pixels: the smallest pixel rectangle holding every pixel the
// scene split can have written subsurface data into, from the meshes' bounding boxes (the same
// bounds three's frustum culling trusts). The blur passes are scissored to it (issue 19): outside
// it the diffuse attachment is 0, so a blur pass writes 0 there anyway, and the compose reads the
// scattered light on subsurface pixels only. The head at 1280×720 covers about a third of the frame.
//
// A skinned mesh is bounded in its pose from its bones (src/support/meshBounds.js). Where the
// bounds cannot be trusted the box is the whole frame: a mesh drawn without frustum culling (three
// does not trust its bounds either), skin weights that do not sum to one, a displacement map (it
// moves vertices beyond the geometry's box), an array camera (several views), a corner on or
// behind the camera's plane. Morph targets are inside the geometry's box (three's
// computeBoundingBox takes them in).
import { Box2, Vector2, Vector3, Vector4 } from 'three';
import { localBoundsOf } from '../support/meshBounds.js';

/** Pixels added on every side: rasterisation covers a pixel whose centre is inside, a box edge may round across it. */
const MARGIN_PX = 1;
const _corner = new Vector3();
const _clip = new Vector4();
const _bounds = new Box2();
const _ndc = new Vector2();

const trusted = (object) => object.frustumCulled !== false
  && !(Array.isArray(object.material) ? object.material : [object.material]).some((m) => m?.displacementMap);

/**
 * Grows `bounds` (NDC) by the projection of `box`'s eight corners; false where a corner is on or
 * behind the camera's plane (its projection is unbounded).
 */
function addProjected(bounds, box, object, camera) {
  for (let k = 0; k < 8; k++) {
    _corner.set(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z);
    _clip.set(_corner.x, _corner.y, _corner.z, 1).applyMatrix4(object.matrixWorld)
      .applyMatrix4(camera.matrixWorldInverse).applyMatrix4(camera.projectionMatrix);
    if (!(_clip.w > 1e-6)) return false;
    bounds.expandByPoint(_ndc.set(_clip.x / _clip.w, _clip.y / _clip.w));
  }
  return true;
}

/**
 * The pixel rectangle (device pixels, origin bottom left as gl.scissor takes it) holding every
 * pixel of `meshes` as `camera` sees them, or null when it is the whole frame (or cannot be bounded).
 * The matrices are read as they are: call it after the frame's render has updated them.
 * @param {import('three').Object3D[]} meshes the scene split's subsurface meshes
 * @param {import('three').Camera} camera
 * @param {number} width device pixels
 * @param {number} height device pixels
 * @returns {{ x: number, y: number, width: number, height: number }|null} an empty box (0 × 0) when nothing is on screen
 */
export function subsurfaceScreenBox(meshes, camera, width, height) {
  if (camera.isArrayCamera) return null;
  _bounds.makeEmpty();
  for (const object of meshes) {
    if (!trusted(object)) return null;
    const box = localBoundsOf(object);
    if (!box) return null;
    if (box.isEmpty()) continue;
    if (!addProjected(_bounds, box, object, camera)) return null;
  }
  if (_bounds.isEmpty()) return { x: 0, y: 0, width: 0, height: 0 };
  const x0 = Math.max(0, Math.floor((_bounds.min.x * 0.5 + 0.5) * width) - MARGIN_PX);
  const y0 = Math.max(0, Math.floor((_bounds.min.y * 0.5 + 0.5) * height) - MARGIN_PX);
  const x1 = Math.min(width, Math.ceil((_bounds.max.x * 0.5 + 0.5) * width) + MARGIN_PX);
  const y1 = Math.min(height, Math.ceil((_bounds.max.y * 0.5 + 0.5) * height) + MARGIN_PX);
  if (x1 <= x0 || y1 <= y0) return { x: 0, y: 0, width: 0, height: 0 };
  if (x0 === 0 && y0 === 0 && x1 === width && y1 === height) return null;
  return { x: x0, y: y0, width: x1 - x0, height: y1 - y0 };
}
