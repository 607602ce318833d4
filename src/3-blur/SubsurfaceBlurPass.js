// Stage 3: one direction of the separable subsurface blur, a SurfacePass (a ShaderPass). Two of
// them (horizontal, then vertical) make the paper's two screen-space passes. Only subsurface
// pixels change; taps on other pixels, off screen or on another surface are dropped and the rest
// renormalised per channel (or lerped back to the centre colour, as in the reference).
import { DataTexture, FloatType, GLSL3, NearestFilter, RGBAFormat, ShaderMaterial, Vector3 } from 'three';
import blurGlsl from '../../shaders/3-blur/subsurfaceBlur.frag.glsl?raw';
import kernelGroupsBlurGlsl from '../../shaders/3-blur/kernelGroupsBlur.frag.glsl?raw';
import blurTapsGlsl from '../../shaders/3-blur/blurTaps.glsl?raw';
import profileLookupGlsl from '../../shaders/common/profileLookup.glsl?raw';
import kernelGroupsGlsl from '../../shaders/3-blur/kernelGroups.glsl?raw';
import { kernelRadiusMm } from '../profiles/kernel.js';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { FootprintTable } from '../profiles/FootprintTable.js';
import { ProfileStack } from '../profiles/ProfileStack.js';
import { MAX_PROFILES } from '../profiles/profileSlots.js';
import { AUTO_MAX_SAMPLES, FOOTPRINT_ROWS, FOOTPRINT_SCALES } from '../profiles/footprints.js';
import { enumDefines, glslFloat, setDefines } from '../support/glsl.js';
import { checkBoolean, checkOneOf, checkOptions, checkRgb } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { FOLLOW_SURFACE_MODES } from '../options.js';
import { SurfacePass, assembleSurfaceGlsl } from './SurfacePass.js';
import { MAX_KERNEL_GROUPS } from './kernelGroups.js';
import { nameClass } from '../support/className.js';

export { FOLLOW_SURFACE_MODES };
/** How the blur weighs its taps: a kernel's fixed taps, or footprints snapped to pixels (see the shader). */
export const KERNEL_MODES = Object.freeze(['taps', 'footprint']);
const DIRECTIONS = Object.freeze(['horizontal', 'vertical']);

/**
 * The taps the shader is compiled for: every count up to it (computeKernel's 3..63) is the
 * `tapCount` uniform, so a change of `samples` (a slider, 'auto') never compiles another program.
 */
const MAX_TAPS = AUTO_MAX_SAMPLES;

const CHUNKS = Object.freeze({ 'common/profileLookup.glsl': profileLookupGlsl, '3-blur/blurTaps.glsl': blurTapsGlsl });
/** The groups' program (setGroupFrame) includes the groups' packing too. */
const GROUP_CHUNKS = Object.freeze({ ...CHUNKS, '3-blur/kernelGroups.glsl': kernelGroupsGlsl });

/** The footprint table's scales as the GLSL defines the shader reads. */
const FOOTPRINT_DEFINES = Object.freeze({
  SSS_FOOTPRINT_SCALE_MIN: glslFloat(FOOTPRINT_SCALES.min),
  SSS_FOOTPRINT_PER_OCTAVE: glslFloat(FOOTPRINT_SCALES.perOctave),
  SSS_FOOTPRINT_ROWS: FOOTPRINT_ROWS,
});

/**
 * Footprints from a marginal kernel's positive offsets o_1 < … < o_H: edges between consecutive
 * offsets, the tail sampled at o_H. (Version 0.1's 'footprint' allocation, for every scale alike;
 * the blur now allocates per scale from the profile's energy: see src/profiles/footprints.js.)
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
 * One direction of the separable subsurface blur: blurs the diffuse light of subsurface pixels
 * only, depth- and mask-aware, in physical units. The horizontal pass writes its light with the
 * depth in the alpha (give it a 32-bit float target) and the vertical pass reads it so (with MSAA,
 * setLightCarriesDepth(true, the multi-target's diffuse) for the coverage); a horizontal pass over
 * SubsurfaceScenePass's diffuse reads one fetch per tap with setLightCarriesDepth(scenePass.diffuseCarriesDepth).
 */
