// The orchestrator: screen-space subsurface scattering as one three.js Pass, in place of a
// RenderPass:
//   const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
//   sss.makeSubsurface(skinMaterial);
//   composer.addPass(sss);              // instead of a RenderPass
//   composer.addPass(new OutputPass());
//
// One frame, in order (render() below is this recipe; each stage lives in its own folder):
//   1. light depth   src/1-light-depth/   linear depth seen from the light (transmittance only)
//   2. scene split   src/2-scene-split/   the scene into the multi-target: colour | diffuse | surface
//   3. plan          src/framePlan.js     the kernel's on-screen reach, 'auto' taps, blur skipped
//                                         below half a pixel
//   4. blur          src/3-blur/          horizontal then vertical over the diffuse light (or the
//                                         dense 2D reference), into the scattered target
//   5. compose       src/4-compose/       colour + scattered diffuse into the composer's buffer,
//                                         with the scene's depth
//   6. transparent   src/2-scene-split/   transparent objects blended over it, depth-tested
import { Color, HalfFloatType, WebGLRenderTarget } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { computeKernel, kernelRadiusMm } from './profiles/kernel.js';
import { getProfile } from './profiles/presets.js';
import { ProfileLookup } from './profiles/ProfileLookup.js';
import { checkInteger, checkNumber, checkOneOf } from './support/parameterChecks.js';
import { describe } from './support/rendererSupport.js';
import {
  FOLLOW_SURFACE_MODES, MATERIAL_DEFAULTS, MAX_MULTISAMPLING, MAX_SCALE_MM, METHODS, METHOD_TABLE, PIPELINE_DEFAULTS,
} from './options.js';
import { estimatePixelsPerMm, planFrame } from './framePlan.js';
import { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';
import { makeSubsurface as hookMaterial, getSubsurface, subsurfaceBindingOf } from './2-scene-split/subsurfaceMaterial.js';
import { isShining } from './2-scene-split/transmittance.js';
import { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
import { SubsurfaceBlurPass } from './3-blur/SubsurfaceBlurPass.js';
import { DenseSubsurfacePass } from './3-blur/DenseSubsurfacePass.js';
import { SubsurfaceComposePass } from './4-compose/SubsurfaceComposePass.js';
import { materialOutputOf } from './4-compose/debugViews.js';

export { METHODS, AUTO_SAMPLES, AUTO_REACH } from './options.js';
export { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';

/** The dense reference's loop bound, pixels of radius (method 'dense' is for validation). */
const DENSE_MAX_RADIUS_PX = 256;

function checkDepthThreshold(depthThresholdMm) {
  return checkNumber('depthThresholdMm', depthThresholdMm, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' });
}

export class SubsurfaceScattering extends Pass {
  /**
   * @param {object} options
   * @param {import('three').Scene} options.scene read every frame (assignable)
   * @param {import('three').Camera} options.camera read every frame (assignable)
   * @param {import('three').SpotLight|import('three').DirectionalLight|null} [options.light=null]
   *   the light shining through thin parts (transmittance); null: no transmittance
   * @param {number} [options.worldUnitInMm=1000] millimetres per world unit (three.js: metres)
   * @param {string|object} [options.profile='skin'] 'skin', 'skinBurley', 'marble', 'milk' or a profile
   * @param {'footprint'|'marginal'|'reference'|'dense'} [options.method='footprint'] how the blur
   *   weighs its taps (see METHOD_TABLE in src/options.js)
   * @param {number|'auto'} [options.samples=17] taps per direction (a budget for 'footprint'), odd,
   *   3..63; 'auto' picks, each frame, the fewest that resolve the on-screen kernel (see AUTO_SAMPLES)
   * @param {number[]} [options.strength] RGB, 0..1: mix with no scattering (reference model)
   * @param {number[]} [options.falloff] RGB, (0, 10]: reference method only
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop']
   * @param {number} [options.depthThresholdMm=6] depth step (mm) treated as another surface
   * @param {boolean} [options.foreshortening=true] narrow the blur on surfaces seen at grazing angles
   * @param {number} [options.lightDepthSize=1024] light depth map resolution, pixels
   * @param {number} [options.type=HalfFloatType] HalfFloatType or FloatType light targets
   * @param {number|'auto'} [options.multisampling='auto'] MSAA samples of the scene split (0: none);
   *   'auto' takes the composer buffer's `samples`, so a composer made with samples: 4 antialiases
   */
  constructor(options = {}) {
    super();
    const o = { ...PIPELINE_DEFAULTS, type: HalfFloatType, ...options };
    const { scene, camera, light } = o;
    if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScattering: scene must be a THREE.Scene, got ${describe(scene)}`);
    if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScattering: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (light !== null && !(light?.isSpotLight || light?.isDirectionalLight)) {
      throw new TypeError(`SubsurfaceScattering: light must be a THREE.SpotLight, THREE.DirectionalLight or null, got ${describe(light)}`);
    }
    checkNumber('worldUnitInMm', o.worldUnitInMm, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' });
    checkOneOf('followSurface', o.followSurface, FOLLOW_SURFACE_MODES);
    checkOneOf('method', o.method, METHODS);
    checkDepthThreshold(o.depthThresholdMm);

    this.needsSwap = false; // like RenderPass: it draws into the read buffer
    /** As RenderPass: true clears the target first; false draws over it (see render's step 5). */
    this.clear = true;
    /** As RenderPass: with clear false, true ignores the target's earlier depth. */
    this.clearDepth = false;
    /** As RenderPass: the clear colour and alpha of the scene (null: the renderer's). */
    this.clearColor = null;
    this.clearAlpha = null;
    /** The scene and camera rendered, read every frame. */
    this.scene = scene;
    this.camera = camera;
    this.worldUnitInMm = o.worldUnitInMm;
    /** false turns the blur off: the compose adds the unblurred diffuse light (transmittance stays). */
    this.scattering = true;
    this.autoSamples = o.samples === 'auto';
    this.method = o.method;
    this._kernelOptions = { profile: getProfile(o.profile), samples: this.autoSamples ? 17 : o.samples, strength: o.strength, falloff: o.falloff };
    this._kernels = new Map(); // computed kernels by their arguments: 'auto' switches between a few
    this.kernel = this._computeKernel(this._kernelOptions, o.method);
    this.profileLookup = new ProfileLookup(this._kernelOptions.profile);
    this.lightDepth = light ? new LightDepthTarget(light, { size: o.lightDepthSize }) : null;
    this.transmittance = light !== null;
    this.followSurface = o.followSurface;
    this.depthThresholdMm = o.depthThresholdMm;
    this.foreshortening = o.foreshortening;

    // Stage 2, 3 and 4 passes, and the two targets the blur writes.
    this.scenePass = new SubsurfaceScenePass(scene, camera, { type: o.type, owner: this });
    const surface = this._surfaceOptions();
    const blur = { ...surface, kernel: this.kernel, mode: METHOD_TABLE[o.method].blur === 'footprint' ? 'footprint' : 'taps', profileLookup: this.profileLookup, strength: o.strength ?? [1, 1, 1] };
    this._blurTarget = new WebGLRenderTarget(1, 1, { type: o.type, depthBuffer: false });
    this.scatteredTarget = new WebGLRenderTarget(1, 1, { type: o.type, depthBuffer: false });
    this._blurTarget.texture.name = 'subsurface.horizontal';
    this.scatteredTarget.texture.name = 'subsurface.scattered';
    this.horizontalPass = new SubsurfaceBlurPass({ ...blur, direction: 'horizontal', diffuseTexture: this.scenePass.diffuseTexture });
    this.verticalPass = new SubsurfaceBlurPass({ ...blur, direction: 'vertical', diffuseTexture: this._blurTarget.texture });
    this._densePass = null; // method 'dense', built when first asked for
    this.composePass = new SubsurfaceComposePass({
      colorTexture: this.scenePass.colorTexture,
      surfaceTexture: this.scenePass.surfaceTexture,
      diffuseTexture: this.scenePass.diffuseTexture,
      scatteredTexture: this.scatteredTarget.texture,
      depthTexture: this.scenePass.depthTexture,
    });
    this._size = { width: 1, height: 1 };
    this.multisampling = o.multisampling;
    /** The hooks of the materials made subsurface through this pipeline, with their options. */
    this.materials = new Map();
    /** What the last frame ran: { samples, kernelPixels, blur } (see planFrame). */
    this.plan = { samples: this._kernelOptions.samples, kernelPixels: 0, blur: false };
    /** The largest on-screen kernel radius of the last frame, pixels (plan.kernelPixels). */
    this.kernelPixels = 0;
    /** Optional { begin(stage), end(stage) } around each stage (dev/gpuTimer.js measures with it). */
    this.stageTimer = null;
  }

  render(renderer, writeBuffer, readBuffer) {
    const { scene, camera } = this;
    const target = this.renderToScreen ? null : readBuffer;
    // 1. Light depth: linear depth seen from the light, for transmittance (not for a light that is off).
    if (this.lightDepth && this.transmittance && isShining(this.lightDepth.light, scene, camera)) {
      this._stage('lightDepth', () => this.lightDepth.render(renderer, scene));
    }
    // 2. Scene split: the opaque scene into the multi-target (colour | diffuse | surface | depth),
    //    multisampled as asked (or as the composer's buffer is).
    Object.assign(this.scenePass, { scene, camera });
    this._matchMultisampling(readBuffer);
    this._stage('scene', () => this._withClearColor(renderer, () => this.scenePass.render(renderer)));
    // 3. Plan: the kernel's reach on screen, the taps for 'auto', no blur under half a pixel.
    this.plan = this._planFrame();
    // 4. Blur: the diffuse light, horizontally then vertically (or densely), into scatteredTarget.
    if (this.plan.blur) this.renderScattering(renderer);
    // 5. Compose: colour + the scattered (without blur: the unblurred) diffuse light, and the
    //    scene's depth, into the target: every pixel (clear), or over what it holds (clear false).
    this.composePass.scatteredTexture = this.plan.blur ? this.scatteredTarget.texture : this.scenePass.diffuseTexture;
    this.composePass.renderToScreen = this.renderToScreen;
    this.composePass.setClear(this.clear, this.clearDepth);
    const autoClear = renderer.autoClear;
    renderer.autoClear = false; // the full-screen quad would clear what clear = false keeps
    try {
      this._stage('compose', () => this.composePass.render(renderer, readBuffer, null));
      // 6. Transparent objects over the composed image, depth-tested against the scene.
      this._stage('transparent', () => this.scenePass.renderTransparent(renderer, target));
    } finally {
      renderer.autoClear = autoClear;
    }
  }

  /** MSAA samples of the scene split: 'auto' (the composer buffer's) or 0..MAX_MULTISAMPLING. */
  get multisampling() {
    return this._multisampling;
  }

  set multisampling(samples) {
    if (samples !== 'auto') checkInteger('multisampling', samples, 0, MAX_MULTISAMPLING, "samples (or 'auto')");
    this._multisampling = samples;
  }

  /** Gives the multi-target the samples asked for; the surface passes then read coverage-weighted inputs. */
  _matchMultisampling(readBuffer) {
    const samples = this._multisampling === 'auto' ? (readBuffer?.samples ?? 0) : this._multisampling;
    const target = this.scenePass.renderTarget;
    if (target.samples === samples) return;
    target.samples = samples;
    target.dispose(); // three rebuilds its buffers, multisampled or not, on the next use
    for (const pass of this._surfacePasses()) pass.setMultisampled(samples > 0);
  }

  /** Runs `draw` with this pass's clearColor / clearAlpha, as RenderPass applies them. */
  _withClearColor(renderer, draw) {
    if (this.clearColor === null && this.clearAlpha === null) return draw();
    const colour = renderer.getClearColor(new Color());
    const alpha = renderer.getClearAlpha();
    try {
      renderer.setClearColor(this.clearColor ?? colour, this.clearAlpha ?? alpha);
      return draw();
    } finally {
      renderer.setClearColor(colour, alpha);
    }
  }

  /** Stage 4 alone over the last scene split, into scatteredTarget (the bench re-runs it to time it). */
  renderScattering(renderer) {
    for (const pass of this._surfacePasses()) pass.camera = this.camera;
    if (METHOD_TABLE[this.method].blur === 'dense') {
      this._stage('dense', () => this.densePass.render(renderer, this.scatteredTarget, null));
    } else {
      this._stage('blurH', () => this.horizontalPass.render(renderer, this._blurTarget, null));
      this._stage('blurV', () => this.verticalPass.render(renderer, this.scatteredTarget, null));
    }
  }

  _stage(name, draw) {
    this.stageTimer?.begin(name);
    try {
      draw();
    } finally {
      this.stageTimer?.end(name);
    }
  }

  _planFrame() {
    const { width, height } = this.scenePass.renderTarget;
    const pixelsPerMm = estimatePixelsPerMm(this.scenePass.subsurfaceMeshes, this.camera, { width, height },
      (m) => (this.scenePass.categoryOf(m) === 'subsurface' ? this._widthWorld(m) : undefined));
    const blurMode = METHOD_TABLE[this.method].blur;
    const plan = planFrame({
      scattering: this.scattering,
      pixelsPerMm,
      samples: this.autoSamples ? 'auto' : this._kernelOptions.samples,
      autoRadiusMm: this.profileLookup.marginalRadiusMm,
      radiusMmOf: (samples) => (blurMode === 'dense' ? this.densePass.radiusMm
        : blurMode === 'footprint' ? this.profileLookup.marginalRadiusMm
          : kernelRadiusMm(this._computeKernel({ ...this._kernelOptions, samples }, this.method))),
    });
    if (plan.samples !== this._kernelOptions.samples) this._applyKernel({ samples: plan.samples });
    this.kernelPixels = plan.kernelPixels;
    return plan;
  }

  /** The scene's depth from the last frame (its opaque part), a DepthTexture, for passes of your own. */
  get depthTexture() {
    return this.scenePass.depthTexture;
  }

  /** The stage passes in frame order (each usable on its own). */
  get passes() {
    return [this.scenePass, this.horizontalPass, this.verticalPass, this.composePass];
  }

  /** The dense 2D reference (method 'dense'), built on first use. */
  get densePass() {
    if (!this._densePass) {
      this._densePass = new DenseSubsurfacePass({ ...this._surfaceOptions(), profile: this._kernelOptions.profile, maxRadiusPx: DENSE_MAX_RADIUS_PX });
      this._densePass.setSize(this._size.width, this._size.height);
      this._densePass.setMultisampled(this.scenePass.renderTarget.samples > 0);
    }
    return this._densePass;
  }

  _surfaceOptions() {
    return {
      camera: this.camera, surfaceTexture: this.scenePass.surfaceTexture, diffuseTexture: this.scenePass.diffuseTexture,
      followSurface: this.followSurface, depthThresholdWorld: this.depthThresholdMm / this.worldUnitInMm, foreshortening: this.foreshortening,
    };
  }

  /** The passes following the surface (both blurs, and the dense reference once built). */
  _surfacePasses() {
    return [this.horizontalPass, this.verticalPass, ...(this._densePass ? [this._densePass] : [])];
  }

  /**
   * Adds this pass to `composer` (in place of a RenderPass); the same as composer.addPass(sss).
   * @param {import('three/addons/postprocessing/EffectComposer.js').EffectComposer} composer
   */
  addTo(composer) {
    if (!composer || typeof composer.addPass !== 'function') {
      throw new TypeError(`SubsurfaceScattering.addTo: composer must be an EffectComposer, got ${describe(composer)}`);
    }
    composer.addPass(this);
    return this;
  }

  /**
   * Makes `material` scatter with this pipeline's profile, scale and light (see makeSubsurface).
   * @param {import('three').MeshStandardMaterial} material
   * @param {{ widthMm?: number, widthScale?: number, transmittance?: boolean, translucency?: number, shrinkMm?: number }} [options]
   */
  makeSubsurface(material, options = {}) {
    const { strength, ...rest } = options; // `strength`: widthScale's old name
    const o = { ...MATERIAL_DEFAULTS, ...this.materials.get(material)?.options, ...rest };
    if (strength !== undefined) o.widthScale = checkNumber('strength', strength, { min: 0, max: 1 });
    // Checked here too, so a later setTransmittance(true) cannot fail half-way.
    checkNumber('translucency', o.translucency, { min: 0, max: 1, maxExclusive: true });
    checkNumber('shrinkMm', o.shrinkMm, { min: 0, max: 1000, unit: 'mm' });
    const hook = hookMaterial(material, {
      widthMm: o.widthMm,
      widthScale: o.widthScale,
      worldUnitInMm: this.worldUnitInMm,
      transmittance: o.transmittance && this.transmittance && this.lightDepth
        ? { lightDepth: this.lightDepth, lookup: this.profileLookup, translucency: o.translucency, shrinkMm: o.shrinkMm }
        : null,
    }, this);
    hook.debugOutput = materialOutputOf(this.composePass.debugView);
    this.materials.set(material, { hook, options: o });
    return hook;
  }

  /** Turns transmittance on or off for every material of this pipeline (a uniform: no recompile). */
  setTransmittance(enabled) {
    if (typeof enabled !== 'boolean') throw new TypeError(`setTransmittance: enabled must be a boolean, got ${describe(enabled)}`);
    if (enabled && !this.lightDepth) throw new Error('setTransmittance: this pipeline has no light (pass `light` to the constructor)');
    this.transmittance = enabled;
    for (const material of this.materials.keys()) this.makeSubsurface(material);
  }

  /**
   * Shows the final image or one ingredient (see DEBUG_VIEWS of SubsurfaceComposePass): 'final',
   * 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance'.
   */
  setDebugView(view, options) {
    this.composePass.setDebugView(view, options);
    for (const { hook } of this.materials.values()) hook.debugOutput = materialOutputOf(view);
  }

  /** Fraction of the width, from the left, shown without scattering (0..1; 0 = none). */
  setSplit(fraction) {
    this.composePass.setSplit(fraction);
  }

  /** computeKernel for `method` (see METHOD_TABLE: 'footprint' builds on the marginal kernel), cached. */
  _computeKernel(options, method) {
    const args = { ...options, method: METHOD_TABLE[method].kernel };
    const key = JSON.stringify([args.profile.name, args.method, args.samples, args.strength, args.falloff]);
    if (!this._kernels.has(key)) this._kernels.set(key, computeKernel(args));
    return this._kernels.get(key);
  }

  /**
   * Rebuilds the kernel (and the profile tables when the profile changes). Changing the method
   * between 'footprint' and the fixed-tap ones recompiles the blur shaders once.
   * @param {{ profile?: string|object, method?: string, samples?: number|'auto', strength?: number[], falloff?: number[] }} options
   */
  setKernel({ method = this.method, samples, ...options } = {}) {
    checkOneOf('method', method, METHODS);
    if (samples === 'auto') this.autoSamples = true;
    else if (samples !== undefined) {
      this.autoSamples = false;
      options.samples = samples;
    }
    this._applyKernel(options, method);
  }

  _applyKernel(options, method = this.method) {
    const next = { ...this._kernelOptions, ...options };
    if (options.profile !== undefined) next.profile = getProfile(options.profile);
    const kernel = this._computeKernel(next, method);
    const profileChanged = next.profile !== this.profileLookup.profile;
    this._kernelOptions = next;
    this.method = method;
    this.kernel = kernel;
    if (profileChanged) {
      this.profileLookup.setProfile(next.profile); // tens of ms: only on a change
      this._densePass?.setProfile(next.profile);
    }
    const mode = METHOD_TABLE[method].blur === 'footprint' ? 'footprint' : 'taps';
    for (const pass of [this.horizontalPass, this.verticalPass]) {
      pass.setMode(mode);
      pass.setKernel(kernel);
      pass.setStrength(next.strength ?? [1, 1, 1]);
    }
  }

  /** The kernel's current settings: { profile, samples, strength, falloff }, plus method. */
  get kernelOptions() {
    return { ...this._kernelOptions, method: this.method };
  }

  /**
   * @param {'drop'|'lerp'|'off'} mode
   * @param {number} [depthThresholdMm]
   */
  setFollowSurface(mode, depthThresholdMm = this.depthThresholdMm) {
    checkDepthThreshold(depthThresholdMm);
    for (const pass of this._surfacePasses()) pass.setFollowSurface(mode, depthThresholdMm / this.worldUnitInMm);
    this.followSurface = mode;
    this.depthThresholdMm = depthThresholdMm;
  }

  /** @param {boolean} enabled narrow the blur on surfaces seen at grazing angles */
  setForeshortening(enabled) {
    for (const pass of this._surfacePasses()) pass.setForeshortening(enabled);
    this.foreshortening = enabled;
  }

  /** World units per profile millimetre `material` writes when this pipeline draws it (width × widthScale). */
  _widthWorld(material) {
    return (subsurfaceBindingOf(material, this) ?? getSubsurface(material)).widthWorld;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this._size = { width, height };
    for (const pass of [...this.passes, ...(this._densePass ? [this._densePass] : [])]) pass.setSize(width, height);
    this._blurTarget.setSize(width, height);
    this.scatteredTarget.setSize(width, height);
  }

  /** Frees every target, material, texture and quad the pipeline created, and unhooks its materials. */
  dispose() {
    for (const { hook } of this.materials.values()) hook.dispose();
    this.materials.clear();
    for (const pass of this.passes) pass.dispose();
    this._densePass?.dispose();
    this._blurTarget.dispose();
    this.scatteredTarget.dispose();
    this.lightDepth?.dispose();
    this.profileLookup.dispose();
  }
}
