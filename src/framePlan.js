// The scene's side of a frame's plan: how large a profile millimetre is on screen over the
// subsurface meshes drawn (estimatePixelsPerMm), the one input the blur stage's own plan takes
// from outside it (src/3-blur/blurPlan.js), and the nearest depth of a mesh, which the light's
// side test shares. Both only read the scene graph and run in Node (test/node/framePlan.test.js).
// planFrame is version 0.2's plan with callbacks into the blur, kept for one minor version.
import { Vector3 } from 'three';
import { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';
import { autoSampleCount } from './3-blur/blurPlan.js';
import { isPerspective, pixelsPerMm } from './support/screenScale.js';

export { autoSampleCount };

const _corner = new Vector3();

/**
 * Version 0.2's frame plan (deprecated: the blur stage plans itself, src/3-blur/blurPlan.js).
 * @param {object} frame
 * @param {boolean} frame.scattering the blur is switched on
 * @param {number} frame.pixelsPerMm the largest on-screen size of a profile millimetre, pixels
 * @param {number|'auto'} frame.samples the taps asked for
 * @param {number} frame.autoRadiusMm the radius 'auto' must resolve pixel by pixel (the marginal's 99 %)
 * @param {(samples: number) => number} frame.radiusMmOf the blur's reach with that many taps, mm
 * @param {(radiusPx: number) => number} [frame.autoSamples=autoSampleCount] the taps 'auto' takes
 * @returns {{ samples: number, kernelPixels: number, blur: boolean }}
 */
export function planFrame(frame) {
  if (frame === null || typeof frame !== 'object') throw new TypeError(`planFrame: frame must be an object { scattering, pixelsPerMm, samples, ... }, got ${frame === null ? 'null' : typeof frame}`);
  const { scattering, pixelsPerMm, samples, autoRadiusMm, radiusMmOf, autoSamples = autoSampleCount } = frame;
  const taps = samples === 'auto' ? autoSamples(autoRadiusMm * pixelsPerMm) : samples;
  const kernelPixels = radiusMmOf(taps) * pixelsPerMm;
  return { samples: taps, kernelPixels, blur: scattering && kernelPixels >= MIN_KERNEL_PIXELS };
}

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
