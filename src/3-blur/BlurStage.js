// Stage 3 as the orchestrator runs it: the kernel settings (method, taps, profile, strength,
// falloff), the two separable passes and the dense reference they can be swapped for, and the two
// targets they write (the horizontal pass's output, then the scattered light). One object, so
// the orchestrator's frame calls `blur.render()` and its setters forward here.
import { WebGLRenderTarget } from 'three';
import { computeKernel, kernelRadiusMm } from '../profiles/kernel.js';
import { getProfile } from '../profiles/presets.js';
import { checkOneOf } from '../support/parameterChecks.js';
import { booleanFields } from '../support/booleanFields.js';
import { METHODS, METHOD_TABLE } from '../options.js';
import { AUTO_MAX_SAMPLES } from '../profiles/footprints.js';
import { autoSampleCount } from '../framePlan.js';
import { SubsurfaceBlurPass } from './SubsurfaceBlurPass.js';
import { DenseSubsurfacePass } from './DenseSubsurfacePass.js';

const TRANSPARENT_BLACK = new Float32Array(4);

/** The dense reference's loop bound, pixels of radius (method 'dense' is for validation). */
const DENSE_MAX_RADIUS_PX = 256;

/** The separable passes' mode for a method: footprints snapped to pixels, or fixed taps. */
const blurModeOf = (method) => (METHOD_TABLE[method].blur === 'footprint' ? 'footprint' : 'taps');

export class BlurStage {
  /**
   * @param {object} options
   * @param {number} options.type HalfFloatType or FloatType for the two targets
   * @param {import('../profiles/ProfileLookup.js').ProfileLookup} options.profileLookup the pipeline's
   *   profile tables (refilled here when the profile changes)
   * @param {string} options.method one of METHODS
   * @param {number|'auto'} options.samples
   * @param {number[]} [options.strength]
   * @param {number[]} [options.falloff]
   * @param {object} options.surface SurfacePass options (camera, surface and diffuse textures,
   *   followSurface, depthThresholdWorld, foreshortening)
   */
  constructor({ type, profileLookup, method, samples, strength, falloff, surface }) {
    checkOneOf('method', method, METHODS);
    this.profileLookup = profileLookup;
    this.method = method;
    this.autoSamples = samples === 'auto';
    this.kernelOptions = { profile: profileLookup.profile, samples: this.autoSamples ? this._autoStart(method) : samples, strength, falloff };
    this._kernels = new Map(); // computed kernels by their arguments: 'auto' switches between a few
    this.kernel = this._computeKernel(this.kernelOptions, method);
    this._surface = surface;
    this._blurTarget = new WebGLRenderTarget(1, 1, { type, depthBuffer: false });
    this._blurTarget.texture.name = 'subsurface.horizontal';
    /** The scattered diffuse light, premultiplied by its coverage like the multi-target's. */
    this.scatteredTarget = new WebGLRenderTarget(1, 1, { type, depthBuffer: false });
    this.scatteredTarget.texture.name = 'subsurface.scattered';
    const blur = {
      ...surface, kernel: this.kernel, mode: blurModeOf(method), profileLookup, strength: strength ?? [1, 1, 1], autoFootprints: this._autoFootprints(),
    };
    this.horizontalPass = new SubsurfaceBlurPass({ ...blur, direction: 'horizontal' });
    this.verticalPass = new SubsurfaceBlurPass({ ...blur, direction: 'vertical', diffuseTexture: this._blurTarget.texture });
    this._densePass = null; // built when first asked for
    this._size = { width: 1, height: 1 };
    this._multisampled = false;
    /**
     * Documented-internal switch (issue 19; the bench undoes it for one measure): the passes are
     * scissored to the subsurface pixels' screen box (render's `box`). false: the whole frame.
     */
    this.confineToSubsurface = true;
    this._scissorKey = null; // the box the targets were last scissored to ('full' or x,y,w,h)
  }

  /** The dense 2D reference (method 'dense'), built on first use. */
  get densePass() {
    if (!this._densePass) {
      this._densePass = new DenseSubsurfacePass({ ...this._surface, profile: this.kernelOptions.profile, maxRadiusPx: DENSE_MAX_RADIUS_PX });
      this._densePass.setSize(this._size.width, this._size.height);
      this._densePass.setMultisampled(this._multisampled);
    }
    return this._densePass;
  }

