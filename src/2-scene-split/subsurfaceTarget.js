// The multi-target contract: the one place that says which attachment holds what, in which
// format, and in which draw phase a subsurface material writes what. The scene pass draws into it,
// the material hook writes it, the blur and the compose read it; all of them use these names.
//
//   attachment  name      format                     on subsurface pixels                       elsewhere
//   0           color     half float RGBA (or float) specular + emissive                         the material's full colour, the background
//   1           diffuse   half float RGBA (or float) rgb: diffuse light + transmitted light;    0
//                 (float while it carries the depth) a: 1, the mask (whatever the width);
//                                                       or the linear view depth (below)
//   2           surface   float RG                   r: linear view depth (world units)          0
//                 (RGBA with several profiles)       g: world units per profile mm × widthScale
//                                                    b: the material's profile slot (several profiles
//                                                       only: src/profiles/profileSlots.js)
//                                                    a: the slot's square (its spread after an
//                                                       MSAA resolve: surfaceSample.glsl)
//   depth       depth     24-bit depth texture       the scene's depth (what the compose hands on to the composer)
//
// The surface attachment is 32-bit float: depth differences of a millimetre at metres of distance
// need its mantissa (half float has 11 bits). The mask is the diffuse alpha, not g > 0, so a
// material with widthScale 0 keeps its diffuse light unblurred instead of losing it. The surface
// grows to RGBA (RGB float is not renderable) only while a frame holds several profiles: one
// profile keeps the 8 bytes a pixel it had.
//
// The diffuse attachment may carry the depth (setDiffuseCarriesDepth; the orchestrator does so
// without MSAA): it is then 32-bit float and its alpha on subsurface pixels is the surface's
// linear view depth, as in the surface's r (shaders/common/carriedDepth.glsl: 1e-30 for a depth of
// 0; the mask is "alpha != 0"), so the blur's taps read light and depth in one fetch. A reader
// that tests the mask with sssCarriesSurface reads both layouts. With MSAA the resolve would
// average depths with the zeros of uncovered samples, so the alpha stays the coverage there.
import { DepthTexture, FloatType, NearestFilter, RGBAFormat, RGFormat, UnsignedIntType, WebGLRenderTarget } from 'three';
import { setTextureType } from '../support/textureType.js';

/** Attachment indices of the multi-target (see the table above). */
export const ATTACHMENTS = Object.freeze({ COLOR: 0, DIFFUSE: 1, SURFACE: 2 });

/** GLSL defines giving the material hook its output locations. */
export const ATTACHMENT_DEFINES = Object.freeze({
  SSS_DIFFUSE_LOCATION: ATTACHMENTS.DIFFUSE,
  SSS_SURFACE_LOCATION: ATTACHMENTS.SURFACE,
});

/**
 * What a subsurface material writes, by the scene pass's call (see SubsurfaceScenePass):
 * - HIDDEN: nothing (its triangles are clipped in the vertex shader), so it casts shadows in the
 *   first call and is rasterised once, in the split;
 * - SPLIT: diffuse, colour (specular + emissive) and surface into all three attachments;
 * - PLAIN: its usual full colour, as anywhere outside the pipeline.
 */
export const DRAW_PHASES = Object.freeze({ HIDDEN: 'hidden', SPLIT: 'split', PLAIN: 'plain' });

const COLOR_ATTACHMENT0 = 0x8ce0; // gl.COLOR_ATTACHMENT0
const NONE = 0; // gl.NONE

/** gl.drawBuffers lists: the colour attachment alone (three's ordinary materials write location 0 only), or all three. */
export const DRAW_BUFFERS = Object.freeze({
  COLOR_ONLY: Object.freeze([COLOR_ATTACHMENT0 + ATTACHMENTS.COLOR, NONE, NONE]),
  ALL: Object.freeze([COLOR_ATTACHMENT0 + ATTACHMENTS.COLOR, COLOR_ATTACHMENT0 + ATTACHMENTS.DIFFUSE, COLOR_ATTACHMENT0 + ATTACHMENTS.SURFACE]),
});

/**
 * Creates the multi-target, 1 × 1 until setSize, with a depth texture (the scene's depth, which
 * the compose hands on to the composer's buffer).
 * @param {number} type HalfFloatType or FloatType for the colour and diffuse attachments
 * @returns {WebGLRenderTarget}
 */
