// Stage 3 as the orchestrator runs it: the blur's settings (method, taps, profile, strength,
// falloff, on or off), its plan for each frame (planBlur, pure, from these settings and the
// scene's scale), the two separable passes and the dense reference the tests and the bench swap
// them for (useDenseReference), and
// the two targets they write (the horizontal pass's output, then the scattered light). One owner:
// the orchestrator's frame calls `blur.plan(pixelsPerMm)` then `blur.render()`, and its setters
// forward here. Which method does what is BLUR_MODES's (src/3-blur/blurPlan.js) and METHOD_TABLE's.
// The profiles are the orchestrator's (one per slot, src/profiles/profileSlots.js): setProfiles.
// Over 300 lines because it is the stage's one owner: its settings' setters, the kernels of every
// method and profile, the plan, the scissor and the two targets (the passes are their own files).
import { FloatType, NearestFilter, RGBAIntegerFormat, UnsignedIntType, WebGLRenderTarget } from 'three';
import { computeKernel, kernelRadiusMm } from '../profiles/kernel.js';
import { getProfile } from '../profiles/presets.js';
import { AUTO_SAMPLES, METHOD_TABLE, PIPELINE_SCHEMA, checkOption } from '../options.js';
import { blendKernels, blurModeOf, checkProfileCount, planBlur } from './blurPlan.js';
import { SubsurfaceBlurPass } from './SubsurfaceBlurPass.js';
import { KernelGroupTable } from './KernelGroupTable.js';
import { MAX_KERNEL_GROUPS, checkKernelGroups, possibleGroupCounts } from './kernelGroups.js';
import { tableOf } from '../profiles/FootprintTable.js';

const TRANSPARENT_BLACK = new Float32Array(4);
const ZERO_UINTS = new Uint32Array(4);

/**
 * The isotropic blur's target between its passes: two RGBA32UI attachments holding the groups as
 * halves (shaders/3-blur/kernelGroups.glsl); integer textures are read by texelFetch only
 * (nearest, no mipmaps).
 */
function createGroupTarget() {
  const target = new WebGLRenderTarget(1, 1, {
    count: 2, type: UnsignedIntType, format: RGBAIntegerFormat, internalFormat: 'RGBA32UI', depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false,
  });
  const [first, second] = target.textures;
  first.name = 'subsurface.horizontalGroups12';
  second.name = 'subsurface.horizontalGroups34';
  return target;
}

/** The dense reference's loop bound, pixels of radius (it is for validation). */
const DENSE_MAX_RADIUS_PX = 256;

/** What the two separable passes run for a method: footprints snapped to pixels, or fixed taps. */
const passModeOf = (method) => (METHOD_TABLE[method].blur === 'footprint' ? 'footprint' : 'taps');

/** The kernel settings setKernel accepts (the profiles come with setProfiles). */
const KERNEL_SETTINGS = Object.freeze(['method', 'samples', 'strength', 'falloff']);