export class SubsurfaceBlurPass extends SurfacePass {
  /**
   * @param {object} options
   * @param {'horizontal'|'vertical'} options.direction
   * @param {Float32Array} options.kernel from computeKernel: (weight R, G, B, offset mm) per tap, centre first
   * @param {import('three').Camera} options.camera the camera the scene was rendered with
   * @param {import('three').Texture} options.surfaceTexture the multi-target's surface attachment
   *   (r: linear view depth in world units, g: world units per profile mm, 0 off subsurface pixels)
   * @param {import('three').Texture|null} [options.diffuseTexture=null] the light to blur; null reads
   *   the composer's read buffer. rgb 0 and alpha 0 outside subsurface pixels, alpha 1 on them.
   * @param {'taps'|'footprint'} [options.mode='taps'] 'taps': the kernel's weights and offsets as
   *   they are; 'footprint': per pixel, footprints of whole pixels allocated for the pixel's scale
   *   (src/profiles/footprints.js), as many taps as the kernel has, weighted by the exact marginal
   *   energy from `profileLookup` (see shaders/3-blur/blurTaps.glsl)
   * @param {ProfileLookup|null} [options.profileLookup=null] required by the 'footprint' mode
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop'] what a tap on another surface does
   * @param {number} [options.depthThresholdWorld=0.006] depth difference (world units) at which a tap
   *   counts fully as another surface
   * @param {boolean} [options.foreshortening=true] grazing angles: shrink the step by cos(tilt) of the
   *   surface along the axis and compare depths with the local plane (see the shader's header)
   * @param {number[]} [options.strength=[1, 1, 1]] RGB in [0, 1], 'footprint' mode: mix with no
   *   scattering (fixed-tap kernels carry their strength in their weights)
   * @param {boolean} [options.autoFootprints=false] 'footprint' mode: per pixel the fewest taps within
   *   AUTO_STEP_ERROR for its scale, up to the kernel's count (give a kernel of AUTO_MAX_SAMPLES taps)
   */
  constructor(options = {}) {
    const {
      direction, kernel, mode = 'taps', profileLookup = null, strength = [1, 1, 1], autoFootprints = false, ...surface
    } = checkOptions('SubsurfaceBlurPass options', options);
    checkOneOf('direction', direction, DIRECTIONS);
    checkBoolean('autoFootprints', autoFootprints);
    checkOneOf('mode', mode, KERNEL_MODES);
    if (mode === 'footprint' && !(profileLookup instanceof ProfileLookup)) {
      throw new TypeError(`SubsurfaceBlurPass: the 'footprint' mode needs a ProfileLookup as profileLookup, got ${describe(profileLookup)}`);
    }
    super({
      name: `SubsurfaceBlurPass(${direction})`,
      fragmentShader: blurGlsl,
      chunks: CHUNKS,
      defines: { AXIS: DIRECTIONS.indexOf(direction), SAMPLES: MAX_TAPS, ...FOOTPRINT_DEFINES, ...enumDefines('KERNEL_MODE', KERNEL_MODES, mode) },
      uniforms: {
        kernel: { value: new Float32Array(MAX_TAPS * 4) },
        tapCount: { value: 1 },
        kernelRadiusMm: { value: 0 },
        strength: { value: new Vector3(1, 1, 1) },
        tProfile: { value: null },
        marginalRangeMm: { value: 1 },
        marginalRangesMm: { value: new Float32Array(1) },
        tFootprints: { value: null },
        tKernels: { value: null },
        // The isotropic blur's groups (setGroupFrame; shaders/3-blur/kernelGroups.glsl).
        groupEnergies: { value: new Float32Array(MAX_KERNEL_GROUPS * 3) },
        tGroupFractions: { value: null },
        tGroups0: { value: null },
        tGroups1: { value: null },
      },
    }, surface);
    // GLSL 3: the horizontal pass of the groups writes two unsigned-integer attachments, so the
    // shader declares its own outputs.
    this.material.glslVersion = GLSL3;
    /** This frame's groups (setGroupFrame): 1 blurs with `material`, more with its variant for that count. */
    this.groups = 1;
    this._groupMaterials = new Map(); // count → the material compiled with SSS_GROUPS count
    this.direction = direction;
    // One kernel's horizontal pass writes its light with the depth in the alpha (a 32-bit float
    // target), so the vertical pass reads it as carried light (setLightCarriesDepth's coverage with MSAA).
    if (direction === 'vertical') this.setLightCarriesDepth(true);
    this.mode = mode;
    /** The footprint allocation for the profile and the kernel's tap count ('footprint' mode). */
    this.footprintTable = profileLookup ? new FootprintTable(profileLookup) : null;
    /** Several profiles' tables, stacked ('footprint' mode with more than one profile). */
    this.profileStack = new ProfileStack();
    this.setProfiles(profileLookup ? [profileLookup] : []);
    /** 'footprint' mode: taps chosen per pixel for its scale ('auto'), or the kernel's count everywhere. */
    this.autoFootprints = autoFootprints;
    this.setKernel(kernel);
    this.setStrength(strength);
  }

