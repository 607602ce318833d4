// The three.js releases supported: the oldest and newest the browser tests run against
// (scripts/threeMatrix.js), held equal to package.json's peer range by a unit test. The material
// hook injects into three's shader chunks at fixed points, so outside the range it may fail, and
// older releases lack what the stages use (the multi-target's `textures`, r163).
import { REVISION } from 'three';

/** As REVISION numbers (0.168.0 is 168). */
export const SUPPORTED_THREE = Object.freeze({ oldest: 168, newest: 187 });

/**
 * The WebGPU entry's floor, r187: MRTNode.setClearColor (three.js pull request #34250: the
 * subsurface outputs must clear to alpha 0, three clears extra attachments to 1) and RenderPipeline.
 */
export const WEBGPU_THREE = Object.freeze({ oldest: 187, newest: SUPPORTED_THREE.newest });

/** The peer dependency range of `releases`. */
export const rangeOf = (releases) => `>=0.${releases.oldest}.0 <0.${releases.newest + 1}.0`;

/** package.json's peerDependencies. */
export const SUPPORTED_THREE_RANGE = rangeOf(SUPPORTED_THREE);

/** package.json's subpathPeerDependencies. */
export const WEBGPU_THREE_RANGE = rangeOf(WEBGPU_THREE);

/** "three r187", for error messages. */
export function threeRelease() {
  return `three r${REVISION}`;
}

export function isSupportedThree(revision = REVISION) {
  const r = Number.parseInt(revision, 10);
  return r >= SUPPORTED_THREE.oldest && r <= SUPPORTED_THREE.newest;
}

/** "(supported: three >=0.168.0 <0.188.0, r168 to r187)", the end of every version message. */
export function supportedThreeNote(releases = SUPPORTED_THREE) {
  return `(supported: three ${rangeOf(releases)}, r${releases.oldest} to r${releases.newest})`;
}

let warnedNewer = false;

/**
 * The one version gate of both entries: too old throws; newer warns once (untested, may work: the
 * material hook fails loudly if three's chunks changed).
 * @param {string} who what is being built, e.g. 'SubsurfaceScattering'
 * @param {{ oldest: number, newest: number }} [releases] the entry's range (SUPPORTED_THREE, WEBGPU_THREE)
 * @param {string} [revision] three's REVISION (a parameter for the tests)
 */
export function checkThreeRevision(who, releases = SUPPORTED_THREE, revision = REVISION) {
  const r = Number.parseInt(revision, 10);
  if (r > releases.newest) {
    if (!warnedNewer) console.warn(`${who}: three r${revision} is newer than the releases this version was tested with ${supportedThreeNote(releases)}`);
    warnedNewer = true;
    return;
  }
  if (!(r >= releases.oldest)) throw new Error(`${who}: three r${revision} is not supported ${supportedThreeNote(releases)}`);
}
