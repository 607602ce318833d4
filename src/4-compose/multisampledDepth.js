// The scene's depth handed on per sample. A RenderPass into a multisampled buffer leaves a depth
// per sample there, so a pass drawn after it (an overlay RenderPass with clear false, the
// transparent objects) depth-tests each sample and keeps its antialiased edge along the scene's
// silhouettes. The compose draws from resolved textures (WebGL 2 has no multisample textures) and
// could hand on only one depth per pixel (gl_FragDepth): where a pixel's samples lay on two
// surfaces, an overlay between them showed fully or not at all. WebGL 2 cannot copy into a
// multisampled buffer either (blitFramebuffer refuses a multisampled draw framebuffer). So where
// the output is multisampled like the scene split (same samples, size and depth format) and
// drawn whole (no scissor, the full viewport), its multisampled framebuffer takes the split's
// multisampled depth buffer as its own: the depth the split drew is the output's, sample for
// sample, and the compose writes colour only. Its own depth buffer is put back when the output
// stops taking the split's (another output, MSAA or size; the pipeline disposed).
//
// three keeps a target's buffers in renderer.properties (WebGLTextures, r168 to r187):
// __webglMultisampledFramebuffer (a multisampled target's, where it renders without
// WEBGL_multisampled_render_to_texture) and __webglDepthRenderbuffer (its depth). A release that
// keeps them otherwise makes share() throw, naming what it misses.
import { REVISION } from 'three';

const GL_RENDERBUFFER = 0x8d41;
const GL_RENDERBUFFER_SAMPLES = 0x8cab;
const GL_RENDERBUFFER_INTERNAL_FORMAT = 0x8d44;
const GL_RENDERBUFFER_WIDTH = 0x8d42;
const GL_RENDERBUFFER_HEIGHT = 0x8d43;

/** WebGLRenderbuffer → its storage { samples, format, width, height }, read from GL once per buffer (three makes new ones on a resize). */
const storages = new WeakMap();

/** WebGLFramebuffer → the depth renderbuffer a pipeline attached to it (absent: three's own). */
const attached = new WeakMap();

function storageOf(gl, renderbuffer) {
  let storage = storages.get(renderbuffer);
  if (!storage) {
    const bound = gl.getParameter(gl.RENDERBUFFER_BINDING);
    gl.bindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    storage = {
      samples: gl.getRenderbufferParameter(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES),
      format: gl.getRenderbufferParameter(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT),
      width: gl.getRenderbufferParameter(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH),
      height: gl.getRenderbufferParameter(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT),
    };
    gl.bindRenderbuffer(GL_RENDERBUFFER, bound);
    storages.set(renderbuffer, storage);
  }
  return storage;
}

/**
 * The multisampled framebuffer and depth renderbuffer three keeps for `target`, or null where it
 * keeps none because it renders to the texture multisampled (WEBGL_multisampled_render_to_texture).
 * @throws {Error} where three's properties hold neither (a release whose internals differ)
 */
function multisampledBuffersOf(renderer, target) {
  const properties = renderer.properties.get(target);
  const framebuffer = properties.__webglMultisampledFramebuffer;
  const depth = properties.__webglDepthRenderbuffer;
  if (framebuffer && depth) return { framebuffer, depth };
  if (renderer.extensions.has('WEBGL_multisampled_render_to_texture') && properties.__useRenderToTexture !== false) return null;
  throw new Error(`SubsurfaceComposePass: three r${REVISION} keeps no ${framebuffer ? '__webglDepthRenderbuffer' : '__webglMultisampledFramebuffer'} ` +
    'for a multisampled render target, where r168 to r187 do: this release of three is not supported by the depth hand-off under MSAA');
}

/** Whether three draws into the whole of `target` (a scissor or a smaller viewport: another view shares it). */
function drawnWhole(target) {
  const { x, y, z, w } = target.viewport;
  return target.scissorTest !== true && x === 0 && y === 0 && z === target.width && w === target.height;
}

/** One pipeline's depth shared with its output's multisampled framebuffer (see the file's header). */
export class MultisampledDepthShare {
  constructor() {
    /** @type {{ renderer: object, target: object, framebuffer: WebGLFramebuffer, own: WebGLRenderbuffer }|null} the output that takes the split's depth */
    this._shared = null;
  }

  /**
   * Gives `target` `source`'s multisampled depth, where both are multisampled alike; leaves
   * `target` bound. Called after `source` is drawn and before anything draws into `target`.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget} source the scene split's multi-target
   * @param {import('three').WebGLRenderTarget|null} target the compose's output (null: the screen)
   * @returns {boolean|string} true: shared; false: nothing per sample to hand on (the output is
   *   the screen, not multisampled, or drawn in part); a string: why a multisampled output cannot
   *   take it (the compose then writes the depth, one per pixel)
   */
  share(renderer, source, target) {
    const reason = this._share(renderer, source, target);
    if (reason !== true) this.release();
    return reason;
  }

  _share(renderer, source, target) {
    if (!target || !(target.samples > 0) || !target.depthBuffer || !source.depthBuffer || !drawnWhole(target)) return false;
    if (!(source.samples > 0)) return 'the scene split is not multisampled (`multisampling` 0)';
    renderer.setRenderTarget(target); // three makes its buffers on first use
    const from = multisampledBuffersOf(renderer, source);
    const to = multisampledBuffersOf(renderer, target);
    if (!from || !to) return false; // rendered to the texture multisampled: no buffer to share
    const gl = renderer.getContext();
    const a = storageOf(gl, from.depth);
    const b = storageOf(gl, to.depth);
    // A framebuffer's attachments must agree in samples and size; the resolve copies depth between equal formats only.
    if (a.samples !== b.samples) return `${b.samples} samples, the scene split ${a.samples}`;
    if (a.width !== b.width || a.height !== b.height) return `${b.width} × ${b.height} pixels, the scene split ${a.width} × ${a.height}`;
    if (a.format !== b.format) return `a depth buffer of format 0x${b.format.toString(16)}, the scene split 0x${a.format.toString(16)} (a stencil buffer or a depth texture of another type)`;
    if (this._shared && this._shared.framebuffer !== to.framebuffer) this.release();
    if (attached.get(to.framebuffer) !== from.depth) {
      renderer.state.bindFramebuffer(gl.FRAMEBUFFER, to.framebuffer);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, from.depth);
      attached.set(to.framebuffer, from.depth);
    }
    this._shared ??= { renderer, target, framebuffer: to.framebuffer, own: to.depth };
    renderer.setRenderTarget(target);
    return true;
  }

  /** Puts the output's own depth buffer back (where three has not made it new since). */
  release() {
    if (!this._shared) return;
    const { renderer, target, framebuffer, own } = this._shared;
    this._shared = null;
    if (renderer.properties.get(target).__webglMultisampledFramebuffer !== framebuffer || !attached.has(framebuffer)) return;
    const gl = renderer.getContext();
    const current = renderer.getRenderTarget();
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, own);
    attached.delete(framebuffer);
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, null);
    renderer.setRenderTarget(current);
  }
}