  /**
   * This frame's groups (the isotropic blur, 'footprint' mode; shaders/3-blur/kernelGroups.glsl):
   * 1 blurs with one kernel (`material`, separable, exact along the screen axes only); 2..4 with
   * `material`'s variant compiled for that count, which follows its defines (a program per count,
   * kept: a change of count is no recompile once each has been drawn). The horizontal pass then
   * writes the group target, the vertical one reads its attachments (`groups`).
   * `coverage` (the vertical pass): a texture whose alpha is the coverage, for the surface reads
   * that divide it out (MSAA: the slope's neighbours), in place of the light it no longer reads.
   * @param {{ count: number, energies?: Float32Array, fractions?: import('three').Texture, groups?: readonly import('three').Texture[], coverage?: import('three').Texture|null }} frame
   */
  setGroupFrame({ count, energies = null, fractions = null, groups = [], coverage = null }) {
    if (!Number.isInteger(count) || count < 1 || count > MAX_KERNEL_GROUPS) throw new RangeError(`SubsurfaceBlurPass.setGroupFrame: count must be an integer in 1..${MAX_KERNEL_GROUPS}, got ${describe(count)}`);
    if (count > 1 && this.mode !== 'footprint') throw new RangeError(`SubsurfaceBlurPass.setGroupFrame: groups need the 'footprint' mode, the pass is in '${this.mode}'`);
    this.groups = count;
    // The light's alpha is the coverage the surface reads divide out: the groups' pass reads its
    // light from `groups`, and the coverage from `coverage` (the multi-target's diffuse).
    this.uniforms.tDiffuse.value = count > 1 && coverage ? coverage : this.diffuseTexture;
    if (count === 1) return;
    this.uniforms.groupEnergies.value = energies;
    this.uniforms.tGroupFractions.value = fractions;
    this.uniforms.tGroups0.value = groups[0] ?? null;
    this.uniforms.tGroups1.value = groups[1] ?? null;
  }

  /**
   * The material `count` groups draw with: `material`, or its variant for the count (defines
   * synced, uniforms shared; kept, so that its program stays compiled: BlurStage.warmUpMaterials).
   * @param {number} [count=this.groups]
   */
  groupMaterial(count = this.groups) {
    if (count === 1) return this.material;
    let variant = this._groupMaterials.get(count);
    if (!variant) {
      // As ShaderPass builds `material`, from the groups' shader, sharing its uniforms (clone()
      // would copy them, and warns at render targets' textures).
      const { name, vertexShader, glslVersion, uniforms } = this.material;
      this._groupShader ??= assembleSurfaceGlsl(name, kernelGroupsBlurGlsl, GROUP_CHUNKS);
      variant = new ShaderMaterial({ name, vertexShader, fragmentShader: this._groupShader, glslVersion, uniforms, defines: { ...this.material.defines } });
      this._groupMaterials.set(count, variant);
    }
    // The groups have their own target: the vertical pass reads them, not the carried light.
    setDefines(variant, { ...this.material.defines, SSS_GROUPS: count, SSS_MAX_GROUPS: MAX_KERNEL_GROUPS, ...(this.direction === 'vertical' ? { SSS_LIGHT_CARRIES_DEPTH: 0 } : {}) });
    return variant;
  }

