// Stage 4: adds the scattered diffuse light back to the rest of the scene's light, linear HDR;
// other pixels come out as their material wrote them. Split and debug views (src/4-compose/debugViews.js).
import { AlwaysDepth, LessEqualDepth, Vector4 } from 'three';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../../shaders/common/fullscreen.vert.glsl?raw';
import composeGlsl from '../../shaders/4-compose/compose.frag.glsl?raw';
import finiteGlsl from '../../shaders/common/finite.glsl?raw';
import carriedDepthGlsl from '../../shaders/common/carriedDepth.glsl?raw';
import { assembleGlsl, enumDefines, setDefines } from '../support/glsl.js';
import { definesVariant } from '../support/compilePrograms.js';
import { describe } from '../support/rendererSupport.js';
import { checkBoolean, checkOneOf, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { PASS_BOOLEANS, booleanFields } from '../support/booleanFields.js';
import { DEBUG_VIEWS, DEBUG_VIEW } from './debugViews.js';
import { PIPELINE_DEFAULTS } from '../options.js';
import { nameClass } from '../support/className.js';
import { MultisampledDepthShare } from './multisampledDepth.js';

const fragmentShader = assembleGlsl('SubsurfaceComposePass', composeGlsl, { 'common/finite.glsl': finiteGlsl, 'common/carriedDepth.glsl': carriedDepthGlsl });

export class SubsurfaceComposePass extends ShaderPass {
  /**
   * @param {object} options
   * @param {import('three').Texture} options.colorTexture the multi-target's colour attachment:
   *   specular + emissive of subsurface pixels, full colour elsewhere
   * @param {import('three').Texture} options.surfaceTexture the multi-target's surface attachment
   * @param {import('three').Texture} options.diffuseTexture the diffuse light before the blur; alpha
   *   not 0 on the mask
   * @param {import('three').Texture|null} [options.scatteredTexture=null] the blurred diffuse light,
   *   alpha as the diffuse's; null: the composer's read buffer
   * @param {import('three').DepthTexture} options.depthTexture the multi-target's depth, written out
   * @param {import('three').WebGLRenderTarget|null} [options.depthTarget=null] the multi-target
   *   itself: where the output is multisampled like it, the output takes its multisampled depth
   *   (./multisampledDepth.js) instead of a depth written one per pixel
   */
  constructor(options = {}) {
    const {
      colorTexture, surfaceTexture, diffuseTexture, scatteredTexture = null, depthTexture, depthTarget = null,
    } = checkOptions('SubsurfaceComposePass options', options, ['colorTexture', 'surfaceTexture', 'diffuseTexture', 'scatteredTexture', 'depthTexture', 'depthTarget']);
    const inputs = { colorTexture, surfaceTexture, diffuseTexture, depthTexture };
    for (const [name, t] of Object.entries(inputs)) {
      if (!t || t.isTexture !== true) throw new TypeError(`SubsurfaceComposePass: ${name} must be a THREE.Texture, got ${describe(t)}`);
    }
    if (depthTarget !== null && (depthTarget?.isWebGLRenderTarget !== true || depthTarget.depthTexture !== depthTexture)) {
      throw new TypeError(`SubsurfaceComposePass: depthTarget must be null or the THREE.WebGLRenderTarget whose depthTexture is depthTexture, got ${describe(depthTarget)}`);
    }
    super({
      name: 'SubsurfaceComposePass',
      defines: { ...enumDefines('DEBUG_VIEW', DEBUG_VIEWS, DEBUG_VIEW.FINAL), KEEP_BACKGROUND: 0, WRITE_DEPTH: 1 },
      uniforms: {
        tColor: { value: null }, tScattered: { value: null }, tDiffuse: { value: null }, tSurface: { value: null },
        tDepth: { value: null }, farDepth: { value: 1 },
        splitX: { value: 0 }, debugDepthRange: { value: PIPELINE_DEFAULTS.debugDepthRange }, debugThicknessRangeMm: { value: PIPELINE_DEFAULTS.debugThicknessRangeMm },
        maskBox: { value: new Vector4(0, 0, 0x7fffffff, 0x7fffffff) },
        scatteredShare: { value: 1 },
      },
      vertexShader,
      fragmentShader,
    }, 'tScattered');
    this.uniforms.tColor.value = inputs.colorTexture;
    this.uniforms.tSurface.value = inputs.surfaceTexture;
    this.uniforms.tDiffuse.value = inputs.diffuseTexture;
    this.uniforms.tDepth.value = inputs.depthTexture;
    this.scatteredTexture = scatteredTexture;
    this._depthTarget = depthTarget;
    this._depthShare = new MultisampledDepthShare();
    /**
     * How the last frame handed the scene's depth on: true, per sample (the output took the split's
     * multisampled depth); false, written per pixel (the output is not multisampled, or drawn in
     * part); a string: why a multisampled output could not take it (written per pixel: a pass
     * drawn after it has an aliased edge along silhouettes).
     * @type {boolean|string}
     */
    this.depthHandOff = false;
    this.setClear(true);
    this.debugView = DEBUG_VIEW.FINAL;
    this.split = 0;
    this._width = 1;
  }

  /**
   * Shows the final image or one ingredient: 'depth' is white near over `depthRange` world units;
   * 'thickness' the profile mm T(d) is read at, white at `thicknessRangeMm`. 'thickness' and
   * 'transmittance' need the materials to write them (materialOutputOf).
   * @param {import('./debugViews.js').DebugView} view one of DEBUG_VIEWS
   * @param {{ depthRange?: number, thicknessRangeMm?: number }} [options]
   */
  setDebugView(view, options = {}) {
    checkOneOf('view', view, DEBUG_VIEWS);
    const { depthRange = PIPELINE_DEFAULTS.debugDepthRange, thicknessRangeMm = PIPELINE_DEFAULTS.debugThicknessRangeMm } = checkOptions('setDebugView options', options, ['depthRange', 'thicknessRangeMm']);
    checkNumber('depthRange', depthRange, { min: 0, minExclusive: true, max: Infinity, unit: 'world units' });
    checkNumber('thicknessRangeMm', thicknessRangeMm, { min: 0, minExclusive: true, max: Infinity, unit: 'mm' });
    setDefines(this.material, enumDefines('DEBUG_VIEW', DEBUG_VIEWS, view));
    this.uniforms.debugDepthRange.value = depthRange;
    this.uniforms.debugThicknessRangeMm.value = thicknessRangeMm;
    this.debugView = view;
  }

  /**
   * As RenderPass's `clear` and `clearDepth`: false keeps the target's pixels where the scene drew
   * nothing and, unless `clearDepth`, where the target's depth is nearer.
   * @param {boolean} clear
   * @param {boolean} [clearDepth=false]
   */
  setClear(clear, clearDepth = false) {
    checkBoolean('clear', clear);
    checkBoolean('clearDepth', clearDepth);
    setDefines(this.material, { KEEP_BACKGROUND: clear ? 0 : 1 });
    this.material.depthFunc = clear || clearDepth ? AlwaysDepth : LessEqualDepth;
    this._clear = clear;
  }

  /**
   * The subsurface pixels' screen box (device pixels, origin bottom left; null: anywhere): outside
   * it only colour and depth are fetched.
   * @param {{ x: number, y: number, width: number, height: number }|null} box
   */
  setMaskBox(box) {
    if (box === null) this.uniforms.maskBox.value.set(0, 0, 0x7fffffff, 0x7fffffff);
    else this.uniforms.maskBox.value.set(box.x, box.y, box.x + box.width, box.y + box.height);
  }

  /**
   * The share of the scattered light shown on subsurface pixels, the rest the unblurred light (1:
   * the scattered alone; the orchestrator gives the plan's fade, src/3-blur/blurPlan.js).
   * @param {number} share in [0, 1]
   */
  setScatteredShare(share) {
    this.uniforms.scatteredShare.value = checkNumber('scatteredShare', share, { min: 0, max: 1 });
  }

  /** Draws into `writeBuffer` (the screen with renderToScreen), as ShaderPass does. */
  render(renderer, writeBuffer, readBuffer, deltaTime, maskActive) {
    // getReversed: three r172+.
    this.uniforms.farDepth.value = renderer.state.buffers.depth.getReversed?.() ? 0 : 1;
    // The depth per sample where the output takes the split's (it replaces the output's depth:
    // with clear only); else written, one per pixel (written only while the depth test is on).
    const target = this.renderToScreen ? null : writeBuffer;
    if (this._clear && this._depthTarget) {
      this.depthHandOff = this._depthShare.share(renderer, this._depthTarget, target);
    } else {
      this.releaseDepth();
    }
    const shared = this.depthHandOff === true;
    setDefines(this.material, { WRITE_DEPTH: shared ? 0 : 1 });
    this.material.depthTest = !shared;
    this.material.depthWrite = !shared;
    super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
  }

  /**
   * render() within `rect` of the output (device pixels), as far as the output's own scissor lets
   * it: an ArrayCamera view composed again with its own plan (src/support/cameraViews.js).
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget|null} writeBuffer
   * @param {{ x: number, y: number, width: number, height: number }} rect
   */
  renderIn(renderer, writeBuffer, rect) {
    const target = this.renderToScreen ? null : writeBuffer;
    const ratio = target ? 1 : renderer.getPixelRatio(); // the screen's scissor is in CSS pixels
    const scissor = target ? target.scissor.clone() : renderer.getScissor(new Vector4());
    const scissorTest = target ? target.scissorTest : renderer.getScissorTest();
    const within = (scissorTest ? scissor.clone().multiplyScalar(ratio) : new Vector4(0, 0, Infinity, Infinity));
    const x0 = Math.max(rect.x, within.x);
    const y0 = Math.max(rect.y, within.y);
    const x1 = Math.min(rect.x + rect.width, within.x + within.z);
    const y1 = Math.min(rect.y + rect.height, within.y + within.w);
    if (!(x1 > x0 && y1 > y0)) return;
    const set = (s, test) => {
      if (target) Object.assign(target, { scissorTest: test }).scissor.copy(s);
      else {
        renderer.setScissor(s);
        renderer.setScissorTest(test);
      }
    };
    set(new Vector4(x0, y0, x1 - x0, y1 - y0).multiplyScalar(1 / ratio), true);
    try {
      this.render(renderer, writeBuffer, null);
    } finally {
      set(scissor, scissorTest);
    }
  }

  /** @param {number} fraction of the width, from the left, shown without the blur (0 = none, 1 = all) */
  setSplit(fraction) {
    checkNumber('split', fraction, { min: 0, max: 1 });
    this.split = fraction;
    this.uniforms.splitX.value = fraction * this._width;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width) {
    this._width = width;
    this.uniforms.splitX.value = this.split * width;
  }

  /** Gives an output that took the scene split's depth its own back (a frame drawn without the compose over what it holds). */
  releaseDepth() {
    this._depthShare.release();
    this.depthHandOff = false;
  }

  /** Frees the pass; an output that took the scene split's depth gets its own back. */
  /**
   * The materials the next frame may draw with into `target` (SubsurfaceScattering.compileAsync):
   * `material`, and where render() may hand the split's depth on (a multisampled output, clear) its
   * copy with the depth written the other way, kept so that its program stays compiled.
   * @param {import('three').WebGLRenderTarget|null} target the output (null: the screen)
   * @returns {import('three').ShaderMaterial[]}
   */
  warmUpMaterials(target) {
    this._twin?.dispose();
    this._twin = null;
    if (!this._clear || !(target?.samples > 0)) return [this.material];
    this._twin = definesVariant(this.material, { WRITE_DEPTH: this.material.defines.WRITE_DEPTH ? 0 : 1 });
    return [this.material, this._twin];
  }

  dispose() {
    this._depthShare.release();
    this._twin?.dispose();
    this._twin = null;
    super.dispose();
  }

  /** The blurred diffuse light: a texture, or null for the composer's read buffer. */
  set scatteredTexture(texture) {
    this._scatteredTexture = texture;
    this.uniforms.tScattered.value = texture;
    this.textureID = texture ? null : 'tScattered';
  }

  get scatteredTexture() {
    return this._scatteredTexture;
  }
}

booleanFields(SubsurfaceComposePass.prototype, PASS_BOOLEANS);

nameClass(SubsurfaceComposePass, 'SubsurfaceComposePass'); // its name in messages, minified or not
