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
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { getProfile } from './profiles/presets.js';
import { ProfileLookup } from './profiles/ProfileLookup.js';
import { checkBoolean, checkNumber, checkOptions } from './support/parameterChecks.js';
import { describe } from './support/rendererSupport.js';
import { PASS_BOOLEANS, booleanFields } from './support/booleanFields.js';
import { FrameChecks, checkTargetSize, checkTargetLimits } from './support/frameChecks.js';
import { warnDeprecated } from './support/deprecation.js';
import { PIPELINE_SCHEMA, checkOption, checkPipelineOptions } from './options.js';
import { estimatePixelsPerMm, nearestViewDepth } from './framePlan.js';
import { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';
import { PipelineMaterials } from './2-scene-split/PipelineMaterials.js';
import { isShining, lightFromBehind } from './2-scene-split/transmittance.js';
import { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
import { BlurStage } from './3-blur/BlurStage.js';
import { SubsurfaceComposePass } from './4-compose/SubsurfaceComposePass.js';
import { materialOutputOf } from './4-compose/debugViews.js';

export { METHODS, AUTO_SAMPLES, AUTO_REACH } from './options.js';
export { MIN_KERNEL_PIXELS } from './3-blur/samplingModel.js';

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
    const o = checkPipelineOptions(options); // every option checked here, once, against the schema

    this.needsSwap = false; // like RenderPass: it draws into the read buffer
    /** As RenderPass: true clears the target first; false draws over it (see render's step 5). */
    this.clear = true;
    /** As RenderPass: with clear false, true ignores the target's earlier depth. */
    this.clearDepth = false;
    this._clearColor = null;
    this._clearAlpha = null;
    this._scene = o.scene;
    this._camera = o.camera;
    this._worldUnitInMm = o.worldUnitInMm;
    this._depthThresholdMm = o.depthThresholdMm;
    this._stageTimer = null;
    this.profileLookup = new ProfileLookup(getProfile(o.profile));
    this.lightDepth = o.light ? new LightDepthTarget(o.light, { size: o.lightDepthSize }) : null;
    this._transmittance = o.light !== null;
    this.multisampling = o.multisampling;
    /** The size setSize last gave, device pixels (checked against the GPU's limits on the next frame). */
    this._size = { width: 1, height: 1 };
    /** The GPU's render target limits, known from the first frame on. */
    this._limits = undefined;
    /** The frame's checks of the camera and the light, each warned about once (see `problems`). */
    this._checks = new FrameChecks('SubsurfaceScattering');

    // Stages 2, 3 and 4.
    this.scenePass = new SubsurfaceScenePass(o.scene, o.camera, { type: o.type, owner: this });
    this.blur = new BlurStage({
      type: o.type, profileLookup: this.profileLookup, method: o.method, samples: o.samples, strength: o.strength, falloff: o.falloff,
      surface: {
        camera: o.camera, surfaceTexture: this.scenePass.surfaceTexture, diffuseTexture: this.scenePass.diffuseTexture,
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
    this._debug = { view: 'final', depthRange: 100, thicknessRangeMm: 10 };
    /** The materials made subsurface through this pipeline (see makeSubsurface). */
    this.subsurfaceMaterials = new PipelineMaterials(this, () => ({
      worldUnitInMm: this.worldUnitInMm,
      lightDepth: this.transmittance ? this.lightDepth : null,
      lookup: this.profileLookup,
      debugOutput: materialOutputOf(this._debug.view),
    }));
    /** What the last frame ran: { samples, kernelPixels, blur, passes } (see src/3-blur/blurPlan.js). */
    this.plan = this.blur.lastPlan;
    /** The largest on-screen kernel radius of the last frame, pixels (plan.kernelPixels). */
    this.kernelPixels = 0;
  }

  // ---- The settings: each a property, checked on assignment by the options schema (src/options.js).

  /**
   * As RenderPass: the clear colour of the scene (null: the renderer's).
   * @type {import('three').ColorRepresentation|null}
   */
  get clearColor() { return this._clearColor; }

  set clearColor(color) {
    const ok = color === null || typeof color === 'string' || color?.isColor === true || (typeof color === 'number' && Number.isFinite(color));
    if (!ok) throw new TypeError(`SubsurfaceScattering.clearColor must be null, a THREE.Color, a CSS colour string or a hex number, got ${describe(color)}`);
    this._clearColor = color;
  }

  /**
   * As RenderPass: the clear alpha of the scene, 0..1 (null: the renderer's).
   * @type {number|null}
   */
  get clearAlpha() { return this._clearAlpha; }

  set clearAlpha(alpha) {
    this._clearAlpha = alpha === null ? null : checkNumber('SubsurfaceScattering.clearAlpha', alpha, { min: 0, max: 1 });
  }

  /** The scene rendered, read every frame. @type {import('three').Scene} */
  get scene() { return this._scene; }

  set scene(scene) { this._scene = checkOption(PIPELINE_SCHEMA, 'scene', scene); }

  /** The camera rendered with, read every frame (`sss.camera = otherCamera` switches the view). @type {import('three').Camera} */
  get camera() { return this._camera; }

  set camera(camera) { this._camera = checkOption(PIPELINE_SCHEMA, 'camera', camera); }

  /**
   * Millimetres per world unit (1000 for metres): assigning it rescales every material of the
   * pipeline and the depth threshold.
   * @type {number}
   */
  get worldUnitInMm() { return this._worldUnitInMm; }

  set worldUnitInMm(worldUnitInMm) {
    this._worldUnitInMm = checkOption(PIPELINE_SCHEMA, 'worldUnitInMm', worldUnitInMm);
    this.blur.setFollowSurface(this.followSurface, this._depthThresholdMm / worldUnitInMm);
    this.subsurfaceMaterials.rebindAll();
  }

  /**
   * false turns the blur off: the compose adds the unblurred diffuse light (transmittance stays).
   * @type {boolean}
   */
  get scattering() { return this.blur.scattering; }

  set scattering(scattering) { this.blur.scattering = checkBoolean('SubsurfaceScattering.scattering', scattering); }

  /** How the blur weighs its taps (METHOD_TABLE); a switch between 'footprint' and the fixed-tap methods recompiles once. @type {import('./options.js').Method} */
  get method() { return this.blur.method; }

  /** @param {import('./options.js').Method} method */
  set method(method) { this.blur.setKernel({ method }); }

  /** Taps per direction asked for, or 'auto' (this frame's count: `plan.samples`). @type {number|'auto'} */
  get samples() { return this.blur.samples; }

  /** @param {number|'auto'} samples */
  set samples(samples) { this.blur.setKernel({ samples: checkOption(PIPELINE_SCHEMA, 'samples', samples) }); }

  /** The diffusion profile (a preset's name or a profile object; read back as the profile object). @type {object} */
  get profile() { return this.blur.kernelOptions.profile; }

  /** @param {import('./options.js').ProfileName|object} profile */
  set profile(profile) { this.blur.setKernel({ profile }); }

  /** RGB 0..1, mix with no scattering; undefined: the method's default. @type {number[]|undefined} */
  get strength() { return this.blur.kernelOptions.strength; }

  /** @param {number[]} strength */
  set strength(strength) { this.blur.setKernel({ strength: checkOption(PIPELINE_SCHEMA, 'strength', strength) }); }

  /** RGB (0, 10], method 'reference''s kernel shape; undefined: the reference's. @type {number[]|undefined} */
  get falloff() { return this.blur.kernelOptions.falloff; }

  /** @param {number[]} falloff */
  set falloff(falloff) { this.blur.setKernel({ falloff: checkOption(PIPELINE_SCHEMA, 'falloff', falloff) }); }

  /** What a tap on another surface does. @type {import('./options.js').FollowSurfaceMode} */
  get followSurface() { return this.blur.horizontalPass.followSurface; }

  /** @param {import('./options.js').FollowSurfaceMode} mode */
  set followSurface(mode) {
    this.blur.setFollowSurface(checkOption(PIPELINE_SCHEMA, 'followSurface', mode), this._depthThresholdMm / this._worldUnitInMm);
  }

  /** The depth step taken for another surface, mm. @type {number} */
  get depthThresholdMm() { return this._depthThresholdMm; }

  /** @param {number} depthThresholdMm */
  set depthThresholdMm(depthThresholdMm) {
    this._depthThresholdMm = checkOption(PIPELINE_SCHEMA, 'depthThresholdMm', depthThresholdMm);
    this.blur.setFollowSurface(this.followSurface, depthThresholdMm / this._worldUnitInMm);
  }

  /** Narrow the blur on surfaces seen at grazing angles. @type {boolean} */
  get foreshortening() { return this.blur.horizontalPass.foreshortening; }

  /** @param {boolean} enabled */
  set foreshortening(enabled) { this.blur.setForeshortening(checkOption(PIPELINE_SCHEMA, 'foreshortening', enabled)); }

  /**
   * Light through thin parts for every material of this pipeline (a uniform: no recompile). true
   * needs the constructor's `light`.
   * @type {boolean}
   */
  get transmittance() { return this._transmittance; }

  /** @param {boolean} enabled */
  set transmittance(enabled) {
    checkBoolean('SubsurfaceScattering.transmittance', enabled);
    if (enabled && !this.lightDepth) {
      throw new TypeError('SubsurfaceScattering.transmittance: light must be a THREE.SpotLight or THREE.DirectionalLight to turn transmittance on, ' +
        'and this pipeline has none (pass `light` to the constructor)');
    }
    this._transmittance = enabled;
    this.subsurfaceMaterials.rebindAll();
  }

  /**
   * MSAA samples of the scene split: 'auto' (the composer buffer's) or 0..16.
   * @type {number|'auto'}
   */
  get multisampling() { return this._multisampling; }

  /** @param {number|'auto'} samples */
  set multisampling(samples) { this._multisampling = checkOption(PIPELINE_SCHEMA, 'multisampling', samples); }

  /**
   * The final image or one ingredient (DEBUG_VIEWS): 'final', 'diffuse', 'specular', 'depth',
   * 'mask', 'thickness', 'transmittance'.
   * @type {import('./4-compose/debugViews.js').DebugView}
   */
  get debugView() { return this._debug.view; }

  /** @param {import('./4-compose/debugViews.js').DebugView} view */
  set debugView(view) { this._showDebug({ ...this._debug, view }); }

  /** World units the 'depth' view maps to black..white (default 100). @type {number} */
  get debugDepthRange() { return this._debug.depthRange; }

  /** @param {number} depthRange */
  set debugDepthRange(depthRange) { this._showDebug({ ...this._debug, depthRange }); }

  /** Profile mm the 'thickness' view maps to black..white (default 10). @type {number} */
  get debugThicknessRangeMm() { return this._debug.thicknessRangeMm; }

  /** @param {number} thicknessRangeMm */
  set debugThicknessRangeMm(thicknessRangeMm) { this._showDebug({ ...this._debug, thicknessRangeMm }); }

  /** The fraction of the width, from the left, shown without scattering (0..1; 0 = none). @type {number} */
  get split() { return this.composePass.split; }

  /** @param {number} fraction */
  set split(fraction) { this.composePass.setSplit(fraction); }

  /**
   * Optional { begin(stage), end(stage) } around each stage (dev/gpuTimer.js measures with it), or null.
   * @type {{ begin(stage: StageName): void, end(stage: StageName): void }|null}
   */
  get stageTimer() { return this._stageTimer; }

  set stageTimer(timer) {
    if (timer !== null && !(timer && typeof timer.begin === 'function' && typeof timer.end === 'function')) {
      throw new TypeError(`SubsurfaceScattering.stageTimer must be null or an object with begin(stage) and end(stage) functions, got ${describe(timer)}`);
    }
    this._stageTimer = timer;
  }

  // ---- What the last frame did.

  /**
   * What the last frame found wrong with the camera, the light or the scene, one message each (empty
   * when nothing is): each is also warned about on the console, once per pipeline. See the README's
   * "Errors and limits".
   * @type {readonly string[]}
   */
  get problems() { return this._checks.current; }

  /** The scene's depth from the last frame (its opaque part), a DepthTexture, for passes of your own. */
  get depthTexture() { return this.scenePass.depthTexture; }

  // ---- The frame.

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
    if (lightWorks && isShining(this.lightDepth.light, scene, camera) && this._transmits(scene, camera)) {
      this._stage('lightDepth', () => this.lightDepth.render(renderer, scene));
    } else {
      this.lightDepth?.invalidate();
    }
    // 2. Scene split: the opaque scene into the multi-target (colour | diffuse | surface | depth),
    //    multisampled as asked (or as the composer's buffer is).
    Object.assign(this.scenePass, { scene, camera, clearColor: this.clearColor, clearAlpha: this.clearAlpha });
    const msaaSamples = this._multisampling === 'auto' ? (readBuffer?.samples ?? 0) : this._multisampling;
    if (this.scenePass.setSamples(msaaSamples)) this.blur.setMultisampled(msaaSamples > 0);
    this._stage('scene', () => this.scenePass.render(renderer));
    // 3. Plan: the blur plans itself (src/3-blur/blurPlan.js) from the on-screen size of a profile
    //    millimetre: its taps for 'auto', no blur under half a pixel.
    this.plan = this.blur.plan(this._pixelsPerMm());
    this.kernelPixels = this.plan.kernelPixels;
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
   * Stage 4 alone over the last scene split, into scatteredTarget, as the last frame planned it
   * (the bench re-runs it to time it).
   * @param {import('three').WebGLRenderer} renderer
   */
  renderScattering(renderer) {
    this.blur.render(renderer, this.camera, (stage, draw) => this._stage(stage, draw), this.plan);
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
    if (materialOutputOf(this._debug.view) === 'thickness') return true;
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

  /** The largest on-screen size of a profile mm over the subsurface meshes the split drew. @private */
  _pixelsPerMm() {
    const { width, height } = this.scenePass.renderTarget;
    return estimatePixelsPerMm(this.scenePass.subsurfaceMeshes, this.camera, { width, height },
      (m) => (this.scenePass.categoryOf(m) === 'subsurface' ? this.subsurfaceMaterials.widthWorldOf(m) : undefined));
  }

  /** @private @param {{ view: string, depthRange: number, thicknessRangeMm: number }} debug */
  _showDebug(debug) {
    const { view, depthRange, thicknessRangeMm } = debug;
    this.composePass.setDebugView(view, { depthRange, thicknessRangeMm }); // checks all three
    this._debug = debug;
    this.subsurfaceMaterials.setDebugOutput(materialOutputOf(view));
  }

  // ---- Materials, composer, size, disposal.

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
  get materials() { return this.subsurfaceMaterials.entries; }

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

  // ---- The stages' parts, for pipelines of your own and for inspection (unstable: they follow
  //      the stages' code; the settings above are the API).

  /** @internal The stage passes in frame order (each usable on its own). */
  get passes() { return [this.scenePass, this.blur.horizontalPass, this.blur.verticalPass, this.composePass]; }
  /** @internal */
  get horizontalPass() { return this.blur.horizontalPass; }
  /** @internal */
  get verticalPass() { return this.blur.verticalPass; }
  /** @internal The dense 2D reference (method 'dense'), built on first use. */
  get densePass() { return this.blur.densePass; }
  /** @internal The last frame's scattered diffuse light. */
  get scatteredTarget() { return this.blur.scatteredTarget; }
  /** @internal @type {Float32Array} the separable kernel of the last frame (computeKernel's layout) */
  get kernel() { return this.blur.kernel; }
  /** @internal Whether the taps are chosen for the on-screen scale (samples 'auto'). */
  get autoSamples() { return this.blur.autoSamples; }
  /** @internal The kernel's current settings: { profile, samples, strength, falloff }, plus method. */
  get kernelOptions() { return { ...this.blur.kernelOptions, method: this.method }; }

  // ---- Version 0.2's setter methods: deprecated (one setter style: assign the property).

  /**
   * @deprecated assign `method`, `samples`, `profile`, `strength`, `falloff`
   * @param {{ profile?: import('./options.js').ProfileName|object, method?: import('./options.js').Method, samples?: number|'auto', strength?: number[], falloff?: number[] }} options
   */
  setKernel(options = {}) {
    warnDeprecated('SubsurfaceScattering.setKernel()', 'the properties (sss.method = ..., sss.samples = ..., sss.profile = ...)');
    if (options === null || typeof options !== 'object' || Array.isArray(options)) {
      throw new TypeError(`setKernel: options must be an object { profile, method, samples, strength, falloff }, got ${describe(options)}`);
    }
    checkOptions('setKernel options', options, KERNEL_OPTIONS);
    this.blur.setKernel({ ...options });
  }

  /** @deprecated assign `transmittance` @param {boolean} enabled */
  setTransmittance(enabled) {
    warnDeprecated('SubsurfaceScattering.setTransmittance()', 'sss.transmittance = enabled');
    this.transmittance = enabled;
  }

  /**
   * @deprecated assign `followSurface` and `depthThresholdMm`
   * @param {import('./options.js').FollowSurfaceMode} mode @param {number} [depthThresholdMm]
   */
  setFollowSurface(mode, depthThresholdMm = this.depthThresholdMm) {
    warnDeprecated('SubsurfaceScattering.setFollowSurface()', 'sss.followSurface = mode; sss.depthThresholdMm = mm');
    checkOption(PIPELINE_SCHEMA, 'depthThresholdMm', depthThresholdMm);
    this.followSurface = mode;
    this.depthThresholdMm = depthThresholdMm;
  }

  /** @deprecated assign `foreshortening` @param {boolean} enabled */
  setForeshortening(enabled) {
    warnDeprecated('SubsurfaceScattering.setForeshortening()', 'sss.foreshortening = enabled');
    this.foreshortening = enabled;
  }

  /**
   * @deprecated assign `debugView` (and `debugDepthRange`, `debugThicknessRangeMm`)
   * @param {import('./4-compose/debugViews.js').DebugView} view
   * @param {{ depthRange?: number, thicknessRangeMm?: number }} [options]
   */
  setDebugView(view, options = {}) {
    warnDeprecated('SubsurfaceScattering.setDebugView()', 'sss.debugView = view (and sss.debugDepthRange, sss.debugThicknessRangeMm)');
    const { depthRange = 100, thicknessRangeMm = 10 } = checkOptions('setDebugView options', options, ['depthRange', 'thicknessRangeMm']);
    this._showDebug({ view, depthRange, thicknessRangeMm });
  }

  /** @deprecated assign `split` @param {number} fraction */
  setSplit(fraction) {
    warnDeprecated('SubsurfaceScattering.setSplit()', 'sss.split = fraction');
    this.split = fraction;
  }
}

// enabled, needsSwap, clear and renderToScreen (three's Pass fields), and clearDepth: booleans only.
booleanFields(SubsurfaceScattering.prototype, [...PASS_BOOLEANS, 'clearDepth']);

/** What setKernel accepts. */
const KERNEL_OPTIONS = Object.freeze(['profile', 'method', 'samples', 'strength', 'falloff']);
