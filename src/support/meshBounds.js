// A mesh's bounds in its own space, as the frame needs them now: the screen box the blur is
// scissored to (src/2-scene-split/subsurfaceScreenBox.js) and the light depth map's near and far
// (src/1-light-depth/LightDepthView.js). A skinned mesh's geometry box holds its bind pose only,
// and three's SkinnedMesh.computeBoundingBox skins every vertex on the CPU (milliseconds a frame
// for a head); here each bone gets once the box of the vertices it moves (bind pose), so a pose
// costs eight corners per bone: linear blend skinning puts a vertex at a weighted mean (weights
// summing to one) of its bones' moves of it, inside the box around those bones' moved boxes.
import { Box3, Matrix4, Vector3 } from 'three';

const _matrix = new Matrix4();
const _vertex = new Vector3();
const _base = new Vector3();
const _box = new Box3();
/** geometry → { key, boxes }: per bone the box of its vertices in the bind pose, or null where they bound nothing. */
const skinBoxes = new WeakMap();

/** The largest move a morph target can add to vertex `i` (influences taken as at most 1 each). */
function morphReach(geometry, i) {
  const targets = geometry.morphAttributes.position;
  if (!targets) return 0;
  let reach = 0;
  for (const target of targets) {
    _vertex.fromBufferAttribute(target, i);
    if (!geometry.morphTargetsRelative) _vertex.sub(_base.fromBufferAttribute(geometry.attributes.position, i));
    reach += _vertex.length();
  }
  return reach;
}

/**
 * Per bone, the box of the vertices it moves in the bind pose (skeleton space; empty: none), or
 * null where the weights do not sum to one (the blend would leave the boxes' hull).
 * @param {import('three').SkinnedMesh} mesh
 */
function bindBoxes(mesh) {
  const { geometry, skeleton } = mesh;
  const key = `${mesh.bindMatrix.elements.join()}|${skeleton.bones.length}`;
  const cached = skinBoxes.get(geometry);
  if (cached?.key === key) return cached.boxes;
  const { position, skinIndex, skinWeight } = geometry.attributes;
  let boxes = position && skinIndex && skinWeight ? skeleton.bones.map(() => new Box3()) : null;
  const scale = mesh.bindMatrix.getMaxScaleOnAxis();
  for (let i = 0; boxes && i < position.count; i++) {
    _vertex.fromBufferAttribute(position, i).applyMatrix4(mesh.bindMatrix);
    const reach = morphReach(geometry, i) * scale;
    let sum = 0;
    for (let k = 0; k < 4; k++) {
      const weight = skinWeight.getComponent(i, k);
      if (weight === 0) continue;
      sum += weight;
      const box = boxes[skinIndex.getComponent(i, k)];
      if (!box) { boxes = null; break; }
      box.expandByPoint(_base.copy(_vertex).addScalar(reach)).expandByPoint(_base.copy(_vertex).addScalar(-reach));
    }
    if (Math.abs(sum - 1) > 1e-3) boxes = null;
  }
  skinBoxes.set(geometry, { key, boxes });
  return boxes;
}

/** A skinned mesh's bounds in its posed state, its own space (the bones' world matrices as they are). */
function skinnedBounds(mesh, into) {
  const boxes = mesh.skeleton && bindBoxes(mesh);
  if (!boxes) return null;
  into.makeEmpty();
  const { bones, boneInverses } = mesh.skeleton;
  for (let j = 0; j < bones.length; j++) {
    if (boxes[j].isEmpty()) continue;
    _matrix.multiplyMatrices(bones[j].matrixWorld, boneInverses[j]);
    into.union(_box.copy(boxes[j]).applyMatrix4(_matrix));
  }
  return into.isEmpty() ? into : into.applyMatrix4(mesh.bindMatrixInverse);
}

const _skinned = new WeakMap();

/**
 * The box three keeps for `object` in its own space (an InstancedMesh's or BatchedMesh's own, a
 * skinned mesh's posed from its bones, else its geometry's), or null where none bounds it.
 * @param {import('three').Object3D} object
 * @returns {import('three').Box3|null}
 */
export function localBoundsOf(object) {
  if (object.isSkinnedMesh === true) {
    if (!_skinned.has(object)) _skinned.set(object, new Box3());
    return skinnedBounds(object, _skinned.get(object));
  }
  if (object.boundingBox !== undefined) { // InstancedMesh, BatchedMesh
    if (object.boundingBox === null) object.computeBoundingBox();
    return object.boundingBox;
  }
  const { geometry } = object;
  if (!geometry?.isBufferGeometry) return null;
  if (geometry.boundingBox === null) geometry.computeBoundingBox();
  return geometry.boundingBox;
}
