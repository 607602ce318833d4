// Stage 3: one direction of the separable subsurface blur, as a ShaderPass. Two of them
// (horizontal, then vertical) make the paper's two screen-space passes. Only subsurface pixels
// change; taps on other pixels, off screen or on another surface are dropped and the rest
// renormalised per channel (or lerped back to the centre colour, as in the reference).
import { Vector2, Vector3, Vector4 } from 'three';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../shaders/fullscreen.vert.glsl?raw';
import blurGlsl from '../shaders/subsurfaceBlur.frag.glsl?raw';
import profileLookupGlsl from '../shaders/profileLookup.glsl?raw';
import surfaceSlopeGlsl from '../shaders/surfaceSlope.glsl?raw';
import finiteGlsl from '../shaders/finite.glsl?raw';
import { kernelRadiusMm } from './kernel.js';
import { ProfileLookup } from './ProfileLookup.js';
import { checkNumber, checkOneOf, checkRgb } from './parameterChecks.js';
import { describe } from './rendererSupport.js';

export const FOLLOW_SURFACE_MODES = ['off', 'drop', 'lerp'];
export const KERNEL_MODES = ['taps', 'footprint'];
const DIRECTIONS = ['horizontal', 'vertical'];
const fragmentShader = blurGlsl.replace('PROFILE_LOOKUP_GLSL', profileLookupGlsl).replace('SURFACE_SLOPE_GLSL', surfaceSlopeGlsl)
  .replace('FINITE_GLSL', finiteGlsl);

/**
 * The footprints of the 'footprint' mode from a marginal kernel's positive offsets o_1 < … < o_H:
 * edges between consecutive offsets, the tail sampled at o_H.
 * @param {Float32Array} kernel
 * @returns {{ edgesMm: number[], tailOffsetMm: number }}
 */
export function footprintsOf(kernel) {
  const offsets = [];
  for (let i = 1; i < kernel.length / 4; i++) if (kernel[i * 4 + 3] > 0) offsets.push(kernel[i * 4 + 3]);
  offsets.sort((a, b) => a - b);
  const edgesMm = [];
  for (let j = 0; j + 1 < offsets.length; j++) edgesMm.push((offsets[j] + offsets[j + 1]) / 2);
  return { edgesMm, tailOffsetMm: offsets[offsets.length - 1] ?? 0 };
}

/**
 * One direction of the separable subsurface blur (a ShaderPass): blurs the diffuse light of
 * subsurface pixels only, depth- and mask-aware, in physical units.
 */
export class SubsurfaceBlurPass extends ShaderPass {
  /**
   * @param {object} options
   * @param {'horizontal'|'vertical'} options.direction
   * @param {Float32Array} options.kernel from computeKernel: (weight R, G, B, offset mm) per tap, centre first
   * @param {import('three').Camera} options.camera the camera the scene was rendered with
   * @param {import('three').Texture} options.surfaceTexture r: linear view depth (world units),
   *   g: world units per kernel mm, 0 on pixels that are not subsurface
   * @param {import('three').Texture|null} [options.diffuseTexture=null] the light to blur; null reads
   *   the composer's read buffer. rgb 0 and alpha 0 outside subsurface pixels, alpha 1 on them.
   * @param {'taps'|'footprint'} [options.mode='taps'] 'taps': the kernel's weights and offsets as
   *   they are; 'footprint': the kernel's footprints snapped to pixels per pixel and weighted by the
   *   exact marginal energy from `profileLookup` (see shaders/subsurfaceBlur.frag.glsl)
   * @param {ProfileLookup|null} [options.profileLookup=null] required by the 'footprint' mode
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop'] what a tap on another surface does
   * @param {number} [options.depthThresholdWorld=0.006] depth difference (world units) at which a tap
   *   counts fully as another surface
   * @param {boolean} [options.foreshortening=true] grazing angles: shrink the step by cos(tilt) of the
   *   surface along the axis and compare depths with the local plane (see the shader's header)
   * @param {number[]} [options.strength=[1, 1, 1]] RGB in [0, 1], 'footprint' mode: mix with no
   *   scattering (fixed-tap kernels carry their strength in their weights)
   */
  constructor({
    direction, kernel, camera, surfaceTexture, diffuseTexture = null, mode = 'taps', profileLookup = null,
    followSurface = 'drop', depthThresholdWorld = 0.006, foreshortening = true, strength = [1, 1, 1],
  } = {}) {
    checkOneOf('direction', direction, DIRECTIONS);
    checkOneOf('mode', mode, KERNEL_MODES);
    if (mode === 'footprint' && !(profileLookup instanceof ProfileLookup)) {
      throw new TypeError(`SubsurfaceBlurPass: the 'footprint' mode needs a ProfileLookup as profileLookup, got ${describe(profileLookup)}`);
    }
    if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceBlurPass: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (!surfaceTexture || surfaceTexture.isTexture !== true) {
      throw new TypeError(`SubsurfaceBlurPass: surfaceTexture must be a THREE.Texture, got ${describe(surfaceTexture)}`);
    }
    super({
      name: `SubsurfaceBlurPass(${direction})`,
      defines: {
        AXIS: direction === 'horizontal' ? 0 : 1, SAMPLES: 1, EDGE_ARRAY_SIZE: 1, FOLLOW_SURFACE: 1,
        KERNEL_MODE: KERNEL_MODES.indexOf(mode), FORESHORTEN: 1,
      },
      uniforms: {
        tDiffuse: { value: null },
        tSurface: { value: null },
        kernel: { value: [] },
        kernelRadiusMm: { value: 0 },
        strength: { value: new Vector3(1, 1, 1) },
        projectionScale: { value: 1 },
        resolution: { value: new Vector2(1, 1) },
        depthFalloff: { value: 1 },
        perspective: { value: true },
        tProfile: { value: null },
        marginalRangeMm: { value: 1 },
        footprintEdgesMm: { value: [0] },
        tailOffsetMm: { value: 0 },
      },
      vertexShader,
      fragmentShader,
    });
    this.direction = direction;
    this.camera = camera;
    this.mode = mode;
    this.profileLookup = profileLookup;
    this.uniforms.tProfile.value = profileLookup?.texture ?? null;
    this.uniforms.tSurface.value = surfaceTexture;
    this.diffuseTexture = diffuseTexture;
    this.setKernel(kernel);
    this.setFollowSurface(followSurface, depthThresholdWorld);
    this.setForeshortening(foreshortening);
    this.setStrength(strength);
  }

