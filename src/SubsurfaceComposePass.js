// Stage 4: adds the scattered diffuse light back on top of the specular light, in linear HDR.
// Pixels that are not subsurface come out as their material wrote them.
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../shaders/fullscreen.vert.glsl?raw';
import fragmentShader from '../shaders/compose.frag.glsl?raw';
import { describe } from './rendererSupport.js';

export class SubsurfaceComposePass extends ShaderPass {
  /**
   * @param {object} options
   * @param {import('three').Texture} options.lightTexture specular + emissive (full colour off subsurface pixels)
   * @param {import('three').Texture} options.surfaceTexture g > 0 on subsurface pixels
   * @param {import('three').Texture|null} [options.scatteredTexture=null] the blurred diffuse light;
   *   null reads the composer's read buffer (the vertical blur's output)
   */
  constructor({ lightTexture, surfaceTexture, scatteredTexture = null } = {}) {
    for (const [name, t] of [['lightTexture', lightTexture], ['surfaceTexture', surfaceTexture]]) {
      if (!t || t.isTexture !== true) throw new TypeError(`SubsurfaceComposePass: ${name} must be a THREE.Texture, got ${describe(t)}`);
    }
    super({
      name: 'SubsurfaceComposePass',
      uniforms: { tLight: { value: null }, tScattered: { value: null }, tSurface: { value: null } },
      vertexShader,
      fragmentShader,
    }, 'tScattered');
    this.uniforms.tLight.value = lightTexture;
    this.uniforms.tSurface.value = surfaceTexture;
    this.scatteredTexture = scatteredTexture;
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