  /** The passes following the surface (both blurs, and the dense reference once built). */
  get surfacePasses() {
    return [this.horizontalPass, this.verticalPass, ...(this._densePass ? [this._densePass] : [])];
  }

  /** The taps asked for: a count, or 'auto'. */
  get samples() {
    return this.autoSamples ? 'auto' : this.kernelOptions.samples;
  }

  /**
   * 'auto': footprints choose their taps per pixel from the table (the kernel only bounds them), so
   * the frame keeps AUTO_MAX_SAMPLES; fixed-tap kernels take the frame's count (autoSampleCount).
   * @param {number} radiusPx the on-screen radius holding 99 % of the marginal's energy
   */
  autoSamplesFor(radiusPx) {
    return this._autoFootprints() ? AUTO_MAX_SAMPLES : autoSampleCount(radiusPx);
  }

  _autoFootprints(method = this.method) {
    return this.autoSamples && METHOD_TABLE[method].blur === 'footprint';
  }

  /** The kernel's count when 'auto' starts: the footprints' bound, or a middle count for fixed taps. */
  _autoStart(method) {
    return METHOD_TABLE[method].blur === 'footprint' ? AUTO_MAX_SAMPLES : 17;
  }

  /** The blur's reach with `samples` taps, mm: below half a pixel of it nothing moves. */
  radiusMmOf(samples) {
    const blur = METHOD_TABLE[this.method].blur;
    if (blur === 'dense') return this.densePass.radiusMm;
    if (blur === 'footprint') return this.profileLookup.marginalRadiusMm;
    return kernelRadiusMm(this._computeKernel({ ...this.kernelOptions, samples }, this.method));
  }

  /**
   * Stage 3 over the multi-target, into scatteredTarget.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Camera} camera the camera of the scene split
   * @param {(stage: string, draw: () => void) => void} timed runs each pass, timed as `stage`
   * @param {{ x: number, y: number, width: number, height: number }|null} [box=null] the subsurface
   *   pixels' screen box (src/2-scene-split/subsurfaceScreenBox.js); null: the whole frame
   */
  render(renderer, camera, timed, box = null) {
    for (const pass of this.surfacePasses) pass.camera = camera;
    // The scissor's clears (when the box moved) are timed with the first pass.
    const scissored = () => this._scissor(renderer, this.confineToSubsurface ? box : null);
    if (METHOD_TABLE[this.method].blur === 'dense') {
      timed('dense', () => { scissored(); this.densePass.render(renderer, this.scatteredTarget, null); });
    } else {
      timed('blurH', () => { scissored(); this.horizontalPass.render(renderer, this._blurTarget, null); });
      timed('blurV', () => this.verticalPass.render(renderer, this.scatteredTarget, null));
    }
  }

  /**
   * Scissors both targets to `box` (null: none). Outside it the passes would write 0 (the diffuse
   * attachment is 0 off subsurface pixels), so a target is cleared to 0 whenever the box moves:
   * the vertical pass's taps and any reader of scatteredTarget then find what an unscissored
   * frame leaves there.
   */
  _scissor(renderer, box) {
    const key = box ? `${box.x},${box.y},${box.width},${box.height}` : 'full';
    if (key === this._scissorKey) return;
    const previous = renderer.getRenderTarget();
    const gl = renderer.getContext();
    for (const target of [this._blurTarget, this.scatteredTarget]) {
      target.scissorTest = false;
      if (box) {
        renderer.setRenderTarget(target);
        gl.clearBufferfv(gl.COLOR, 0, TRANSPARENT_BLACK); // not renderer.clear: its colour is the scene's
        target.scissor.set(box.x, box.y, box.width, box.height);
        target.scissorTest = true;
      }
    }
    if (box) renderer.setRenderTarget(previous);
    this._scissorKey = key;
  }