  /** @param {number[]} strength RGB in [0, 1] ('footprint' mode; see the constructor) */
  setStrength(strength) {
    this.uniforms.strength.value.fromArray(checkRgb('strength', strength, { min: 0, max: 1 }));
  }

  /**
   * The reach of the kernel, mm: below half a pixel of it a pixel does no work. 'taps': the outermost
   * tap; 'footprint': the radius holding 99 % of the marginal (its tail is sampled at least a pixel out).
   */
  get radiusMm() {
    return this.mode === 'footprint' ? this.profileLookup.marginalRadiusMm : kernelRadiusMm(this.kernel);
  }

  /** @param {boolean} enabled the grazing-angle correction (see the constructor) */
  setForeshortening(enabled) {
    if (typeof enabled !== 'boolean') throw new TypeError(`SubsurfaceBlurPass: foreshortening must be a boolean, got ${describe(enabled)}`);
    const define = enabled ? 1 : 0;
    if (this.material.defines.FORESHORTEN !== define) {
      this.material.defines.FORESHORTEN = define;
      this.material.needsUpdate = true;
    }
    this.foreshortening = enabled;
  }

  /** null: blur the composer's read buffer; a texture: blur that instead. */
  set diffuseTexture(texture) {
    this._diffuseTexture = texture;
    this.uniforms.tDiffuse.value = texture;
    this.textureID = texture ? null : 'tDiffuse'; // ShaderPass wires readBuffer only to textureID
  }

  get diffuseTexture() {
    return this._diffuseTexture;
  }

  /** @param {'taps'|'footprint'} mode see the constructor */
  setMode(mode) {
    checkOneOf('mode', mode, KERNEL_MODES);
    if (mode === 'footprint' && !this.profileLookup) {
      throw new TypeError("SubsurfaceBlurPass.setMode: the 'footprint' mode needs the pass to have a profileLookup");
    }
    const define = KERNEL_MODES.indexOf(mode);
    if (this.material.defines.KERNEL_MODE !== define) {
      this.material.defines.KERNEL_MODE = define;
      this.material.needsUpdate = true;
    }
    this.mode = mode;
  }

  /** @param {Float32Array} kernel see computeKernel */
  setKernel(kernel) {
    if (!(kernel instanceof Float32Array) || kernel.length < 4 || kernel.length % 4 !== 0) {
      throw new TypeError('SubsurfaceBlurPass: kernel must be a Float32Array of 4 numbers per tap (see computeKernel)');
    }
    if (!kernel.every(Number.isFinite)) throw new RangeError('SubsurfaceBlurPass: kernel holds NaN or Infinity');
    const samples = kernel.length / 4;
    const taps = [];
    for (let i = 0; i < samples; i++) taps.push(new Vector4().fromArray(kernel, i * 4));
    this.uniforms.kernel.value = taps;
    this.uniforms.kernelRadiusMm.value = kernelRadiusMm(kernel);
    const { edgesMm, tailOffsetMm } = footprintsOf(kernel);
    this.uniforms.footprintEdgesMm.value = edgesMm.length > 0 ? edgesMm : [0];
    this.uniforms.tailOffsetMm.value = tailOffsetMm;
    const defines = this.material.defines;
    if (defines.SAMPLES !== samples) {
      defines.SAMPLES = samples;
      defines.EDGE_ARRAY_SIZE = Math.max(1, (samples - 1) / 2 - 1);
      this.material.needsUpdate = true;
    }
    this.kernel = kernel;
  }

  /**
   * @param {'drop'|'lerp'|'off'} mode
   * @param {number} depthThresholdWorld world units, > 0
   */
  setFollowSurface(mode, depthThresholdWorld = this.depthThresholdWorld) {
    checkOneOf('followSurface', mode, FOLLOW_SURFACE_MODES);
    checkNumber('depthThresholdWorld', depthThresholdWorld, { min: 0, minExclusive: true, max: 1e9, unit: 'world units' });
    const define = FOLLOW_SURFACE_MODES.indexOf(mode);
    if (this.material.defines.FOLLOW_SURFACE !== define) {
      this.material.defines.FOLLOW_SURFACE = define;
      this.material.needsUpdate = true;
    }
    this.followSurface = mode;
    this.depthThresholdWorld = depthThresholdWorld;
    this.uniforms.depthFalloff.value = 1 / depthThresholdWorld;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.uniforms.resolution.value.set(width, height);
  }

  render(renderer, writeBuffer, readBuffer, deltaTime, maskActive) {
    if (this.profileLookup) this.uniforms.marginalRangeMm.value = this.profileLookup.marginalRangeMm;
    this.uniforms.kernelRadiusMm.value = this.radiusMm;
    const projection = this.camera.projectionMatrix.elements;
    this.uniforms.projectionScale.value = this.direction === 'horizontal' ? projection[0] : projection[5];
    this.uniforms.perspective.value = this.camera.isPerspectiveCamera === true || projection[15] === 0;
    super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
  }
}
