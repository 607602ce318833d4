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
 * scene split (`multisampling`), a transparent object (drawn after the compose), and the compose's
 * depth write (the scene's depth handed on to later passes), and (issue 22) two balls beside
 * the head in its profile (threeObjects) or in two more (threeProfiles: three profiles on screen),
 * and (issue 20) the isotropic blur (isotropic: `kernelGroups: 'auto'`; the default blurs with one
 * kernel).
 * Timed on ours frame by frame ('stages') and on the plain three.js frame (`threePlain`) alike.
 */
export const ADDITIONS = Object.freeze(['msaa4', 'transparent', 'noDepthWrite', 'threeObjects', 'threeProfiles', 'isotropic']);

/** The additions measured by switching them off (their rows say what they add by the difference's sign). */
export const MEASURED_BY_ABSENCE = Object.freeze(['noDepthWrite']);

/**
 * Features whose switch recompiles a shader (the blur's group capacity): warmed up in the timed
 * call itself, so the compile falls in the warm-up frame (their CPU time per frame is then not taken).
 */
export const RECOMPILING_FEATURES = Object.freeze(['isotropic', 'isotropicDepthFromSurface']);

/**
 * Issue 10's and issue 19's optimizations, each undone for the measure by a switch of the passes
 * (bench/peers.js's UNDO_SWITCHES), so the frame without them is timed next to the frame with
 * them, in the same rounds: lightDepthEveryFrame draws the light depth pass every frame, as before
 * it was skipped while the light reaches no subsurface mesh from behind; composeAsBefore runs the
 * compose shader as it was before it fetched less (the scattered light at every pixel, the
 * surface attachment always); depthPrepass draws the subsurface materials' depth in the scene
 * split's first call, as before each was drawn once; fullFrameBlur runs both blur passes over the
 * whole frame, as before they were scissored to the subsurface pixels' screen box;
 * bothTexelsFetched has the blur fetch both texels around every tap, as before it skipped the one
 * a tap on a texel centre weighs 0; depthFromSurface has the vertical blur read each tap's depth
 * from the surface attachment (two fetches per texel, the light between the passes in the
 * pipeline's type), as before the horizontal pass handed it on in the light's alpha; maskInDiffuse
 * has the diffuse attachment hold the mask in its alpha (in the pipeline's type), as before it
 * carried the depth there, so the horizontal taps (and the dense reference's) read the surface too;
 * maskFromDiffuse has the compose read the mask from the diffuse attachment at every pixel, as
 * before it read it from the scattered light's alpha inside the subsurface pixels' box;
 * msaaDepthResolvedTwice (with MSAA 4, against msaa4) lets three resolve the scene split's depth
 * after its first call too, as before; isotropicDepthFromSurface (the isotropic blur, against
 * isotropic) has its vertical taps read the surface for each texel's depth, as before the group
 * target carried it.
 */
export const UNDONE_OPTIMIZATIONS = Object.freeze(['lightDepthEveryFrame', 'composeAsBefore', 'depthPrepass', 'fullFrameBlur', 'bothTexelsFetched', 'depthFromSurface', 'maskInDiffuse', 'maskFromDiffuse', 'msaaDepthResolvedTwice', 'isotropicDepthFromSurface']);

/** The measure an undone optimization is held against: the MSAA frame, the isotropic one, or ours as it is ('none'). */
export const undoneAgainst = (feature) => (feature.startsWith('msaa') ? 'msaa4' : feature.startsWith('isotropic') ? 'isotropic' : 'none');

/** Everything the features block switches, one at a time. */
export const FEATURES = Object.freeze([...ADDITIONS, ...UNDONE_OPTIMIZATIONS]);