export class BlurStage {
  /**
   * @param {object} options
   * @param {number} options.type HalfFloatType or FloatType for the scattered light
   * @param {import('../profiles/ProfileLookup.js').ProfileLookup} options.profileLookup the first
   *   profile's tables (setProfiles gives the frame's profiles)
   * @param {import('../options.js').Method} options.method
   * @param {number|'auto'} options.samples
   * @param {number[]} [options.strength]
   * @param {number[]} [options.falloff]
   * @param {object} options.surface SurfacePass options (camera, surface and diffuse textures,
   *   followSurface, depthThresholdWorld, foreshortening)
   * @param {'auto'|number} [options.kernelGroups=1] the isotropic blur's groups (see `kernelGroups`)
   */
  constructor({ type, profileLookup, method, samples, strength, falloff, surface, kernelGroups = 1 }) {
    this.profileLookup = profileLookup;
    /** The profiles' tables by slot; the first one's kernel is the fixed-tap methods'. */
    this.profileLookups = [profileLookup];
    this._scattering = true;
    this._settings = { profile: profileLookup.profile, method: checkOption(PIPELINE_SCHEMA, 'method', method), samples, strength, falloff };
    this._kernels = new WeakMap(); // profile → computed kernels by their arguments: 'auto' switches between a few
    this._surface = surface;
    // Nearest: the passes fetch texels, and a 32-bit float target stays complete without float filtering.
    this._blurTarget = new WebGLRenderTarget(1, 1, { type: FloatType, depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter }); // 32 bits: it carries the depth
    this._blurTarget.texture.name = 'subsurface.horizontal';
    this._kernelGroups = checkKernelGroups(kernelGroups);
    this._checkGroupsMethod(method, this._kernelGroups);
    this._groupTarget = null; // built when a grouped frame first needs it
    this._groupTable = new KernelGroupTable();
    /** The scattered diffuse light, premultiplied by its coverage like the multi-target's. */
    this.scatteredTarget = new WebGLRenderTarget(1, 1, { type, depthBuffer: false });
    this.scatteredTarget.texture.name = 'subsurface.scattered';
    const firstKernel = this._kernelFor(this._startSamples());
    const blur = { ...surface, kernel: firstKernel, mode: passModeOf(method), profileLookup, strength: strength ?? [1, 1, 1], autoFootprints: this._autoFootprints() };
    this.horizontalPass = new SubsurfaceBlurPass({ ...blur, direction: 'horizontal' });
    this.verticalPass = new SubsurfaceBlurPass({ ...blur, direction: 'vertical', diffuseTexture: this._blurTarget.texture });
    this._densePass = null; // built when first asked for
    this._DensePass = null; // its class, handed in by useDenseReference
    this._dense = false; // the dense reference runs instead of the separable passes (useDenseReference)
    this._size = { width: 1, height: 1 };
    this._multisampled = false;
    this._applyCarriedDepth();
    this._scissorKey = null; // the box the targets were last scissored to ('full' or x,y,w,h)
    /** The kernel the separable passes hold (computeKernel's layout). */
    this.kernel = firstKernel;
    this._applySettings();
    /** The last frame's plan (see planBlur). */
    this.lastPlan = { samples: this.kernel.length / 4, kernelPixels: 0, blur: false, fade: 0, tapBlend: null, passes: blurModeOf(method).passes, groups: 1, groupings: null };
  }

  /** @type {import('../options.js').Method} */
  get method() { return this._settings.method; }

  /** The taps asked for: a count, or 'auto'. */
  get samples() { return this._settings.samples; }

  /** Whether the taps are chosen per frame (or per pixel) for the on-screen scale. */
  get autoSamples() { return this._settings.samples === 'auto'; }

  /** The kernel's settings: { profile, samples (this frame's count), strength, falloff }. */
  get kernelOptions() {
    const { profile, strength, falloff } = this._settings;
    return { profile, samples: this.kernel.length / 4, strength, falloff };
  }

  /**
   * Which light carries the depth in its alpha (shaders/common/carriedDepth.glsl): the
   * multi-target's diffuse without MSAA (with it the alpha is the coverage:
   * src/2-scene-split/subsurfaceTarget.js), read by the horizontal pass and the dense reference; and
   * the horizontal pass's output always, read by the vertical pass (with MSAA the coverage then
   * comes from the multi-target's diffuse).
   */
  _applyCarriedDepth() {
    this.horizontalPass.setLightCarriesDepth(!this._multisampled);
    this._densePass?.setLightCarriesDepth(!this._multisampled);
    this.verticalPass.setLightCarriesDepth(true, this._multisampled ? this._surface.diffuseTexture : null);
  }

  /**
   * The isotropic blur's groups ('footprint' only): 1 (default) is the one-kernel blur (exact
   * along the screen axes only); 'auto' takes per frame one group where one is within
   * src/3-blur/kernelGroups.js's budget at the frame's largest on-screen scale (a far head), else
   * MAX_KERNEL_GROUPS (three cost about what four do); 2..4 that many. A count's programs are
   * compiled on the first frame that draws with them, and kept (at most one pair per count).
   * @type {'auto'|number}
   */
  get kernelGroups() { return this._kernelGroups; }

  set kernelGroups(groups) {
    const next = checkKernelGroups(groups);
    this._checkGroupsMethod(this.method, next);
    this._kernelGroups = next;
  }

  /** A count of groups above 1 needs method 'footprint' (RangeError); 'auto' is one kernel for the others. */
  _checkGroupsMethod(method, groups) {
    if (typeof groups === 'number' && groups > 1 && METHOD_TABLE[method].blur !== 'footprint') {
      throw new RangeError(`SubsurfaceScattering: kernelGroups ${groups} needs method 'footprint' (method '${method}' blurs with one kernel); use kernelGroups 1 or 'auto'`);
    }
  }

