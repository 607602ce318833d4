// The demo's two camera shots, framed for any window shape: the close-up of the face the page opens
// on, and the full head (the figure renderer's and the bench's default camera). A shot is a camera
// position and target chosen at 16:9; narrower windows move the camera back along the same line
// until the shot's width fits, so a phone in portrait still sees the whole face. Pure: runs in Node.
import { DEFAULT_CAMERA } from './headScene.js';

/**
 * @typedef {object} Shot
 * @property {string} label
 * @property {number[]} camera position x,y,z and target x,y,z at 16:9 (the scan's units, ~5 cm)
 * @property {number} halfWidth world units either side of the target that must stay in view
 */

/** @type {Record<'face'|'head', Shot>} */
export const SHOTS = Object.freeze({
  // Three-quarter view from the right and a little above: forehead to chin, the nose and brows
  // casting shadows the blur visibly softens.
  face: Object.freeze({ label: 'Close-up', camera: Object.freeze([1.3, 2.05, 9.0, 0, 1.35, 2]), halfWidth: 1.45 }),
  head: Object.freeze({ label: 'Full head', camera: DEFAULT_CAMERA, halfWidth: 3.2 }),
});

export const SHOT_NAMES = Object.freeze(Object.keys(SHOTS));

/**
 * The camera (position x,y,z and target x,y,z) of a shot in a view of this aspect ratio.
 * @param {'face'|'head'} name
 * @param {number} aspect width / height
 * @param {number} fovDeg the camera's vertical field of view
 */
export function shotCamera(name, aspect, fovDeg) {
  const shot = SHOTS[name];
  if (!shot) throw new RangeError(`shot must be one of ${SHOT_NAMES.join(', ')}, got ${name}`);
  const [x, y, z, tx, ty, tz] = shot.camera;
  const offset = [x - tx, y - ty, z - tz];
  const distance = Math.hypot(...offset);
  const tanHalf = Math.tan((fovDeg * Math.PI) / 360);
  // Wide enough at the reference distance: keep it; otherwise back off until halfWidth fits.
  const needed = Math.max(distance, shot.halfWidth / (tanHalf * aspect));
  const k = needed / distance;
  return [tx + offset[0] * k, ty + offset[1] * k, tz + offset[2] * k, tx, ty, tz];
}