  /** computeKernel for `method` (see METHOD_TABLE: 'footprint' builds on the marginal kernel), cached. */
  _computeKernel(options, method) {
    const args = { ...options, method: METHOD_TABLE[method].kernel };
    const key = JSON.stringify([args.profile.name, args.method, args.samples, args.strength, args.falloff]);
    if (!this._kernels.has(key)) this._kernels.set(key, computeKernel(args));
    return this._kernels.get(key);
  }

  /**
   * Rebuilds the kernel (and the profile tables when the profile changes).
   * @param {{ profile?: string|object, method?: string, samples?: number|'auto', strength?: number[], falloff?: number[] }} options
   */
  setKernel({ method = this.method, samples, ...options } = {}) {
    checkOneOf('method', method, METHODS);
    if (samples === 'auto') {
      this.autoSamples = true;
      options.samples = this._autoStart(method);
    } else if (samples !== undefined) {
      this.autoSamples = false;
      options.samples = samples;
    } else if (this.autoSamples && this._autoFootprints(method) !== this._autoFootprints()) {
      options.samples = this._autoStart(method); // 'auto' kept across a switch of method
    }
    this.applyKernel(options, method);
  }

  /** Sets kernel options without touching 'auto' (the frame plan's taps go through here). */
  applyKernel(options, method = this.method) {
    const next = { ...this.kernelOptions, ...options };
    if (options.profile !== undefined) next.profile = getProfile(options.profile);
    const kernel = this._computeKernel(next, method);
    this._warnBuiltInKernel(method, next.profile);
    const profileChanged = next.profile !== this.profileLookup.profile;
    this.kernelOptions = next;
    this.method = method;
    this.kernel = kernel;
    if (profileChanged) {
      this.profileLookup.setProfile(next.profile); // tens of ms: only on a change
      this._densePass?.setProfile(next.profile);
    }
    for (const pass of [this.horizontalPass, this.verticalPass]) {
      pass.autoFootprints = this._autoFootprints(method);
      pass.setMode(blurModeOf(method));
      pass.setKernel(kernel);
      pass.setStrength(next.strength ?? [1, 1, 1]);
    }
  }

  /**
   * Method 'reference' is Jimenez 2012's kernel with its skin profile built in (REFERENCE §3): any
   * other profile then drives only transmittance. Said once per profile, not silently.
   */
  _warnBuiltInKernel(method, profile) {
    if (method !== 'reference' || profile === getProfile('skin')) return;
    this._warnedProfiles ??= new WeakSet();
    if (this._warnedProfiles.has(profile)) return;
    this._warnedProfiles.add(profile);
    console.warn(
      `SubsurfaceScattering: method 'reference' blurs with Jimenez's built-in skin kernel (strength and falloff shape it); ` +
      `profile ${profile.name ? `'${profile.name}'` : '(custom)'} is used for transmittance only. Use method 'footprint' or 'marginal' to blur with it.`,
    );
  }

  /** @param {'drop'|'lerp'|'off'} mode @param {number} depthThresholdWorld */
  setFollowSurface(mode, depthThresholdWorld) {
    for (const pass of this.surfacePasses) pass.setFollowSurface(mode, depthThresholdWorld);
    Object.assign(this._surface, { followSurface: mode, depthThresholdWorld });
  }

  /** @param {boolean} enabled */
  setForeshortening(enabled) {
    for (const pass of this.surfacePasses) pass.setForeshortening(enabled);
    this._surface.foreshortening = enabled;
  }

  /** @param {boolean} multisampled the multi-target is MSAA-resolved (see SurfacePass.setMultisampled) */
  setMultisampled(multisampled) {
    for (const pass of this.surfacePasses) pass.setMultisampled(multisampled);
    this._multisampled = multisampled;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this._size = { width, height };
    this._scissorKey = null; // setSize resets the targets' scissors
    for (const pass of this.surfacePasses) pass.setSize(width, height);
    this._blurTarget.setSize(width, height);
    this.scatteredTarget.setSize(width, height);
  }

  dispose() {
    for (const pass of this.surfacePasses) pass.dispose();
    this._blurTarget.dispose();
    this.scatteredTarget.dispose();
  }
}

booleanFields(BlurStage.prototype, ['confineToSubsurface']);
