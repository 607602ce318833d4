// What the bench's side-by-side measures (shared by the page, bench/peers.js, and the runner,
// bench/peerRun.js; no imports, so it loads in both).

/** The four frames: three.js alone, ours (defaults), Babylon.js alone, Babylon.js with its SSS. */
export const VARIANTS = Object.freeze(['threePlain', 'ours', 'babylonPlain', 'babylonSss']);

/** The stages of the pipeline as its stageTimer names them (src/SubsurfaceScattering.js). */
export const STAGES = Object.freeze(['lightDepth', 'scene', 'blurH', 'blurV', 'compose', 'transparent']);

/**
 * What one round times, a few frames each: the four frames; 'stages', frames of ours timed stage
 * by stage; 'blur', its two blur passes re-run over the last scene split; 'floor', the fetch-only
 * floor's two passes over the same pixels.
 */
export const PEER_MEASURES = Object.freeze([...VARIANTS, 'stages', 'blur', 'floor']);

/**
 * What version 0.2 added to a frame, each measured against the frame without it: MSAA 4 in the
 * scene split (`multisampling`), a transparent object (drawn after the compose), and (issue 22) two balls beside
 * the head in its profile (threeObjects) or in two more (threeProfiles: three profiles on screen),
 * and (issue 20) the isotropic blur (isotropic: `kernelGroups: 'auto'`; the default blurs with one
 * kernel).
 * Timed on ours frame by frame ('stages') and on the plain three.js frame (`threePlain`) alike.
 */
export const ADDITIONS = Object.freeze(['msaa4', 'transparent', 'threeObjects', 'threeProfiles', 'isotropic']);

/**
 * Features whose switch recompiles a shader (the blur's group capacity): warmed up in the timed
 * call itself, so the compile falls in the warm-up frame (their CPU time per frame is then not taken).
 */
export const RECOMPILING_FEATURES = Object.freeze(['isotropic']);

/** Everything the features block switches, one at a time. */
export const FEATURES = ADDITIONS;
