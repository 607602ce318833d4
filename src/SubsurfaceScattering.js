// The orchestrator: owns the stages and wires them into an EffectComposer, so a user writes
//   const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 50 });
//   sss.makeSubsurface(skinMaterial);
//   sss.addTo(composer);            // instead of a RenderPass
//   composer.addPass(new OutputPass());
// Pipeline: light depth (stage 1) → scene split (2) → horizontal blur → vertical blur (3) → compose (4).
import { HalfFloatType, Vector3 } from 'three';
import { computeKernel } from './kernel.js';
import { getProfile } from './profiles.js';
import { checkNumber, checkOneOf } from './parameterChecks.js';
import { describe } from './rendererSupport.js';
import { LightDepthTarget } from './LightDepthTarget.js';
import { ProfileLookup } from './ProfileLookup.js';
import { makeSubsurface as hookMaterial, getSubsurface } from './subsurfaceMaterial.js';
import { SubsurfaceScenePass } from './SubsurfaceScenePass.js';
import { SubsurfaceBlurPass, FOLLOW_SURFACE_MODES } from './SubsurfaceBlurPass.js';
import { SubsurfaceComposePass } from './SubsurfaceComposePass.js';

const _corner = new Vector3();

/** Upper bound on worldUnitInMm and depthThresholdMm: a kilometre per unit; beyond is a mistake. */
const MAX_SCALE_MM = 1e6;

/** Defaults of the per-material options (makeSubsurface). */
const MATERIAL_DEFAULTS = { widthMm: 1, strength: 1, transmittance: true, translucency: 0, shrinkMm: 0.6 };

/** How the blur weighs its taps (see the constructor). */
export const METHODS = ['footprint', 'marginal', 'reference'];

/**
 * Tap budgets 'auto' chooses from: each is compiled once, so few levels keep shader switches rare.
 * The smallest is used whose (samples - 3) / 2 single-pixel footprints per side reach AUTO_REACH of
 * the on-screen radius holding 99 % of the marginal's energy.
 */
export const AUTO_SAMPLES = [5, 9, 13, 17, 25, 33, 45, 63];

/**
 * Measured (docs/BENCH.md, "Footprint taps and auto quality"): the error against the dense reference
 * stops falling once (samples - 3) / 2 reaches 0.6-0.92 of the radius estimate, which is an upper
 * bound (the nearest bounding-box corner); 0.92 is the conservative end.
 */
export const AUTO_REACH = 0.92;

/** Below half a pixel a kernel cannot move light into another pixel (issue: "no work"). */
export const MIN_KERNEL_PIXELS = 0.5;