export function createSubsurfaceTarget(type) {
  const depthTexture = new DepthTexture(1, 1, UnsignedIntType); // 24-bit, like three's depth renderbuffers
  depthTexture.name = 'subsurface.depth';
  const target = new WebGLRenderTarget(1, 1, { count: 3, type, depthBuffer: true, depthTexture });
  const { COLOR, DIFFUSE, SURFACE } = ATTACHMENTS;
  target.textures[COLOR].name = 'subsurface.color';
  target.textures[DIFFUSE].name = 'subsurface.diffuse';
  // Every reader fetches texels (texelFetch); nearest also keeps a 32-bit float attachment complete
  // where float filtering (OES_texture_float_linear) is missing.
  for (const texture of target.textures) texture.minFilter = texture.magFilter = NearestFilter;
  const surface = target.textures[SURFACE];
  surface.name = 'subsurface.surface';
  surface.type = FloatType;
  surface.format = RGFormat;
  return target;
}

/**
 * Gives the surface attachment the channels `profileCount` profiles need: RG for one, RGBA (b: the
 * profile slot) for several. three reallocates the target's buffers on its next use.
 * @param {WebGLRenderTarget} target from createSubsurfaceTarget
 * @param {number} profileCount
 * @returns {boolean} whether the format changed
 */
export function setSurfaceChannels(target, profileCount) {
  const surface = target.textures[ATTACHMENTS.SURFACE];
  const format = profileCount > 1 ? RGBAFormat : RGFormat;
  if (surface.format === format) return false;
  surface.format = format;
  target.dispose();
  return true;
}

/** Multi-targets whose diffuse attachment carries the depth in its alpha. */
const carryingDepth = new WeakSet();

/**
 * Makes the diffuse attachment carry the depth in its alpha (FloatType: the depth needs 32 bits)
 * or the mask (`type`, as created). three reallocates the buffers on the next use when the type
 * changes. The subsurface materials read it per draw (diffuseCarriesDepth).
 * @param {WebGLRenderTarget} target from createSubsurfaceTarget
 * @param {boolean} enabled
 * @param {number} type the attachment's type without the depth (HalfFloatType or FloatType)
 * @returns {boolean} whether the layout changed
 */
export function setDiffuseCarriesDepth(target, enabled, type) {
  if (enabled === carryingDepth.has(target)) return false;
  if (enabled) carryingDepth.add(target);
  else carryingDepth.delete(target);
  setTextureType(target, target.textures[ATTACHMENTS.DIFFUSE], enabled ? FloatType : type);
  return true;
}

/**
 * Whether `target`'s diffuse alpha is the depth (setDiffuseCarriesDepth), not the mask.
 * @param {WebGLRenderTarget|null|undefined} target
 */
export function diffuseCarriesDepth(target) {
  return target != null && carryingDepth.has(target);
}

/** What is being drawn, while a pipeline draws: its target, the draw phase and the pipeline. */
let drawing = null;
const PLAIN_DRAW = Object.freeze({ target: undefined, phase: DRAW_PHASES.PLAIN, owner: null });

/**
 * Runs `draw()` with hooked materials told what to write into `target` and for which pipeline
 * (`owner`, whose per-material settings they use).
 * @param {WebGLRenderTarget|null} target the target the draw goes to (null: the screen)
 * @param {'hidden'|'split'|'plain'} phase one of DRAW_PHASES
 * @param {object} owner the pipeline drawing
 * @param {() => void} draw
 */
export function drawingInto(target, phase, owner, draw) {
  const outer = drawing;
  drawing = { target, phase, owner };
  try {
    draw();
  } finally {
    drawing = outer;
  }
}

/**
 * What a hooked material drawn into `target` now writes, and for which pipeline: the current
 * draw's, if it goes to this target; otherwise PLAIN for no pipeline (the screen, a cube camera,
 * another composer, a shadow map rendered meanwhile).
 * @param {WebGLRenderTarget|null} target
 * @returns {{ phase: string, owner: object|null }}
 */
export function currentDraw(target) {
  return drawing !== null && drawing.target === target ? drawing : PLAIN_DRAW;
}