  /** @param {number[]} strength RGB in [0, 1] ('footprint' mode; see the constructor) */
  setStrength(strength) {
    this.uniforms.strength.value.fromArray(checkRgb('strength', strength, { min: 0, max: 1 }));
  }

  /**
   * The profiles blurred, by slot (src/profiles/profileSlots.js): one is the pass as without this
   * feature (PROFILE_COUNT 1, the lookup's own tables); several (up to MAX_PROFILES) recompile it
   * once with PROFILE_COUNT, each pixel then reading its slot's tables from the ProfileStack.
   * @param {readonly ProfileLookup[]} lookups
   */
  setProfiles(lookups) {
    if (!Array.isArray(lookups) || !lookups.every((lookup) => lookup instanceof ProfileLookup)) {
      throw new TypeError(`SubsurfaceBlurPass.setProfiles: lookups must be an array of ProfileLookup, one per slot, got ${describe(lookups)}`);
    }
    if (lookups.length > MAX_PROFILES) throw new RangeError(`SubsurfaceBlurPass.setProfiles: lookups holds at most ${MAX_PROFILES} profiles, got ${lookups.length}`);
    if (lookups.length <= 1) this.profileStack.dispose(); // one profile reads its lookup's own tables
    /** The profiles' tables, by slot (empty: none, 'taps' mode only). */
    this.profileLookups = [...lookups];
    this.profileLookup = lookups[0] ?? null;
    if (this.footprintTable) this.footprintTable.lookup = this.profileLookup;
    this.uniforms.tProfile.value = this.profileLookup?.texture ?? null;
    setDefines(this.material, { PROFILE_COUNT: Math.max(lookups.length, 1) });
  }

  /**
   * The reach of the kernel, mm: below half a pixel of it a pixel does no work. 'taps': the outermost
   * tap; 'footprint': the radius holding 99 % of the marginal (its tail is sampled at least a pixel
   * out); the widest profile's.
   */
  get radiusMm() {
    return this.mode === 'footprint' ? Math.max(...this.profileLookups.map((lookup) => lookup.marginalRadiusMm)) : Math.max(...this.slotKernels.map(kernelRadiusMm));
  }

  /** What the footprint table is built for: 'auto', or the kernel's tap count. */
  get footprintSamples() {
    return this.autoFootprints ? 'auto' : this.kernel.length / 4;
  }

  /** @param {'taps'|'footprint'} mode see the constructor */
  setMode(mode) {
    checkOneOf('mode', mode, KERNEL_MODES);
    if (mode === 'footprint' && !this.profileLookup) {
      throw new TypeError("SubsurfaceBlurPass.setMode: the 'footprint' mode needs the pass to have a profileLookup");
    }
    setDefines(this.material, enumDefines('KERNEL_MODE', KERNEL_MODES, mode));
    this.mode = mode;
    if (mode !== 'footprint') this.groups = 1; // fixed taps blur with one kernel
  }