function checkDepthThreshold(depthThresholdMm) {
  return checkNumber('depthThresholdMm', depthThresholdMm, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' });
}

/**
 * The whole pipeline, wired into an EffectComposer: light depth, scene split, two blurs, compose.
 * `enabled = false` turns the blur off (transmittance stays; see setTransmittance).
 */
export class SubsurfaceScattering {
  /**
   * @param {object} options
   * @param {import('three').Scene} options.scene
   * @param {import('three').Camera} options.camera
   * @param {import('three').SpotLight|import('three').DirectionalLight|null} [options.light=null]
   *   the light shining through thin parts (transmittance); null: no transmittance
   * @param {number} [options.worldUnitInMm=1000] millimetres per world unit (three.js: metres)
   * @param {string|object} [options.profile='skin'] 'skin', 'skinBurley', 'marble', 'milk' or a profile
   * @param {'footprint'|'marginal'|'reference'} [options.method='footprint'] how the blur weighs its taps:
   *   'footprint' snaps the marginal kernel's footprints to pixels and weighs them exactly, per pixel;
   *   'marginal' and 'reference' use computeKernel's fixed taps
   * @param {number|'auto'} [options.samples=17] taps per direction (a budget for 'footprint'), odd,
   *   3..63; 'auto' picks, each frame, the fewest that resolve the on-screen kernel (see AUTO_SAMPLES)
   * @param {number[]} [options.strength] RGB, 0..1: mix with no scattering (reference model)
   * @param {number[]} [options.falloff] RGB, (0, 10]: reference method only
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop']
   * @param {number} [options.depthThresholdMm=6] depth step (mm) treated as another surface
   * @param {boolean} [options.foreshortening=true] narrow the blur on surfaces seen at grazing angles
   * @param {number} [options.lightDepthSize=1024] light depth map resolution, pixels
   * @param {number} [options.type=HalfFloatType] HalfFloatType or FloatType light targets
   */
  constructor({
    scene, camera, light = null, worldUnitInMm = 1000, profile = 'skin', method = 'footprint', samples = 17,
    strength, falloff, followSurface = 'drop', depthThresholdMm = 6, foreshortening = true, lightDepthSize = 1024,
    type = HalfFloatType,
  } = {}) {
    if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScattering: scene must be a THREE.Scene, got ${describe(scene)}`);
    if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScattering: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (light !== null && !(light?.isSpotLight || light?.isDirectionalLight)) {
      throw new TypeError(`SubsurfaceScattering: light must be a THREE.SpotLight, THREE.DirectionalLight or null, got ${describe(light)}`);
    }
    checkNumber('worldUnitInMm', worldUnitInMm, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' });
    checkOneOf('followSurface', followSurface, FOLLOW_SURFACE_MODES);
    checkOneOf('method', method, METHODS);
    this.autoSamples = samples === 'auto';
    if (this.autoSamples) samples = 17;

    this.scene = scene;
    this.camera = camera;
    this.worldUnitInMm = worldUnitInMm;
    this.enabled = true;
    this.method = method;
    this._kernelOptions = { profile: getProfile(profile), samples, strength, falloff };
    this._kernels = new Map(); // computed kernels by their arguments: 'auto' switches between a few
    this.kernel = this._computeKernel(this._kernelOptions, method);
    this.profileLookup = new ProfileLookup(this._kernelOptions.profile);
    this.lightDepth = light ? new LightDepthTarget(light, { size: lightDepthSize }) : null;

    this.scenePass = new SubsurfaceScenePass(scene, camera, { type, lightDepth: this.lightDepth });
    const common = {
      kernel: this.kernel,
      mode: method === 'footprint' ? 'footprint' : 'taps',
      profileLookup: this.profileLookup,
      camera,
      surfaceTexture: this.scenePass.surfaceTexture,
      followSurface,
      depthThresholdWorld: checkDepthThreshold(depthThresholdMm) / worldUnitInMm,
      foreshortening,
      strength: strength ?? [1, 1, 1],
    };
    this.horizontalPass = new SubsurfaceBlurPass({ ...common, direction: 'horizontal', diffuseTexture: this.scenePass.diffuseTexture });
    this.verticalPass = new SubsurfaceBlurPass({ ...common, direction: 'vertical' });
    this.composePass = new SubsurfaceComposePass({
      lightTexture: this.scenePass.lightTexture,
      surfaceTexture: this.scenePass.surfaceTexture,
      unscatteredTexture: this.scenePass.diffuseTexture,
    });
    /** The hooks of the materials made subsurface through this pipeline, with their options. */
    this.materials = new Map();
    this.transmittance = light !== null;
    this.depthThresholdMm = depthThresholdMm;
    this.followSurface = followSurface;
    /** Largest on-screen kernel radius estimated for the last frame, pixels. */
    this.kernelPixels = 0;

    // The scene pass runs first each frame: decide there whether the blur has any work to do.
    const render = this.scenePass.render.bind(this.scenePass);
    this.scenePass.render = (renderer, writeBuffer, readBuffer, deltaTime, maskActive) => {
      render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
      this._updateBlurWork();
    };
  }

  /** The passes in composer order. */
  get passes() {
    return [this.scenePass, this.horizontalPass, this.verticalPass, this.composePass];
  }

  /**
   * Adds the scene pass, both blurs and the compose pass to `composer` (in place of a RenderPass).
   * @param {import('three/addons/postprocessing/EffectComposer.js').EffectComposer} composer
   */
  addTo(composer) {
    if (!composer || typeof composer.addPass !== 'function') {
      throw new TypeError(`SubsurfaceScattering.addTo: composer must be an EffectComposer, got ${describe(composer)}`);
    }
    for (const pass of this.passes) composer.addPass(pass);
    return this;
  }

  /**
   * Makes `material` scatter with this pipeline's profile, scale and light (see makeSubsurface).
   * @param {import('three').MeshStandardMaterial} material
   * @param {{ widthMm?: number, strength?: number, transmittance?: boolean, translucency?: number, shrinkMm?: number }} [options]
   */
  makeSubsurface(material, options = {}) {
    const o = { ...MATERIAL_DEFAULTS, ...this.materials.get(material)?.options, ...options };
    // Checked here too, so a later setTransmittance(true) cannot fail half-way.
    checkNumber('translucency', o.translucency, { min: 0, max: 1, maxExclusive: true });
    checkNumber('shrinkMm', o.shrinkMm, { min: 0, max: 1000, unit: 'mm' });
    const hook = hookMaterial(material, {
      widthMm: o.widthMm,
      strength: o.strength,
      worldUnitInMm: this.worldUnitInMm,
      transmittance: o.transmittance && this.transmittance && this.lightDepth
        ? { lightDepth: this.lightDepth, lookup: this.profileLookup, translucency: o.translucency, shrinkMm: o.shrinkMm }
        : null,
    });
    hook.debugOutput = this._debugOutput();
    this.materials.set(material, { hook, options: o });
    return hook;
  }

  /** Turns transmittance on or off for every material of this pipeline (recompiles them once). */
  setTransmittance(enabled) {
    if (typeof enabled !== 'boolean') throw new TypeError(`setTransmittance: enabled must be a boolean, got ${describe(enabled)}`);
    if (enabled && !this.lightDepth) throw new Error('setTransmittance: this pipeline has no light (pass `light` to the constructor)');
    this.transmittance = enabled;
    this.scenePass.lightDepth = enabled ? this.lightDepth : null; // no light pass when unused
    for (const material of this.materials.keys()) this.makeSubsurface(material);
  }

  /**
   * Shows the final image or one ingredient (see DEBUG_VIEWS of SubsurfaceComposePass): 'final',
   * 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance'.
   */
  setDebugView(view, options) {
    this.composePass.setDebugView(view, options);
    for (const { hook } of this.materials.values()) hook.debugOutput = this._debugOutput();
  }

  _debugOutput() {
    const view = this.composePass.debugView;
    return view === 'thickness' || view === 'transmittance' ? view : 'diffuse';
  }

  /** Fraction of the width, from the left, shown without scattering (0..1; 0 = none). */
  setSplit(fraction) {
    this.composePass.setSplit(fraction);
  }

  /** computeKernel for this pipeline's method ('footprint' builds on the marginal kernel), cached. */
  _computeKernel(options, method) {
    const args = { ...options, method: method === 'reference' ? 'reference' : 'marginal' };
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
    if (profileChanged) this.profileLookup.setProfile(next.profile); // tens of ms: only on a change
    for (const pass of [this.horizontalPass, this.verticalPass]) {
      pass.setMode(method === 'footprint' ? 'footprint' : 'taps');
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
    for (const pass of [this.horizontalPass, this.verticalPass]) pass.setFollowSurface(mode, depthThresholdMm / this.worldUnitInMm);
    this.followSurface = mode;
    this.depthThresholdMm = depthThresholdMm;
  }

  /** @param {boolean} enabled narrow the blur on surfaces seen at grazing angles */
  setForeshortening(enabled) {
    for (const pass of [this.horizontalPass, this.verticalPass]) pass.setForeshortening(enabled);
  }

  /**
   * Estimates the largest on-screen kernel radius (pixels) over the visible subsurface meshes, at
   * the nearest corner of their bounding boxes (an upper bound); skips both blurs when it is under
   * half a pixel.
   */
  _updateBlurWork() {
    const camera = this.camera;
    const size = this.scenePass.renderTarget;
    const p = camera.projectionMatrix.elements;
    const pixelsPerWorldAtUnitDepth = Math.max(p[0] * size.width, p[5] * size.height) / 2;
    const perspective = camera.isPerspectiveCamera === true || p[15] === 0;
    let pixelsPerMm = 0;
    for (const mesh of this.scenePass.subsurfaceMeshes) {
      // Instanced and skinned meshes have boxes of their own (all instances, the posed skin).
      if (typeof mesh.computeBoundingBox === 'function' && !mesh.boundingBox) mesh.computeBoundingBox();
      if (!mesh.geometry.boundingBox) mesh.geometry.computeBoundingBox();
      const box = mesh.boundingBox ?? mesh.geometry.boundingBox;
      let nearest = Infinity;
      for (let corner = 0; corner < 8; corner++) {
        const { min, max } = box;
        _corner.set(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z);
        _corner.applyMatrix4(mesh.matrixWorld).applyMatrix4(camera.matrixWorldInverse);
        nearest = Math.min(nearest, -_corner.z);
      }
      nearest = perspective ? Math.max(nearest, camera.near ?? 1e-6) : 1;
      for (const m of Array.isArray(mesh.material) ? mesh.material : [mesh.material]) {
        if (this.scenePass.categoryOf(m) !== 'subsurface') continue;
        pixelsPerMm = Math.max(pixelsPerMm, (this._widthWorld(m) * pixelsPerWorldAtUnitDepth) / nearest);
      }
    }
    if (this.autoSamples) this._chooseSamples(pixelsPerMm);
    const pixels = this.horizontalPass.radiusMm * pixelsPerMm;
    this.kernelPixels = pixels;
    const blur = this.enabled && pixels >= MIN_KERNEL_PIXELS;
    this.horizontalPass.enabled = blur;
    this.verticalPass.enabled = blur;
    // Without the blurs, compose the unblurred diffuse light straight from the scene pass.
    this.composePass.scatteredTexture = blur ? null : this.scenePass.diffuseTexture;
  }

  /** 'auto' samples: the fewest AUTO_SAMPLES resolving the on-screen kernel pixel by pixel. */
  _chooseSamples(pixelsPerMm) {
    const radiusPx = this.profileLookup.marginalRadiusMm * pixelsPerMm;
    const samples = AUTO_SAMPLES.find((n) => (n - 3) / 2 >= AUTO_REACH * radiusPx) ?? AUTO_SAMPLES[AUTO_SAMPLES.length - 1];
    if (samples !== this._kernelOptions.samples) this._applyKernel({ samples });
  }

  /** World units per kernel millimetre that `material` writes (width × strength). */
  _widthWorld(material) {
    const { sssWidthWorld, sssStrength } = getSubsurface(material).uniforms;
    return sssWidthWorld.value * sssStrength.value;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    for (const pass of this.passes) pass.setSize(width, height);
  }

  /** Frees every target, material, texture and quad the pipeline created, and unhooks its materials. */
  dispose() {
    for (const { hook } of this.materials.values()) hook.dispose();
    this.materials.clear();
    for (const pass of this.passes) pass.dispose();
    this.lightDepth?.dispose();
    this.profileLookup.dispose();
  }
}