  /** The most groups a frame may take: MAX_KERNEL_GROUPS when the method and setting group, else 1 (one kernel). */
  get groupCapacity() {
    return METHOD_TABLE[this.method].blur === 'footprint' && this._kernelGroups !== 1 ? MAX_KERNEL_GROUPS : 1;
  }

  /**
   * false turns the blur off (the orchestrator's `scattering`) and releases its targets (the
   * horizontal pass's, the scattered light's, the groups'), which no frame reads until it is on
   * again: three allocates them again on their next use, cleared as the scissor's first frame.
   * @type {boolean}
   */
  get scattering() { return this._scattering; }

  set scattering(on) {
    this._scattering = on;
    if (on) return;
    this._blurTarget.dispose();
    this.scatteredTarget.dispose();
    if (this._groupTarget) this._freeGroupTarget();
    this._scissorKey = null;
  }

  /**
   * The materials the blur's next frames may draw with under the current settings (warm-up,
   * SubsurfaceScattering.compileAsync): both passes' for one kernel, or for each count of groups a
   * frame may take (kernelGroups.js's possibleGroupCounts), and the dense reference's where it is on.
   * @returns {import('three').ShaderMaterial[]}
   */
  warmUpMaterials() {
    if (this._dense) return [this.densePass.material];
    const counts = this.groupCapacity === 1 ? [1] : possibleGroupCounts(this.profileLookups.map((lookup) => lookup.profile), this._kernelGroups);
    return counts.flatMap((count) => [this.horizontalPass.groupMaterial(count), this.verticalPass.groupMaterial(count)]);
  }

  /** The dense 2D reference (useDenseReference), built on first use. */
  get densePass() {
    if (!this._densePass) {
      if (!this._DensePass) throw new Error('BlurStage: the dense reference is reached through useDenseReference (three-separable-sss/internals)');
      this._densePass = new this._DensePass({ ...this._surface, profile: this._settings.profile, maxRadiusPx: DENSE_MAX_RADIUS_PX });
      this._densePass.setSize(this._size.width, this._size.height);
      this._densePass.setMultisampled(this._multisampled);
      this._densePass.setLightCarriesDepth(!this._multisampled);
    }
    return this._densePass;
  }

  /** The passes following the surface (both blurs, and the dense reference once built). */
  get surfacePasses() {
    return [this.horizontalPass, this.verticalPass, ...(this._densePass ? [this._densePass] : [])];
  }

  /** 'footprint' with 'auto': per pixel the fewest taps for its scale, within the AUTO_MAX_SAMPLES budget. */
  _autoFootprints() {
    return this.autoSamples && METHOD_TABLE[this.method].blur === 'footprint';
  }

  /** The count the passes are built with before the first plan: the mode's 'auto' start, or the count asked for. */
  _startSamples() {
    return this.autoSamples ? blurModeOf(this.method).autoSamples(0) : this.samples;
  }

  /** computeKernel for this method's kernel (METHOD_TABLE) with `samples` taps, for `profile` (default: the first slot's), cached. */
  _kernelFor(samples, profile = this._settings.profile) {
    const { method, strength, falloff } = this._settings;
    const args = { profile, samples, strength, falloff, method: METHOD_TABLE[method].kernel };
    const key = JSON.stringify([args.method, samples, strength, falloff]);
    if (!this._kernels.has(profile)) this._kernels.set(profile, new Map());
    const kernels = this._kernels.get(profile);
    if (!kernels.has(key)) kernels.set(key, computeKernel(args));
    return kernels.get(key);
  }

  /**
   * The kernel of a plan for `profile`: its count's, or with tapBlend both counts' as one
   * (blendKernels; the first slot's last one is kept while the blend is the same).
   */
  _kernelOfPlan(plan, profile = this._settings.profile) {
    const blend = plan.tapBlend;
    if (!blend) return this._kernelFor(plan.samples, profile);
    const key = JSON.stringify(blend);
    if (profile === this._settings.profile && this._blended?.key === key) return this._blended.kernel;
    const kernel = blendKernels(this._kernelFor(blend.from, profile), this._kernelFor(blend.to, profile), blend.share);
    if (profile === this._settings.profile) this._blended = { key, kernel };
    return kernel;
  }

  /** Every slot's kernel of `samples` taps (the first is `kernel`'s). */
  _slotKernels(samples) {
    return this.profileLookups.map((lookup) => this._kernelFor(samples, lookup.profile));
  }

