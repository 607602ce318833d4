// The three.js releases this library supports: the oldest and the newest the version matrix runs
// the browser tests against (scripts/threeMatrix.js, in CI), and package.json's peer range, which
// a unit test holds equal to SUPPORTED_THREE_RANGE. The material hook injects into three's shader
// chunks at fixed points, so outside the range it may fail; its error names both. The constructors
// check REVISION first (checkThreeRevision): on r160 the multi-target's `textures` (r163+) is
// missing and the page died with "Cannot read properties of undefined (reading '0')".
import { REVISION } from 'three';

/** The oldest and newest supported three releases, as REVISION numbers (0.168.0 is 168). */
export const SUPPORTED_THREE = Object.freeze({ oldest: 168, newest: 187 });

/**
 * The releases the WebGPURenderer entry supports: its own floor, r187. The node needs
 * MRTNode.setClearColor (three.js pull request #34250: the subsurface outputs must clear to alpha
 * 0, three clears extra attachments to alpha 1) and RenderPipeline (r183's name of PostProcessing).
 */
export const WEBGPU_THREE = Object.freeze({ oldest: 187, newest: SUPPORTED_THREE.newest });

/** The peer dependency range of `releases`: every release from the oldest to the newest. */
export const rangeOf = (releases) => `>=0.${releases.oldest}.0 <0.${releases.newest + 1}.0`;

/** The main entry's peer range (package.json's peerDependencies; a unit test holds them equal). */
export const SUPPORTED_THREE_RANGE = rangeOf(SUPPORTED_THREE);

/** The webgpu entry's peer range (package.json's subpathPeerDependencies). */
export const WEBGPU_THREE_RANGE = rangeOf(WEBGPU_THREE);

/** "three r187" (or whatever REVISION is loaded), for error messages. */
export function threeRelease() {
  return `three r${REVISION}`;
}

/** Whether the loaded three is within the supported range. */
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
 * Checks the loaded three release before anything is built: older than the oldest supported one
 * is an Error naming it and the range (such releases lack what the stages use); newer than the
 * newest is one console warning (untested, it may work: the material hook still fails loudly if
 * three's shader chunks changed).
 * The one version gate of both entries.
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
