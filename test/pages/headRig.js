// The demo's head scene for the test pages (postprocessing.js, webgpu.js): a fresh clone of the
// mesh and its material each time (each pipeline hooks or converts its own), the camera framing the
// face. Nothing here is part of the library.
import { loadHead } from '/demo/headModel.js';
import { createHeadScene, FACE_CENTRE } from '/demo/headScene.js';

let headPromise = null;

/**
 * @param {number} aspect the camera's
 * @param {number} [fovDeg] narrows the demo's 25° view onto the face (more pixels per mm)
 */
export async function headRig(aspect, fovDeg) {
  headPromise ??= loadHead({ base: '/' });
  const loaded = await headPromise;
  const mesh = loaded.mesh.clone();
  mesh.material = loaded.mesh.material.clone();
  const rig = createHeadScene(mesh);
  rig.camera.aspect = aspect;
  rig.camera.fov = fovDeg ?? rig.camera.fov;
  rig.camera.updateProjectionMatrix();
  rig.camera.lookAt(FACE_CENTRE);
  rig.camera.updateMatrixWorld();
  return { ...rig, isStandIn: loaded.isStandIn };
}
