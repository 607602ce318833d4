// The three.js releases the WebGPURenderer entry supports: its own floor, above the WebGL entry's
// (src/support/threeVersion.js). The node needs MRTNode.setClearColor (three.js pull request
// #34250, August 2026: the subsurface outputs must clear to alpha 0, three clears extra attachments
// to alpha 1) and RenderPipeline (r183's name of PostProcessing); r187 is the release it is tested
// with. package.json states the range (subpathPeerDependencies), a unit test holds the two equal.
import { REVISION } from 'three';
import { SUPPORTED_THREE } from '../support/threeVersion.js';

/** The oldest and newest three releases the node supports, as REVISION numbers. */
export const WEBGPU_THREE = Object.freeze({ oldest: 187, newest: SUPPORTED_THREE.newest });

/** The entry's peer range. */
export const WEBGPU_THREE_RANGE = `>=0.${WEBGPU_THREE.oldest}.0 <0.${WEBGPU_THREE.newest + 1}.0`;

/** Throws when the loaded three is older than the node's floor (naming both). */
export function checkWebgpuThree(revision = REVISION) {
  if (Number.parseInt(revision, 10) < WEBGPU_THREE.oldest) {
    throw new Error(`three-separable-sss/webgpu needs three r${WEBGPU_THREE.oldest} or later (${WEBGPU_THREE_RANGE}), got three r${revision}`);
  }
}