  /**
   * What planBlur needs, all of it this stage's own: the reach of each kernel it may choose is
   * read lazily (a kernel is computed once, when a frame first needs its count).
   * @returns {import('./blurPlan.js').BlurSettings}
   */
  get planSettings() {
    const counts = this.autoSamples ? AUTO_SAMPLES : [this.samples];
    const kernelReachMm = {};
    const reachOf = (n) => Math.max(...this._slotKernels(n).map(kernelRadiusMm)); // the widest profile's
    for (const n of counts) Object.defineProperty(kernelReachMm, n, { enumerable: true, get: () => reachOf(n) });
    return {
      method: this.method,
      samples: this.samples,
      scattering: this.scattering,
      marginalRadiusMm: Math.max(...this.profileLookups.map((lookup) => lookup.marginalRadiusMm)),
      dense: this._dense,
      denseRadiusMm: this._dense ? this.densePass.radiusMm : 0,
      kernelReachMm,
      kernelGroups: this.groupCapacity > 1 ? this._kernelGroups : 1,
      profiles: this.profileLookups.map((lookup) => lookup.profile),
    };
  }

  /**
   * Plans this frame (planBlur) and gives the separable passes the kernel of the planned count: a
   * uniform change, never a recompile (the shaders are compiled for the most taps).
   * @param {number} pixelsPerMm the largest on-screen size of a profile mm this frame
   * @returns {import('./blurPlan.js').BlurPlan}
   */
  plan(pixelsPerMm) {
    const plan = planBlur(this.planSettings, pixelsPerMm);
    const kernel = plan.passes === 'separable' ? this._kernelOfPlan(plan) : this.kernel;
    if (kernel !== this.kernel) this._setPassKernels(kernel, plan);
    this.lastPlan = plan;
    return plan;
  }

  /**
   * Stage 3 over the multi-target, into scatteredTarget, as `plan` says.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Camera} camera the camera of the scene split
   * @param {(stage: string, draw: () => void) => void} timed runs each pass, timed as `stage`
   * @param {import('./blurPlan.js').BlurPlan} [plan] the frame's plan (default: the last one)
   * @param {{ x: number, y: number, width: number, height: number }|null} [box=null] the subsurface
   *   pixels' screen box (src/2-scene-split/subsurfaceScreenBox.js); null: the whole frame
   * @param {string} [clearKey] what the targets' clears follow (renderViews: all the views' boxes;
   *   default: `box`)
   */
  render(renderer, camera, timed, plan = this.lastPlan, box = null, clearKey = undefined) {
    for (const pass of this.surfacePasses) pass.camera = camera;
    if (this.groupCapacity > 1) this._ensureGroupTarget();
    else if (this._groupTarget) this._freeGroupTarget(); // back to one kernel: its 32 B per pixel go
    const kernel = plan.passes === 'separable' ? this._kernelOfPlan(plan) : this.kernel; // the plan's, where views plan apart
    if (kernel !== this.kernel) this._setPassKernels(kernel, plan);
    // The scissor's clears (when the box moved) are timed with the first pass.
    const scissored = () => this._scissor(renderer, box, clearKey);
    if (plan.passes === 'dense') {
      timed('dense', () => { scissored(); this.densePass.render(renderer, this.scatteredTarget, null); });
    } else {
      timed('blurH', () => {
        scissored();
        this.horizontalPass.render(renderer, this._horizontalTarget(plan), null);
      });
      timed('blurV', () => this.verticalPass.render(renderer, this.scatteredTarget, null));
    }
  }

  /**
   * Stage 3 for each of an ArrayCamera's views (src/support/cameraViews.js): each view with its own
   * camera, plan and subsurface box, into its own rectangle of the targets, its taps inside it, as
   * that view drawn alone with its camera would be blurred. The targets are cleared once where the
   * boxes moved; a view its plan does not blur is left out (the compose shows its unblurred light).
   * @param {import('three').WebGLRenderer} renderer
   * @param {{ camera: import('three').Camera, viewport: object, rect: object, plan: import('./blurPlan.js').BlurPlan, box: object }[]} views
   *   box: the view's subsurface pixels in the target (within rect)
   * @param {(stage: string, draw: () => void) => void} timed
   */
  renderViews(renderer, views, timed) {
    const clearKey = `views:${views.map(({ plan, box }) => (plan.blur ? `${box.x},${box.y},${box.width},${box.height}` : '-')).join(';')}`;
    try {
      for (const view of views) {
        if (!view.plan.blur || view.box.width === 0) continue;
        for (const pass of this.surfacePasses) pass.setView(view.rect, view.viewport);
        this.render(renderer, view.camera, timed, view.plan, view.box, clearKey);
      }
    } finally {
      for (const pass of this.surfacePasses) pass.setSize(this._size.width, this._size.height);
    }
  }

