// The multi-target contract: the one place that says which attachment holds what, in which
// format, and in which draw phase a subsurface material writes what. The scene pass draws into it,
// the material hook writes it, the blur and the compose read it; all of them use these names.
//
//   attachment  name      format                     on subsurface pixels                       elsewhere
//   0           color     half float RGBA (or float) specular + emissive                         the material's full colour, the background
//   1           diffuse   half float RGBA (or float) rgb: diffuse light + transmitted light;    0
//                                                    a: 1, the mask (whatever the width)
//   2           surface   float RG                   r: linear view depth (world units)          0
//                                                    g: world units per profile mm × widthScale
//
// The surface attachment is 32-bit float: depth differences of a millimetre at metres of distance
// need its mantissa (half float has 11 bits). The mask is the diffuse alpha, not g > 0, so a
// material with widthScale 0 keeps its diffuse light unblurred instead of losing it.
import { FloatType, NearestFilter, RGFormat, WebGLRenderTarget } from 'three';

/** Attachment indices of the multi-target (see the table above). */
export const ATTACHMENTS = Object.freeze({ COLOR: 0, DIFFUSE: 1, SURFACE: 2 });

/** GLSL defines giving the material hook its output locations. */
export const ATTACHMENT_DEFINES = Object.freeze({
  SSS_DIFFUSE_LOCATION: ATTACHMENTS.DIFFUSE,
  SSS_SURFACE_LOCATION: ATTACHMENTS.SURFACE,
});

/**
 * What a subsurface material writes, by the scene pass's call (see SubsurfaceScenePass):
 * - DEPTH: depth only (after its alpha tests), so it occludes and casts shadows in the first call;
 * - SPLIT: diffuse, colour (specular + emissive) and surface into all three attachments;
 * - PLAIN: its usual full colour, as anywhere outside the pipeline.
 */
export const DRAW_PHASES = Object.freeze({ DEPTH: 'depth', SPLIT: 'split', PLAIN: 'plain' });

const COLOR_ATTACHMENT0 = 0x8ce0; // gl.COLOR_ATTACHMENT0
const NONE = 0; // gl.NONE

/** gl.drawBuffers lists: the colour attachment alone (three's ordinary materials write location 0 only), or all three. */
export const DRAW_BUFFERS = Object.freeze({
  COLOR_ONLY: Object.freeze([COLOR_ATTACHMENT0 + ATTACHMENTS.COLOR, NONE, NONE]),
  ALL: Object.freeze([COLOR_ATTACHMENT0 + ATTACHMENTS.COLOR, COLOR_ATTACHMENT0 + ATTACHMENTS.DIFFUSE, COLOR_ATTACHMENT0 + ATTACHMENTS.SURFACE]),
});

/** The draw phase of each multi-target while the scene pass draws into it. */
const phases = new WeakMap();

/**
 * Creates the multi-target, 1 × 1 until setSize.
 * @param {number} type HalfFloatType or FloatType for the colour and diffuse attachments
 * @returns {WebGLRenderTarget}
 */
export function createSubsurfaceTarget(type) {
  const target = new WebGLRenderTarget(1, 1, { count: 3, type, depthBuffer: true });
  const { COLOR, DIFFUSE, SURFACE } = ATTACHMENTS;
  target.textures[COLOR].name = 'subsurface.color';
  target.textures[DIFFUSE].name = 'subsurface.diffuse';
  const surface = target.textures[SURFACE];
  surface.name = 'subsurface.surface';
  surface.type = FloatType;
  surface.format = RGFormat;
  surface.minFilter = surface.magFilter = NearestFilter;
  phases.set(target, DRAW_PHASES.PLAIN);
  return target;
}

/**
 * Tells hooked materials what to write while drawn into `target` (the scene pass sets it per call
 * and puts PLAIN back after).
 * @param {WebGLRenderTarget} target a multi-target from createSubsurfaceTarget
 * @param {'depth'|'split'|'plain'} phase one of DRAW_PHASES
 */
export function setDrawPhase(target, phase) {
  phases.set(target, phase);
}

/**
 * What a hooked material writes into `target`: its phase if it is a multi-target being drawn by
 * the scene pass, PLAIN for any other target (the screen, a cube camera, another composer).
 * @param {WebGLRenderTarget|null} target
 */
export function drawPhaseOf(target) {
  return (target && phases.get(target)) ?? DRAW_PHASES.PLAIN;
}
