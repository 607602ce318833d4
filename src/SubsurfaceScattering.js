// The orchestrator: screen-space subsurface scattering as one three.js Pass, in place of a
// RenderPass:
//   const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
//   sss.makeSubsurface(skinMaterial);
//   composer.addPass(sss);              // instead of a RenderPass
//   composer.addPass(new OutputPass());
//
// One frame, in order (render() below is this recipe; each stage lives in its own folder):
//   1. light depth   src/1-light-depth/   linear depth seen from the light (transmittance only)
//   2. scene split   src/2-scene-split/   the opaque scene into the multi-target:
//                                         colour | diffuse | surface | depth
//   3. plan          src/framePlan.js     the kernel's on-screen reach, 'auto' taps, blur skipped
//                                         below half a pixel
//   4. blur          src/3-blur/          horizontal then vertical over the diffuse light (or the
//                                         dense 2D reference), into the scattered target
//   5. compose       src/4-compose/       colour + scattered diffuse into the composer's buffer,
//                                         with the scene's depth
//   6. transparent   src/2-scene-split/   transparent objects blended over it, depth-tested
//
// Over 300 lines because it is the public API: the options' checks, the setters and getters
// (methods, profile, light, sizes, debug views) and their errors are most of it; the frame is
// render() and the stages' own files.
import { FloatType, HalfFloatType } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { getProfile } from './profiles/presets.js';
import { ProfileLookup } from './profiles/ProfileLookup.js';
import { checkBoolean, checkInteger, checkNumber, checkOneOf, checkOptions } from './support/parameterChecks.js';
import { describe } from './support/rendererSupport.js';
import { PASS_BOOLEANS, booleanFields } from './support/booleanFields.js';
import { FrameChecks, checkTargetSize, checkTargetLimits } from './support/frameChecks.js';
import {
  FOLLOW_SURFACE_MODES, MAX_MULTISAMPLING, MAX_SCALE_MM, METHODS, MIN_SCALE_MM, PIPELINE_DEFAULTS, PIPELINE_OPTIONS,
} from './options.js';
import { estimatePixelsPerMm, nearestViewDepth, planFrame } from './framePlan.js';
import { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';
import { PipelineMaterials } from './2-scene-split/PipelineMaterials.js';
import { isShining, lightFromBehind } from './2-scene-split/transmittance.js';
import { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
import { BlurStage } from './3-blur/BlurStage.js';
import { SubsurfaceComposePass } from './4-compose/SubsurfaceComposePass.js';
import { materialOutputOf } from './4-compose/debugViews.js';

export { METHODS, AUTO_SAMPLES, AUTO_REACH } from './options.js';
export { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';

function checkDepthThreshold(depthThresholdMm) {
  return checkNumber('depthThresholdMm', depthThresholdMm, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' });
}

function checkWorldUnit(worldUnitInMm) {
  return checkNumber('worldUnitInMm', worldUnitInMm, { min: MIN_SCALE_MM, max: MAX_SCALE_MM, unit: 'mm' });
}

function checkScene(scene) {
  if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScattering: scene must be a THREE.Scene, got ${describe(scene)}`);
  return scene;
}

function checkCamera(camera) {
  if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScattering: camera must be a THREE.Camera, got ${describe(camera)}`);
  return camera;
}

/** The light depth map's resolution, checked under the pipeline's option name (LightDepthTarget calls it `size`). */
const LIGHT_DEPTH_SIZES = Object.freeze({ min: 16, max: 8192 });

/**
 * new SubsurfaceScattering({ ... }): the defaults are PIPELINE_DEFAULTS.
 * @typedef {object} SubsurfaceScatteringOptions
 * @property {import('three').Scene} scene read every frame (assignable)
 * @property {import('three').Camera} camera read every frame (assignable)
 * @property {import('three').SpotLight|import('three').DirectionalLight|null} [light=null]
 *   the light shining through thin parts (transmittance); null: no transmittance
 * @property {number} [worldUnitInMm=1000] millimetres per world unit (three.js: metres)
 * @property {import('./options.js').ProfileName|object} [profile='skin'] a preset's name or a
 *   profile object (burleyProfile, dipoleProfile, gaussianSumProfile)
 * @property {import('./options.js').Method} [method='footprint'] how the blur weighs its taps
 *   (see METHOD_TABLE in src/options.js)
 * @property {number|'auto'} [samples='auto'] taps per direction (a budget for 'footprint'), odd,
 *   3..63; 'auto': 'footprint' takes per pixel the fewest within AUTO_STEP_ERROR for its scale, the
 *   fixed-tap methods per frame the fewest of AUTO_SAMPLES that resolve the on-screen kernel
 * @property {number[]} [strength] RGB, 0..1: mix with no scattering (reference model)
 * @property {number[]} [falloff] RGB, (0, 10]: reference method only
 * @property {import('./options.js').FollowSurfaceMode} [followSurface='drop']
 * @property {number} [depthThresholdMm=6] depth step (mm) treated as another surface
 * @property {boolean} [foreshortening=true] narrow the blur on surfaces seen at grazing angles
 * @property {number} [lightDepthSize=1024] light depth map resolution, pixels
 * @property {import('three').TextureDataType} [type=HalfFloatType] HalfFloatType or FloatType light targets
 * @property {number|'auto'} [multisampling='auto'] MSAA samples of the scene split (0: none);
 *   'auto' takes the composer buffer's `samples`, so a composer made with samples: 4 antialiases
 */

/**
 * makeSubsurface(material, { ... }) of a pipeline: the defaults are MATERIAL_DEFAULTS.
 * @typedef {object} SubsurfaceMaterialOptions
 * @property {number} [widthMm=1] millimetres of material per profile millimetre (1: physical size)
 * @property {number} [widthScale=1] 0..1, scales the width (0: no scattering, the light kept)
 * @property {number} [strength] widthScale's old name
 * @property {boolean} [transmittance=true] light through thin parts (with the pipeline's light)
 * @property {number} [translucency=0] 0..1 (exclusive)
 * @property {number} [shrinkMm=0.6] how far the light depth lookup moves inwards, mm
 */

/**
 * A stage of one frame, as stageTimer sees it.
 * @typedef {'lightDepth'|'scene'|'blurH'|'blurV'|'dense'|'compose'|'transparent'} StageName
 */

export class SubsurfaceScattering extends Pass {
  /** @param {SubsurfaceScatteringOptions} options */
  constructor(options) {
    super();
    if (options === undefined || options === null || typeof options !== 'object' || Array.isArray(options)) {
      throw new TypeError(`SubsurfaceScattering: options must be an object { scene, camera, ... }, got ${describe(options)}`);
    }
    checkOptions('SubsurfaceScattering options', options, PIPELINE_OPTIONS);
    const o = { ...PIPELINE_DEFAULTS, type: HalfFloatType, ...options };
    const { scene, camera, light } = o;
    checkScene(scene);
    checkCamera(camera);
    if (light !== null && !(light?.isSpotLight || light?.isDirectionalLight)) {
      throw new TypeError(`SubsurfaceScattering: light must be a THREE.SpotLight, THREE.DirectionalLight or null, got ${describe(light)}`);
    }
    checkWorldUnit(o.worldUnitInMm);
    checkOneOf('followSurface', o.followSurface, FOLLOW_SURFACE_MODES);
    checkOneOf('method', o.method, METHODS);
    checkDepthThreshold(o.depthThresholdMm);
    checkBoolean('foreshortening', o.foreshortening);
    if (o.type !== HalfFloatType && o.type !== FloatType) {
      throw new RangeError(`SubsurfaceScattering: type must be THREE.HalfFloatType or THREE.FloatType (light needs HDR targets), got ${describe(o.type)}`);
    }
    checkInteger('lightDepthSize', o.lightDepthSize, LIGHT_DEPTH_SIZES.min, LIGHT_DEPTH_SIZES.max, 'pixels');

    this.needsSwap = false; // like RenderPass: it draws into the read buffer
    /** As RenderPass: true clears the target first; false draws over it (see render's step 5). */
    this.clear = true;
    /** As RenderPass: with clear false, true ignores the target's earlier depth. */
    this.clearDepth = false;
    /**
     * Documented-internal switch (the bench turns it off for one measure: what the skip saves):
     * the light depth pass is skipped while the light reaches no subsurface mesh from behind.
     */
    this.skipsUnreadLightDepth = true;
    this._clearColor = null;
    this._clearAlpha = null;
    this._scene = scene;
    this._camera = camera;
    this._worldUnitInMm = o.worldUnitInMm;
    this._scattering = true;
    this._stageTimer = null;
    this.profileLookup = new ProfileLookup(getProfile(o.profile));
    this.lightDepth = light ? new LightDepthTarget(light, { size: o.lightDepthSize }) : null;
    this._transmittance = light !== null;
    this.depthThresholdMm = o.depthThresholdMm;
    this.multisampling = o.multisampling;
    /** The size setSize last gave, device pixels (checked against the GPU's limits on the next frame). */
    this._size = { width: 1, height: 1 };
    /** The GPU's render target limits, known from the first frame on. */
    this._limits = undefined;
    /** The frame's checks of the camera and the light, each warned about once (see `problems`). */
    this._checks = new FrameChecks('SubsurfaceScattering');

    // Stages 2, 3 and 4.
    this.scenePass = new SubsurfaceScenePass(scene, camera, { type: o.type, owner: this });
    this.blur = new BlurStage({
      type: o.type, profileLookup: this.profileLookup, method: o.method, samples: o.samples, strength: o.strength, falloff: o.falloff,
      surface: {
        camera, surfaceTexture: this.scenePass.surfaceTexture, diffuseTexture: this.scenePass.diffuseTexture,
        followSurface: o.followSurface, depthThresholdWorld: o.depthThresholdMm / o.worldUnitInMm, foreshortening: o.foreshortening,
      },
    });
    this.composePass = new SubsurfaceComposePass({
      colorTexture: this.scenePass.colorTexture,
      surfaceTexture: this.scenePass.surfaceTexture,
      diffuseTexture: this.scenePass.diffuseTexture,
      scatteredTexture: this.blur.scatteredTarget.texture,
      depthTexture: this.scenePass.depthTexture,
    });
    /** The materials made subsurface through this pipeline (see makeSubsurface). */
    this.subsurfaceMaterials = new PipelineMaterials(this, () => ({
      worldUnitInMm: this.worldUnitInMm,
      lightDepth: this.transmittance ? this.lightDepth : null,
      lookup: this.profileLookup,
      debugOutput: materialOutputOf(this.composePass.debugView),
    }));
    /** What the last frame ran: { samples, kernelPixels, blur } (see planFrame). */
    this.plan = { samples: this.blur.kernelOptions.samples, kernelPixels: 0, blur: false };
    /** The largest on-screen kernel radius of the last frame, pixels (plan.kernelPixels). */
    this.kernelPixels = 0;
  }

  /**
   * As RenderPass: the clear colour of the scene (null: the renderer's).
   * @type {import('three').ColorRepresentation|null}
   */
  get clearColor() {
    return this._clearColor;
  }

  set clearColor(color) {
    const ok = color === null || typeof color === 'string' || color?.isColor === true || (typeof color === 'number' && Number.isFinite(color));
    if (!ok) throw new TypeError(`SubsurfaceScattering.clearColor must be null, a THREE.Color, a CSS colour string or a hex number, got ${describe(color)}`);
    this._clearColor = color;
  }

  /**
   * As RenderPass: the clear alpha of the scene, 0..1 (null: the renderer's).
   * @type {number|null}
   */
  get clearAlpha() {
    return this._clearAlpha;
  }

  set clearAlpha(alpha) {
    this._clearAlpha = alpha === null ? null : checkNumber('SubsurfaceScattering.clearAlpha', alpha, { min: 0, max: 1 });
  }

  /**
   * The scene rendered, read every frame (assignable).
   * @type {import('three').Scene}
   */
  get scene() {
    return this._scene;
  }

  set scene(scene) {
    this._scene = checkScene(scene);
  }

  /**
   * The camera rendered with, read every frame (assignable: `sss.camera = otherCamera` switches the view).
   * @type {import('three').Camera}
   */
  get camera() {
    return this._camera;
  }

  set camera(camera) {
    this._camera = checkCamera(camera);
  }

  /**
   * Millimetres per world unit (1000 for metres): assigning it rescales every material of the
   * pipeline and the depth threshold.
   * @type {number}
   */
  get worldUnitInMm() {
    return this._worldUnitInMm;
  }

  set worldUnitInMm(worldUnitInMm) {
    checkWorldUnit(worldUnitInMm);
    this._worldUnitInMm = worldUnitInMm;
    this.blur.setFollowSurface(this.followSurface, this.depthThresholdMm / worldUnitInMm);
    this.subsurfaceMaterials.rebindAll();
  }

  /**
   * false turns the blur off: the compose adds the unblurred diffuse light (transmittance stays).
   * @type {boolean}
   */
  get scattering() {
    return this._scattering;
  }

  set scattering(scattering) {
    this._scattering = checkBoolean('SubsurfaceScattering.scattering', scattering);
  }

  /**
   * Light through thin parts for every material of this pipeline (needs the constructor's `light`);
   * the same as setTransmittance.
   * @type {boolean}
   */
  get transmittance() {
    return this._transmittance;
  }

  set transmittance(enabled) {
    this.setTransmittance(checkBoolean('SubsurfaceScattering.transmittance', enabled));
  }

  /**
   * Optional { begin(stage), end(stage) } around each stage (dev/gpuTimer.js measures with it), or null.
   * @type {{ begin(stage: StageName): void, end(stage: StageName): void }|null}
   */
  get stageTimer() {
    return this._stageTimer;
  }

  set stageTimer(timer) {
    if (timer !== null && !(timer && typeof timer.begin === 'function' && typeof timer.end === 'function')) {
      throw new TypeError(`SubsurfaceScattering.stageTimer must be null or an object with begin(stage) and end(stage) functions, got ${describe(timer)}`);
    }
    this._stageTimer = timer;
  }

  /**
   * What the last frame found wrong with the camera, the light or the scene, one message each (empty
   * when nothing is): each is also warned about on the console, once per pipeline. See the README's
   * "Errors and limits".
   * @type {readonly string[]}
   */
  get problems() {
    return this._checks.current;
  }

  /**
   * One frame into `readBuffer` (or the screen with renderToScreen), as RenderPass draws.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget|null} writeBuffer unused (needsSwap is false)
   * @param {import('three').WebGLRenderTarget} readBuffer
   */
  render(renderer, writeBuffer, readBuffer) {
    const { scene, camera } = this;
    const target = this.renderToScreen ? null : readBuffer;
    // 0. Checks: the size against the GPU's limits (a RangeError), the camera, the light and the
    //    scene (a warning, once each; the frame is drawn as three would draw it).
    this._limits = checkTargetLimits(renderer, this._size, 'SubsurfaceScattering');
    const checks = this._checks.begin();
    checks.camera(camera);
    checks.scene(scene);
    const lightWorks = this.lightDepth !== null && checks.light(this.lightDepth, scene, this._transmittance);
    checks.end();
    // 1. Light depth: linear depth seen from the light, for transmittance (not for a light that is
    //    off, nor one that reaches no subsurface mesh from behind: its map would go unread).
    if (lightWorks && isShining(this.lightDepth.light, scene, camera) && (!this.skipsUnreadLightDepth || this._transmits(scene, camera))) {
      this._stage('lightDepth', () => this.lightDepth.render(renderer, scene));
    } else {
      this.lightDepth?.invalidate();
    }
    // 2. Scene split: the opaque scene into the multi-target (colour | diffuse | surface | depth),
    //    multisampled as asked (or as the composer's buffer is).
    Object.assign(this.scenePass, { scene, camera, clearColor: this.clearColor, clearAlpha: this.clearAlpha });
    const samples = this._multisampling === 'auto' ? (readBuffer?.samples ?? 0) : this._multisampling;
    if (this.scenePass.setSamples(samples)) this.blur.setMultisampled(samples > 0);
    this._stage('scene', () => this.scenePass.render(renderer));
    // 3. Plan: the kernel's reach on screen, the taps for 'auto', no blur under half a pixel.
    this.plan = this._planFrame();
    // 4. Blur: the diffuse light, horizontally then vertically (or densely), into scatteredTarget.
    if (this.plan.blur) this.renderScattering(renderer);
    // 5. Compose: colour + the scattered (without blur: the unblurred) diffuse light, and the
    //    scene's depth, into the target: every pixel (clear), or over what it holds (clear false).
    this.composePass.scatteredTexture = this.plan.blur ? this.blur.scatteredTarget.texture : this.scenePass.diffuseTexture;
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

  /**
   * Stage 4 alone over the last scene split, into scatteredTarget (the bench re-runs it to time it).
   * @param {import('three').WebGLRenderer} renderer
   */
  renderScattering(renderer) {
    this.blur.render(renderer, this.camera, (stage, draw) => this._stage(stage, draw), this.scenePass.subsurfaceBox);
  }

  /** @private @param {StageName} name @param {() => void} draw */
  _stage(name, draw) {
    this.stageTimer?.begin(name);
    try {
      draw();
    } finally {
      this.stageTimer?.end(name);
    }
  }

  /**
   * Whether the light can send transmitted light to a subsurface mesh of this pipeline this frame
   * (lightFromBehind at each one's nearest point); the thickness view always reads the map.
   * @private
   */
  _transmits(scene, camera) {
    if (materialOutputOf(this.composePass.debugView) === 'thickness') return true;
    // The matrices as the scene split's render will see them (three updates them the same way).
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    const { light } = this.lightDepth;
    light.updateMatrixWorld();
    light.target.updateMatrixWorld();
    let transmits = false;
    scene.traverseVisible((object) => {
      if (transmits || !object.isMesh) return;
      const materials = Array.isArray(object.material) ? object.material : [object.material];
      if (materials.some((m) => this.subsurfaceMaterials.entries.get(m)?.options.transmittance) && lightFromBehind(light, camera, nearestViewDepth(object, camera))) transmits = true;
    });
    return transmits;
  }

  /** @private */
  _planFrame() {
    const { width, height } = this.scenePass.renderTarget;
    const pixelsPerMm = estimatePixelsPerMm(this.scenePass.subsurfaceMeshes, this.camera, { width, height },
      (m) => (this.scenePass.categoryOf(m) === 'subsurface' ? this.subsurfaceMaterials.widthWorldOf(m) : undefined));
    const plan = planFrame({
      scattering: this.scattering,
      pixelsPerMm,
      samples: this.blur.samples,
      autoRadiusMm: this.profileLookup.marginalRadiusMm,
      radiusMmOf: (samples) => this.blur.radiusMmOf(samples),
      autoSamples: (radiusPx) => this.blur.autoSamplesFor(radiusPx),
    });
    if (plan.samples !== this.blur.kernelOptions.samples) this.blur.applyKernel({ samples: plan.samples });
    this.kernelPixels = plan.kernelPixels;
    return plan;
  }

  /**
   * MSAA samples of the scene split: 'auto' (the composer buffer's) or 0..MAX_MULTISAMPLING.
   * @type {number|'auto'}
   */
  get multisampling() {
    return this._multisampling;
  }

  set multisampling(samples) {
    if (samples !== 'auto') checkInteger('multisampling', samples, 0, MAX_MULTISAMPLING, "samples (or 'auto')");
    this._multisampling = samples;
  }

  /** The scene's depth from the last frame (its opaque part), a DepthTexture, for passes of your own. */
  get depthTexture() {
    return this.scenePass.depthTexture;
  }

  /** The stage passes in frame order (each usable on its own). */
  get passes() {
    return [this.scenePass, this.blur.horizontalPass, this.blur.verticalPass, this.composePass];
  }

  // Stage 3's parts and settings (see BlurStage).
  get horizontalPass() { return this.blur.horizontalPass; }
  get verticalPass() { return this.blur.verticalPass; }
  /** The dense 2D reference (method 'dense'), built on first use. */
  get densePass() { return this.blur.densePass; }
  /** The last frame's scattered diffuse light. */
  get scatteredTarget() { return this.blur.scatteredTarget; }
  /** @type {Float32Array} the separable kernel (computeKernel's layout) */
  get kernel() { return this.blur.kernel; }
  /** @type {import('./options.js').Method} */
  get method() { return this.blur.method; }
  get autoSamples() { return this.blur.autoSamples; }
  get followSurface() { return this.blur.horizontalPass.followSurface; }
  get foreshortening() { return this.blur.horizontalPass.foreshortening; }
  /** The kernel's current settings: { profile, samples, strength, falloff }, plus method. */
  get kernelOptions() { return { ...this.blur.kernelOptions, method: this.method }; }

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
   * Makes `material` scatter with this pipeline's profile, scale and light (see makeSubsurface):
   * settings of this pipeline's own, so another pipeline can draw the same material with its own.
   * @param {import('three').MeshStandardMaterial} material
   * @param {SubsurfaceMaterialOptions} [options]
   * @returns {import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding}
   */
  makeSubsurface(material, options = {}) {
    return this.subsurfaceMaterials.bind(material, options);
  }

  /**
   * Undoes makeSubsurface for this pipeline: the material renders as without it here, and gets its
   * own shader back once no pipeline has it.
   * @param {import('three').MeshStandardMaterial} material
   * @returns {boolean} whether it was subsurface in this pipeline
   */
  removeSubsurface(material) {
    return this.subsurfaceMaterials.unbind(material);
  }

  /**
   * The materials made subsurface through this pipeline, each with its binding and options.
   * @type {Map<import('three').MeshStandardMaterial, { hook: import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding, options: SubsurfaceMaterialOptions }>}
   */
  get materials() {
    return this.subsurfaceMaterials.entries;
  }

  /**
   * Turns transmittance on or off for every material of this pipeline (a uniform: no recompile).
   * @param {boolean} enabled
   */
  setTransmittance(enabled) {
    if (typeof enabled !== 'boolean') throw new TypeError(`setTransmittance: enabled must be a boolean, got ${describe(enabled)}`);
    if (enabled && !this.lightDepth) {
      throw new TypeError('setTransmittance: light must be a THREE.SpotLight or THREE.DirectionalLight to turn transmittance on, ' +
        'and this pipeline has none (pass `light` to the constructor)');
    }
    this._transmittance = enabled;
    this.subsurfaceMaterials.rebindAll();
  }

  /**
   * Shows the final image or one ingredient (see DEBUG_VIEWS of SubsurfaceComposePass): 'final',
   * 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance'.
   * @param {import('./4-compose/debugViews.js').DebugView} view
   * @param {{ depthRange?: number, thicknessRangeMm?: number }} [options] the ranges the depth
   *   (world units, default 100) and thickness (mm, default 10) views map to black..white
   */
  setDebugView(view, options) {
    this.composePass.setDebugView(view, options);
    this.subsurfaceMaterials.setDebugOutput(materialOutputOf(view));
  }

  /** @param {number} fraction of the width, from the left, shown without scattering (0..1; 0 = none) */
  setSplit(fraction) {
    this.composePass.setSplit(fraction);
  }

  /**
   * Rebuilds the kernel (and the profile tables when the profile changes). Changing the method
   * between 'footprint' and the fixed-tap ones recompiles the blur shaders once.
   * @param {{ profile?: import('./options.js').ProfileName|object, method?: import('./options.js').Method, samples?: number|'auto', strength?: number[], falloff?: number[] }} options
   */
  setKernel(options = {}) {
    if (options === null || typeof options !== 'object' || Array.isArray(options)) {
      throw new TypeError(`setKernel: options must be an object { profile, method, samples, strength, falloff }, got ${describe(options)}`);
    }
    checkOptions('setKernel options', options, KERNEL_OPTIONS);
    this.blur.setKernel({ ...options });
  }

  /**
   * @param {import('./options.js').FollowSurfaceMode} mode
   * @param {number} [depthThresholdMm]
   */
  setFollowSurface(mode, depthThresholdMm = this.depthThresholdMm) {
    checkDepthThreshold(depthThresholdMm);
    this.blur.setFollowSurface(mode, depthThresholdMm / this.worldUnitInMm);
    this.depthThresholdMm = depthThresholdMm;
  }

  /** @param {boolean} enabled narrow the blur on surfaces seen at grazing angles */
  setForeshortening(enabled) {
    this.blur.setForeshortening(checkBoolean('foreshortening', enabled));
  }

  /**
   * Sizes every target, as the composer does on composer.setSize. At least 1 × 1; larger than the
   * GPU's largest render target (MAX_TEXTURE_SIZE, MAX_RENDERBUFFER_SIZE) is a RangeError, here once
   * a frame has told the pipeline the GPU's limits, else on the next frame.
   * @param {number} width device pixels @param {number} height device pixels
   */
  setSize(width, height) {
    checkTargetSize(width, height, 'SubsurfaceScattering.setSize', this._limits);
    this._size = { width, height };
    this.scenePass.setSize(width, height);
    this.blur.setSize(width, height);
    this.composePass.setSize(width, height);
  }

  /** Frees every target, material, texture and quad the pipeline created, and unbinds its materials. */
  dispose() {
    this.subsurfaceMaterials.dispose();
    this.scenePass.dispose();
    this.blur.dispose();
    this.composePass.dispose();
    this.lightDepth?.dispose();
    this.profileLookup.dispose();
  }
}

// enabled, needsSwap, clear and renderToScreen (three's Pass fields), clearDepth and skipsUnreadLightDepth: booleans only.
booleanFields(SubsurfaceScattering.prototype, [...PASS_BOOLEANS, 'clearDepth', 'skipsUnreadLightDepth']);

/** What setKernel accepts. */
const KERNEL_OPTIONS = Object.freeze(['profile', 'method', 'samples', 'strength', 'falloff']);