  /**
   * The horizontal pass's target for the frame, with both passes given the frame's groups (their
   * fraction table, energies and the group target's attachments); one group blurs as without them.
   * @param {import('./blurPlan.js').BlurPlan} plan
   */
  _horizontalTarget(plan) {
    if (this.groupCapacity === 1 || !plan.groupings) { // one kernel (a plan made before the setting changed, too)
      for (const pass of [this.horizontalPass, this.verticalPass]) pass.setGroupFrame({ count: 1 });
      return this._blurTarget;
    }
    this._groupFrame(plan.groupings);
    return this._groupTarget;
  }

  /** Gives both passes the groups of `groupings` (per slot) and the group target, built on first use. */
  _groupFrame(groupings) {
    this._ensureGroupTarget();
    const samples = this.horizontalPass.footprintSamples;
    const fractions = this._groupTable.update(groupings, this.profileLookups.map((lookup) => tableOf(lookup, samples)));
    const frame = { count: Math.max(...groupings.map((g) => g.count)), fractions, energies: this._groupTable.energies };
    this.horizontalPass.setGroupFrame(frame);
    this.verticalPass.setGroupFrame({ ...frame, groups: this._groupTarget.textures, coverage: this._surface.diffuseTexture });
  }

  _freeGroupTarget() {
    this._groupTarget.dispose();
    this._groupTarget = null;
    this._scissorKey = null;
  }

  /** The group target, built when groups first become possible (then cleared and scissored with the others). */
  _ensureGroupTarget() {
    if (this._groupTarget) return;
    this._groupTarget = createGroupTarget();
    this._groupTarget.setSize(this._size.width, this._size.height);
    this._scissorKey = null;
  }

  /**
   * Scissors the targets to `box` (null: none). Outside it the passes would write 0 (the diffuse
   * attachment is 0 off subsurface pixels), so the targets are cleared to 0 whenever the box moves
   * (`clearKey`: the boxes of all the frame's views, where there are several): the vertical pass's
   * taps and any reader of scatteredTarget then find what an unscissored frame leaves there.
   */
  _scissor(renderer, box, clearKey = box ? `${box.x},${box.y},${box.width},${box.height}` : 'full') {
    const targets = [this._blurTarget, this.scatteredTarget, ...(this._groupTarget ? [this._groupTarget] : [])];
    if (clearKey !== this._scissorKey) {
      const previous = renderer.getRenderTarget();
      const gl = renderer.getContext();
      for (const target of targets) {
        target.scissorTest = false;
        if (!box) continue;
        renderer.setRenderTarget(target);
        // not renderer.clear: its colour is the scene's (and gl.clear leaves integer attachments undefined)
        if (target === this._groupTarget) target.textures.forEach((_, i) => gl.clearBufferuiv(gl.COLOR, i, ZERO_UINTS));
        else gl.clearBufferfv(gl.COLOR, 0, TRANSPARENT_BLACK);
      }
      if (box) renderer.setRenderTarget(previous);
      this._scissorKey = clearKey;
    }
    for (const target of targets) {
      target.scissorTest = box !== null;
      if (box) target.scissor.set(box.x, box.y, box.width, box.height);
    }
  }

  /**
   * The frame's profiles, by slot (src/profiles/profileSlots.js): the first one's kernel is the
   * fixed-tap methods' and the dense reference's; several need a method that blurs several
   * (METHOD_TABLE's `profiles`: a RangeError otherwise, the stage unchanged). Their tables are
   * the caller's (refilled by it); here only the passes are pointed at them.
   * @param {readonly import('../profiles/ProfileLookup.js').ProfileLookup[]} lookups one or more
   */
  setProfiles(lookups) {
    this.checkProfileCount(this.method, lookups.length);
    const first = lookups[0];
    this.profileLookups = [...lookups];
    this.profileLookup = first;
    for (const pass of [this.horizontalPass, this.verticalPass]) pass.setProfiles(lookups);
    this._settingsChanged({ ...this._settings, profile: first.profile });
  }