  /**
   * A uniform change in every mode, never a recompile (the shader is compiled for MAX_TAPS).
   * @param {Float32Array} kernel see computeKernel, at most MAX_TAPS taps ('footprint' mode: its
   *   count is the budget)
   * @param {readonly Float32Array[]} [slotKernels] 'taps' mode with several profiles (setProfiles):
   *   each slot's kernel of the same count, `kernel` first; the shader reads slot p's from row p of
   *   a float texture instead of the `kernel` uniform
   */
  setKernel(kernel, slotKernels = [kernel]) {
    if (!(kernel instanceof Float32Array) || kernel.length < 4 || kernel.length % 4 !== 0) {
      throw new TypeError('SubsurfaceBlurPass: kernel must be a Float32Array of 4 numbers per tap (see computeKernel)');
    }
    if (!kernel.every(Number.isFinite)) throw new RangeError('SubsurfaceBlurPass: kernel holds NaN or Infinity');
    if (kernel.length > MAX_TAPS * 4) throw new RangeError(`SubsurfaceBlurPass: kernel has ${kernel.length / 4} taps, at most ${MAX_TAPS}`);
    // Checked whole before anything changes: a refused call leaves the pass as it was.
    if (!Array.isArray(slotKernels) || slotKernels.length < 1 || slotKernels.length > MAX_PROFILES
      || !slotKernels.every((k) => k instanceof Float32Array && k.length === kernel.length && k.every(Number.isFinite))) {
      throw new TypeError(`SubsurfaceBlurPass.setKernel: slotKernels must be an array of 1..${MAX_PROFILES} finite Float32Arrays as long as kernel (${kernel.length}), one per slot, got ${describe(slotKernels)}`);
    }
    // (weight R, G, B, offset mm) per tap, zero-padded to MAX_TAPS: three uploads a flat array as is.
    const taps = this.uniforms.kernel.value;
    taps.fill(0);
    taps.set(kernel);
    this.uniforms.tapCount.value = kernel.length / 4;
    this.uniforms.kernelRadiusMm.value = kernelRadiusMm(kernel);
    this.kernel = kernel;
    this.slotKernels = slotKernels;
    if (slotKernels.length > 1) this._writeSlotKernels(slotKernels);
    else {
      this.uniforms.tKernels.value?.dispose(); // one profile reads the kernel uniform
      this.uniforms.tKernels.value = null;
    }
  }

  /** Row p of `tKernels`: slot p's kernel, zero-padded to MAX_TAPS like the uniform. */
  _writeSlotKernels(slotKernels) {
    const capacity = MAX_TAPS;
    let texture = this.uniforms.tKernels.value;
    if (!texture || texture.image.width !== capacity || texture.image.height !== slotKernels.length) {
      texture?.dispose();
      texture = new DataTexture(new Float32Array(capacity * 4 * slotKernels.length), capacity, slotKernels.length, RGBAFormat, FloatType);
      texture.minFilter = texture.magFilter = NearestFilter;
      texture.name = 'SubsurfaceBlurPass.slotKernels';
      this.uniforms.tKernels.value = texture;
    }
    texture.image.data.fill(0);
    slotKernels.forEach((k, slot) => texture.image.data.set(k, slot * capacity * 4));
    texture.needsUpdate = true;
  }

  render(renderer, writeBuffer, readBuffer, deltaTime, maskActive) {
    if (this.profileLookup) this.uniforms.marginalRangeMm.value = this.profileLookup.marginalRangeMm;
    if (this.mode === 'footprint' && this.profileLookups.length > 1) {
      this.profileStack.update(this.profileLookups, this.footprintSamples);
      this.uniforms.tProfile.value = this.profileStack.profileTexture;
      this.uniforms.tFootprints.value = this.profileStack.footprintTexture;
      this.uniforms.marginalRangesMm.value = this.profileStack.marginalRangesMm;
    } else if (this.mode === 'footprint') {
      this.uniforms.tProfile.value = this.profileLookup.texture;
      this.uniforms.tFootprints.value = this.footprintTable.update(this.footprintSamples);
    }
    this.uniforms.kernelRadiusMm.value = this.radiusMm;
    // ShaderPass draws `material`: this frame's groups' variant stands in for the draw.
    const base = this.material;
    this.material = this.groupMaterial();
    try {
      super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
    } finally {
      this.material = base;
    }
  }

  dispose() {
    super.dispose();
    for (const variant of this._groupMaterials.values()) variant.dispose();
    this._groupMaterials.clear();
    this.footprintTable?.dispose();
    this.profileStack.dispose();
    this.uniforms.tKernels.value?.dispose();
  }
}

nameClass(SubsurfaceBlurPass, 'SubsurfaceBlurPass'); // its name in messages, minified or not
