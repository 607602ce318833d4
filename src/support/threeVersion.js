// The three.js releases this library supports: the oldest and the newest the version matrix runs
// the browser tests against (scripts/threeMatrix.js, in CI), and package.json's peer range, which
// a unit test holds equal to SUPPORTED_THREE_RANGE. The material hook injects into three's shader
// chunks at fixed points, so outside the range it may fail; its error names both.
import { REVISION } from 'three';

/** The oldest and newest supported three releases, as REVISION numbers (0.168.0 is 168). */
export const SUPPORTED_THREE = Object.freeze({ oldest: 168, newest: 187 });

/** The peer dependency range: every release from the oldest to the newest. */
export const SUPPORTED_THREE_RANGE = `>=0.${SUPPORTED_THREE.oldest}.0 <0.${SUPPORTED_THREE.newest + 1}.0`;

/** "three r187" (or whatever REVISION is loaded), for error messages. */
export function threeRelease() {
  return `three r${REVISION}`;
}

/** Whether the loaded three is within the supported range. */
export function isSupportedThree(revision = REVISION) {
  const r = Number.parseInt(revision, 10);
  return r >= SUPPORTED_THREE.oldest && r <= SUPPORTED_THREE.newest;
}