  /**
   * Changes kernel settings: { method, samples, strength, falloff } (checked here; each left out
   * keeps its value). A change of method between 'footprint' and the fixed-tap ones recompiles the
   * blur shaders once; nothing else does.
   * @param {{ method?: string, samples?: number|'auto', strength?: number[], falloff?: number[] }} options
   */
  setKernel(options = {}) {
    const next = { ...this._settings };
    for (const name of KERNEL_SETTINGS) {
      if (!Object.hasOwn(options, name)) continue;
      // undefined: back to the method's own (strength, falloff have no default of their own)
      next[name] = options[name] === undefined && PIPELINE_SCHEMA[name].default === undefined ? undefined : checkOption(PIPELINE_SCHEMA, name, options[name]);
    }
    this.checkProfileCount(next.method, this.profileLookups.length);
    this._checkGroupsMethod(next.method, this._kernelGroups);
    this._settingsChanged(next);
  }

  /**
   * Refuses `count` profiles in one frame that `method` (or the dense reference, while it runs)
   * cannot blur: checkProfileCount's RangeError.
   * @param {import('../options.js').Method} method @param {number} count
   */
  checkProfileCount(method, count) {
    checkProfileCount(method, count, this._dense);
  }

  /**
   * Validation only: true runs the dense 2D reference (DenseSubsurfacePass) instead of the
   * separable passes, false the passes again; a RangeError (nothing changed) with several profiles.
   * @param {boolean} enabled
   * @param {typeof import('./DenseSubsurfacePass.js').DenseSubsurfacePass} DensePass the pass's class
   */
  setDenseReference(enabled, DensePass) {
    checkProfileCount(this.method, this.profileLookups.length, enabled);
    this._DensePass = DensePass; // handed in, so the pass and its shader stay out of the product's bundle
    this._dense = enabled;
  }

  /** Takes `next` settings: the kernel first (a setting computeKernel refuses leaves the stage as it was), then the passes. */
  _settingsChanged(next) {
    const profileChanged = next.profile !== this._settings.profile;
    for (const profile of new Set([next.profile, ...this.profileLookups.map((lookup) => lookup.profile)])) this._warnBuiltInKernel(next.method, profile);
    // The kernel first: a setting computeKernel refuses leaves the stage as it was.
    const previous = this._settings;
    this._settings = next;
    try {
      this.kernel = this._kernelFor(this._startSamples());
    } catch (error) {
      this._settings = previous;
      throw error;
    }
    if (profileChanged) this._densePass?.setProfile(next.profile);
    this._applySettings();
  }

  /** Gives both separable passes the settings' mode, kernel and strength. */
  _applySettings() {
    const mode = passModeOf(this.method);
    for (const pass of [this.horizontalPass, this.verticalPass]) {
      pass.autoFootprints = this._autoFootprints();
      pass.setMode(mode);
      pass.setStrength(this._settings.strength ?? [1, 1, 1]);
    }
    this._setPassKernels(this.kernel);
  }

  /** @param {Float32Array} kernel @param {import('./blurPlan.js').BlurPlan} [plan] the plan it is for (a tapBlend's slots blend too) */
  _setPassKernels(kernel, plan) {
    const slotKernels = passModeOf(this.method) !== 'taps' ? [kernel] // footprints read the tables
      : plan?.tapBlend ? this.profileLookups.map((lookup) => this._kernelOfPlan(plan, lookup.profile)) : this._slotKernels(kernel.length / 4);
    for (const pass of [this.horizontalPass, this.verticalPass]) pass.setKernel(kernel, slotKernels);
    this.kernel = kernel;
  }

  /**
   * Method 'reference' is Jimenez 2012's kernel with its skin profile built in (REFERENCE §3): any
   * other profile then drives only transmittance. Said once per profile, not silently.
   */
  _warnBuiltInKernel(method, profile) {
    if (METHOD_TABLE[method].kernel !== 'reference' || profile === getProfile('skin')) return;
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
    this._applyCarriedDepth();
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this._size = { width, height };
    this._scissorKey = null; // setSize resets the targets' scissors
    for (const pass of this.surfacePasses) pass.setSize(width, height);
    this._blurTarget.setSize(width, height);
    this._groupTarget?.setSize(width, height);
    this.scatteredTarget.setSize(width, height);
  }

  dispose() {
    for (const pass of this.surfacePasses) pass.dispose();
    this._blurTarget.dispose();
    this._groupTarget?.dispose();
    this._groupTable.dispose();
    this.scatteredTarget.dispose();
  }
}
