// Stage 4: adds the scattered diffuse light back on top of the specular light, in linear HDR.
// Pixels that are not subsurface come out as their material wrote them. Also offers a split view
// (unblurred on the left) and debug views of each ingredient.
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../shaders/fullscreen.vert.glsl?raw';
import composeGlsl from '../shaders/compose.frag.glsl?raw';
import finiteGlsl from '../shaders/finite.glsl?raw';
import { describe } from './rendererSupport.js';
import { checkOneOf, checkNumber } from './parameterChecks.js';

const fragmentShader = composeGlsl.replace('FINITE_GLSL', finiteGlsl);

/** What the compose pass can show: the final image or one of its ingredients. */
export const DEBUG_VIEWS = ['final', 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance'];

/** Adds the scattered diffuse light to the specular light (a ShaderPass); split and debug views. */
export class SubsurfaceComposePass extends ShaderPass {
  /**
   * @param {object} options
   * @param {import('three').Texture} options.lightTexture specular + emissive (full colour off subsurface pixels)
   * @param {import('three').Texture} options.surfaceTexture g > 0 on subsurface pixels
   * @param {import('three').Texture|null} [options.scatteredTexture=null] the blurred diffuse light;
   *   null reads the composer's read buffer (the vertical blur's output)
   * @param {import('three').Texture} options.unscatteredTexture the diffuse light before the blur
   *   (split view, debug views)
   */
  constructor({ lightTexture, surfaceTexture, unscatteredTexture, scatteredTexture = null } = {}) {
    for (const [name, t] of [['lightTexture', lightTexture], ['surfaceTexture', surfaceTexture], ['unscatteredTexture', unscatteredTexture]]) {
      if (!t || t.isTexture !== true) throw new TypeError(`SubsurfaceComposePass: ${name} must be a THREE.Texture, got ${describe(t)}`);
    }
    super({
      name: 'SubsurfaceComposePass',
      defines: { DEBUG_VIEW: 0 },
      uniforms: {
        tLight: { value: null }, tScattered: { value: null }, tUnscattered: { value: null }, tSurface: { value: null },
        splitX: { value: 0 }, debugDepthRange: { value: 100 }, debugThicknessRangeMm: { value: 10 },
      },
      vertexShader,
      fragmentShader,
    }, 'tScattered');
    this.uniforms.tLight.value = lightTexture;
    this.uniforms.tSurface.value = surfaceTexture;
    this.uniforms.tUnscattered.value = unscatteredTexture;
    this.scatteredTexture = scatteredTexture;
    this.debugView = 'final';
    this.split = 0;
    this._width = 1;
  }

  /**
   * Shows the final image or one ingredient: 'final', 'diffuse' (scattered), 'specular', 'depth'
   * (near = white over `depthRange` world units), 'mask', 'thickness' (the thickness T(d) is read
   * at, in profile mm: physical mm × (1 − translucency) / widthMm; `thicknessRangeMm` = white),
   * 'transmittance'. The last two need the materials to write them (SubsurfaceScattering.setDebugView).
   */
  setDebugView(view, { depthRange = 100, thicknessRangeMm = 10 } = {}) {
    checkOneOf('view', view, DEBUG_VIEWS);
    checkNumber('depthRange', depthRange, { min: 0, minExclusive: true, max: Infinity, unit: 'world units' });
    checkNumber('thicknessRangeMm', thicknessRangeMm, { min: 0, minExclusive: true, max: Infinity, unit: 'mm' });
    const define = DEBUG_VIEWS.indexOf(view);
    if (this.material.defines.DEBUG_VIEW !== define) {
      this.material.defines.DEBUG_VIEW = define;
      this.material.needsUpdate = true;
    }
    this.uniforms.debugDepthRange.value = depthRange;
    this.uniforms.debugThicknessRangeMm.value = thicknessRangeMm;
    this.debugView = view;
  }

  /** Fraction of the width, from the left, shown without the blur (0 = none, 1 = all). */
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

  /** null: the composer's read buffer; a texture: that one (e.g. the unblurred diffuse light). */
  set scatteredTexture(texture) {
    this._scatteredTexture = texture;
    this.uniforms.tScattered.value = texture;
    this.textureID = texture ? null : 'tScattered';
  }

  get scatteredTexture() {
    return this._scatteredTexture;
  }
}
