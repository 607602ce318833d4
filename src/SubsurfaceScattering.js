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
// The settings are properties made from the options' schema (src/options.js,
// src/support/settings.js); _applySetting says what each does to the stages.
import { Color } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { getProfile } from './profiles/presets.js';
import { ProfileLookup } from './profiles/ProfileLookup.js';
import { profileSlots } from './profiles/profileSlots.js';
import { checkNumber } from './support/parameterChecks.js';
import { assertFloatRenderTargets, describe } from './support/rendererSupport.js';
import { checkThreeRevision } from './support/threeVersion.js';
import { withSettings } from './support/settings.js';
import { stopWatching, warnWhenDisabledFreezes, watchRendered } from './support/frozenFrameWatch.js';
import { PASS_BOOLEANS, booleanFields } from './support/booleanFields.js';
import { FrameChecks, checkTargetSize, checkTargetLimits } from './support/frameChecks.js';
import {
  CAST_SHADOW, MAX_LIGHTS, PIPELINE_SCHEMA, checkPipelineOptions, lightsOf, propertiesOf,
} from './options.js';
import { estimatePixelsPerMm } from './framePlan.js';
import { boxInTarget, cameraViews, unionBox } from './support/cameraViews.js';
import { subsurfaceScreenBox } from './2-scene-split/subsurfaceScreenBox.js';
import { LightDepthTarget } from './1-light-depth/LightDepthTarget.js';
import { PipelineMaterials } from './2-scene-split/PipelineMaterials.js';
import { isShining, lightReachesFromBehind } from './2-scene-split/transmittanceModel.js';
import { SubsurfaceScenePass } from './2-scene-split/SubsurfaceScenePass.js';
import { BlurStage } from './3-blur/BlurStage.js';
import { SubsurfaceComposePass } from './4-compose/SubsurfaceComposePass.js';
import { materialOutputOf } from './4-compose/debugViews.js';
import { compilePassPrograms, compileSceneInto } from './support/compilePrograms.js';
import { holdingMatrices, preservingRendererState } from './support/rendererState.js';
import { nameClass } from './support/className.js';

const _clearColor = new Color();

/**
 * A stage of one frame, as stageTimer sees it.
 * @typedef {'lightDepth'|'scene'|'blurH'|'blurV'|'dense'|'compose'|'transparent'} StageName
 */

/** three's Pass with the pipeline's settings as properties (src/options.js's schema; src/support/settings.js). */
const PassWithSettings = /** @type {new () => Pass & import('./options.js').PipelineSettings} */ (
  withSettings(Pass, PIPELINE_SCHEMA, 'SubsurfaceScattering'));

/**
 * Screen-space subsurface scattering as one three.js Pass, in place of a RenderPass:
 * ```js
 * const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
 * sss.makeSubsurface(skinMaterial);
 * composer.addPass(sss);               // instead of a RenderPass
 * composer.addPass(new OutputPass());
 * sss.samples = 25;                    // every option is a property, checked on assignment
 * ```
 */
export class SubsurfaceScattering extends PassWithSettings {
  /** @param {import('./options.js').SubsurfaceScatteringOptions} options */
  constructor(options) {
    checkThreeRevision('SubsurfaceScattering'); // first: older releases fail inside the stages
    super();
    const o = checkPipelineOptions(options); // every option checked here, once, against the schema
    /** @internal The settings' values (read and assigned through their properties). */
    this._settings = Object.fromEntries(propertiesOf(PIPELINE_SCHEMA).map(({ name }) => [name, o[name]]));
    /**
     * @internal Whether the user set `transmittance` true (not the default), for the frame's word
     * when there is no light: the settings a light needs are kept as set, whatever the order they
     * came in, and take effect with a light.
     */
    this._transmittanceAsked = Object.hasOwn(options, 'transmittance') && o.transmittance;

    this.needsSwap = false; // like RenderPass: it draws into the read buffer
    /** As RenderPass: first in renderer.setEffects([...]) (three r182+), the renderer leaves the scene's draw to it. */
    this.isRenderPass = true;
    /** As RenderPass: true clears the target first; false draws over it (see render's step 5). */
    this.clear = true;
    /** As RenderPass: with clear false, true ignores the target's earlier depth. */
    this.clearDepth = false;
    this._clearColor = null;
    this._clearAlpha = null;
    this._stageTimer = null;
    /** @internal The pipeline's profile's GPU tables (the default of its materials). */
    this._profileLookup = new ProfileLookup(o.profile);
    /** @internal Tables of the other profiles its materials name (computing one takes tens of ms: kept). */
    this._otherLookups = new Map();
    /** @internal Stage 1, for transmittance: a map per light (none without a light). */
    this._lightDepths = lightsOf(o.light, o.scene).slice(0, MAX_LIGHTS).map((light) => new LightDepthTarget(light, { size: o.lightDepthSize }));
    /** @internal Whether a material of this pipeline transmits (the light depth map holds its thickness). */
    this._transmitsThrough = (m) => this._subsurfaceMaterials.entries.get(m)?.options.transmittance === true;
    /** @internal The size setSize last gave, device pixels (checked against the GPU's limits on the next frame). */
    this._size = { width: 1, height: 1 };
    /** @internal The GPU's render target limits, known from the first frame on. */
    this._limits = undefined;
    /** @internal Whether `depthTexture` was read: the scene split then runs on every frame (_drawsPlain). */
    this._depthTextureRead = false;
    /** @internal The frame's checks of the camera and the light, each warned about once (see `problems`). */
    this._checks = new FrameChecks('SubsurfaceScattering');

    // Stages 2, 3 and 4.
    /** @internal */
    this._scenePass = new SubsurfaceScenePass(o.scene, o.camera, { type: o.type, owner: this });
    /** @internal */
    this._blur = new BlurStage({
      type: o.type, profileLookup: this._profileLookup, method: o.method, samples: o.samples, strength: o.strength, falloff: o.falloff, kernelGroups: o.kernelGroups,
      surface: {
        camera: o.camera, surfaceTexture: this._scenePass.surfaceTexture, diffuseTexture: this._scenePass.diffuseTexture,
        followSurface: o.followSurface, depthThresholdWorld: o.depthThresholdMm / o.worldUnitInMm, foreshortening: o.foreshortening,
      },
    });
    this._blur.scattering = o.scattering;
    /** @internal */
    this._composePass = new SubsurfaceComposePass({
      colorTexture: this._scenePass.colorTexture,
      surfaceTexture: this._scenePass.surfaceTexture,
      diffuseTexture: this._scenePass.diffuseTexture,
      scatteredTexture: this._blur.scatteredTarget.texture,
      depthTexture: this._scenePass.depthTexture,
      depthTarget: this._scenePass.renderTarget, // its depth handed on per sample under MSAA (src/4-compose/multisampledDepth.js)
    });
    this._composePass.setDebugView(o.debugView, { depthRange: o.debugDepthRange, thicknessRangeMm: o.debugThicknessRangeMm });
    this._composePass.setSplit(o.split);
    /** @internal The materials made subsurface through this pipeline (see makeSubsurface; `materials` is the public view). */
    this._subsurfaceMaterials = new PipelineMaterials(this, () => ({
      worldUnitInMm: this.worldUnitInMm,
      lightDepths: this.transmittance ? this._lightDepths : [],
      profile: this.profile,
      lookupOf: (profile) => this._lookupOf(profile),
      checkProfiles: (profiles) => this._checkProfiles(this.method, profiles, this.profile, 'makeSubsurface'),
      debugOutput: materialOutputOf(this.debugView),
    }), () => this._useProfiles());
    /**
     * What the last frame ran: { samples, kernelPixels, blur, passes, groups } (src/3-blur/blurPlan.js).
     * @type {ReturnType<BlurStage['plan']>}
     */
    this.plan = this._blur.lastPlan;
    /** @internal The last frame's views (src/support/cameraViews.js), each with its plan and subsurface box. */
    this._views = [];
  }

  /**
   * Acts on a setting just assigned (already checked and kept; a throw here puts the old value
   * back): each setting's effect on the stages.
   * @private @param {string} name @param {*} value @param {*} previous
   */
  _applySetting(name, value, previous) {
    switch (name) {
      case 'profile':
        if (value === previous) return;
        this._checkProfiles(this.method, this._subsurfaceMaterials.profiles(value), value, 'SubsurfaceScattering.profile');
        this._profileLookup.setProfile(value); // tens of ms: only on a change
        this._subsurfaceMaterials.rebindAll(); // a material naming this profile or the last one changes tables
        this._useProfiles();
        return;
      case 'method':
        this._checkProfiles(value, this._subsurfaceMaterials.profiles(), this.profile, 'SubsurfaceScattering.method');
        this._blur.setKernel({ method: value }); // a switch between 'footprint' and the fixed-tap methods recompiles once
        return;
      case 'samples': case 'strength': case 'falloff':
        this._blur.setKernel({ [name]: value });
        return;
      case 'kernelGroups': case 'scattering':
        this._blur[name] = value;
        return;
      case 'worldUnitInMm': case 'followSurface': case 'depthThresholdMm':
        this._blur.setFollowSurface(this.followSurface, this.depthThresholdMm / this.worldUnitInMm);
        if (name === 'worldUnitInMm') this._subsurfaceMaterials.rebindAll();
        return;
      case 'foreshortening':
        this._blur.setForeshortening(value);
        return;
      case 'transmittance':
        this._transmittanceAsked = value;
        this._subsurfaceMaterials.rebindAll();
        return;
      case 'debugView': case 'debugDepthRange': case 'debugThicknessRangeMm':
        this._composePass.setDebugView(this.debugView, { depthRange: this.debugDepthRange, thicknessRangeMm: this.debugThicknessRangeMm });
        this._subsurfaceMaterials.setDebugOutput(materialOutputOf(this.debugView));
        return;
      case 'split':
        this._composePass.setSplit(value);
        return;
      case 'lightDepthSize':
        for (const lightDepth of this._lightDepths) lightDepth.setSize(value);
        return;
      case 'light':
        this._setLight(value, previous);
        return;
      default: // scene, camera, multisampling: read each frame
    }
  }

  /**
   * Other lights, or none: each map follows its light from the next frame (kept where there was
   * one at its place, so its materials read it on). `transmittance` and `debugView` stay as set:
   * they act through the lights there are.
   * @private
   */
  _setLight(light, previous) {
    if (light === previous) return;
    this._useLights(lightsOf(light, this.scene));
  }

  /**
   * A map for each of `lights` (up to MAX_LIGHTS), kept where there was one at its place (its
   * materials read it on), retargeted to its light; the materials rebound where the count changes.
   * @private @param {readonly object[]} lights
   * @returns {boolean} whether the materials were rebound
   */
  _useLights(lights) {
    const maps = this._lightDepths;
    const count = maps.length;
    lights.slice(0, MAX_LIGHTS).forEach((light, i) => {
      if (!maps[i]) maps[i] = new LightDepthTarget(light, { size: this.lightDepthSize });
      else if (maps[i].light !== light) maps[i].setLight(light);
    });
    for (const extra of maps.splice(Math.min(lights.length, MAX_LIGHTS))) extra.dispose();
    if (count === maps.length) return false;
    this._subsurfaceMaterials.rebindAll(); // the bindings list the maps
    return true;
  }

  /** The maps of the scene's shadow-casting lights (`light` 'castShadow'), this frame's. @private */
  _castShadowLights(scene, checks) {
    const lights = lightsOf(CAST_SHADOW, scene);
    if (lights.length > MAX_LIGHTS) {
      checks.problem('castShadowLights', `${lights.length} lights cast shadows: transmittance comes from the first ${MAX_LIGHTS} in the scene's order (list the ones you want in \`light\`)`);
    }
    this._useLights(lights);
  }

  /** @internal The first light's map, or null (the tests' and the bench's handle on stage 1). */
  get _lightDepth() { return this._lightDepths[0] ?? null; }

  /**
   * The diffusion profile of the materials that name none: a preset's name or a profile object,
   * read back as the profile object; the tables are refilled only on a change.
   * @type {import('./options.js').DiffusionProfile}
   */
  get profile() { return super.profile; }

  /** @param {import('./options.js').ProfileName|object} profile */
  set profile(profile) { super.profile = profile; }

  /**
   * As RenderPass: the clear colour of the scene (null: the renderer's).
   * @type {import('three').ColorRepresentation|null}
   */
  get clearColor() { return this._clearColor; }

  set clearColor(color) {
    const ok = color === null || typeof color === 'string' || color?.isColor === true || (typeof color === 'number' && Number.isFinite(color));
    if (!ok) throw new TypeError(`clearColor must be null, a THREE.Color, a CSS colour string or a hex number, got ${describe(color)}`);
    this._clearColor = color;
  }

  /**
   * As RenderPass: the clear alpha of the scene, 0..1 (null: the renderer's).
   * @type {number|null}
   */
  get clearAlpha() { return this._clearAlpha; }

  set clearAlpha(alpha) {
    this._clearAlpha = alpha === null ? null : checkNumber('clearAlpha', alpha, { min: 0, max: 1 });
  }

  /**
   * Optional { begin(stage), end(stage) } around each stage (the demo's live timings measure with it), or null.
   * @type {{ begin(stage: StageName): void, end(stage: StageName): void }|null}
   */
  get stageTimer() { return this._stageTimer; }

  set stageTimer(timer) {
    if (timer !== null && !(timer && typeof timer.begin === 'function' && typeof timer.end === 'function')) {
      throw new TypeError(`stageTimer must be null or an object with begin(stage) and end(stage) functions, got ${describe(timer)}`);
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

  /**
   * The scene's depth from the last frame (its opaque part), a DepthTexture, for passes of your
   * own. Once read, the pipeline splits the scene on every frame to keep it, also where no
   * subsurface mesh is on the screen (elsewhere such a frame is three's own draw, as cheap).
   */
  get depthTexture() {
    this._depthTextureRead = true;
    return this._scenePass.depthTexture;
  }

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
    watchRendered(this, renderer); // for the warning when disabled with nothing else drawing the scene
    // 0. Checks: the size against the GPU's limits (a RangeError), the camera, the light and the
    //    scene (a warning, once each; the frame is drawn as three would draw it). What the frame
    //    covers, decided once (src/frameMeshes.js: visible, layers, LOD levels, the frustum): the
    //    lights' maps, the plan and the box read it.
    assertFloatRenderTargets(renderer, 'SubsurfaceScattering');
    this._limits = checkTargetLimits(renderer, this._size, 'SubsurfaceScattering');
    const checks = this._checks.begin();
    checks.camera(camera);
    checks.scene(scene);
    checks.depthHandOff(this._composePass.depthHandOff); // the last frame's: the output's MSAA unlike the split's
    // 'castShadow': the scene's lights that cast shadows now, more than MAX_LIGHTS said once.
    if (this.light === CAST_SHADOW) this._castShadowLights(scene, checks);
    if (this._lightDepths.length === 0) checks.withoutLight(this._transmittanceAsked, this.debugView);
    Object.assign(this._scenePass, { scene, camera, clearColor: this.clearColor, clearAlpha: this.clearAlpha });
    const frame = this._scenePass.collect();
    // The lights' checks fit their maps to the transmitting meshes on the screen.
    const works = this._lightDepths.map((lightDepth) => checks.light(lightDepth, frame, this.transmittance, this._transmitsThrough));
    // What cannot be drawn as the camera sees it is drawn as three draws it, named once: the copies
    // the frame met and could not make subsurface, and, from the frame after three compiled them,
    // the materials whose own hook took out a point of the split or threw in a light's pass.
    this._subsurfaceMaterials.checkMaterials(checks, this._scenePass.copiesNotFollowed);
    for (const lightDepth of this._lightDepths) for (const [key, message] of lightDepth.shapeProblems) checks.problem(key, message);
    checks.end();
    // No subsurface mesh on the screen: the frame is three's own, as a RenderPass draws it.
    if (this._drawsPlain()) {
      for (const lightDepth of this._lightDepths) lightDepth.invalidate();
      this.plan = this._blur.plan(0);
      this._stage('scene', () => this._renderPlain(renderer, target));
      return;
    }
    // The stages render the scene several times: its matrices were updated once, by collect.
    holdingMatrices(scene, () => this._renderStages(renderer, readBuffer, target, works));
  }

  /**
   * Steps 1 to 6 of a frame whose checks (step 0) found subsurface meshes on the screen.
   * @private
   */
  _renderStages(renderer, readBuffer, target, works) {
    const { scene, camera } = this;
    const { frame } = this._scenePass;
    // 1. Light depth: linear depth seen from each light, for transmittance (not for a light that
    //    is off, nor one that reaches no subsurface mesh from behind: its map would go unread).
    this._lightDepths.forEach((lightDepth, i) => {
      if (works[i] && isShining(lightDepth.light, scene, camera) && this._transmits(lightDepth.light, camera)) {
        this._stage('lightDepth', () => lightDepth.render(renderer, scene, frame));
      } else {
        lightDepth.invalidate();
      }
    });
    // 2. Scene split: the opaque scene into the multi-target (colour | diffuse | surface | depth),
    //    multisampled as asked (or as the composer's buffer is).
    const msaaSamples = this.multisampling === 'auto' ? (readBuffer?.samples ?? 0) : this.multisampling;
    if (this._scenePass.setSamples(msaaSamples)) this._blur.setMultisampled(msaaSamples > 0);
    this._stage('scene', () => this._scenePass.render(renderer));
    // 3. Plan: the blur plans itself (src/3-blur/blurPlan.js) from the on-screen size of a profile
    //    millimetre: its taps for 'auto', no blur under half a pixel. An ArrayCamera's views are
    //    planned apart, each at its own camera's scale.
    this._views = this._planViews(camera);
    // The frame's plan: its view's, or the one reaching furthest of an ArrayCamera's (none: no blur).
    this.plan = this._views.length === 0 ? this._blur.plan(0)
      : this._views.map((view) => view.plan).reduce((most, plan) => (plan.kernelPixels > most.kernelPixels ? plan : most));
    const blurred = this._views.filter((view) => view.plan.blur);
    // 4. Blur: the diffuse light, horizontally then vertically (or densely), into scatteredTarget.
    if (blurred.length > 0) this._renderScattering(renderer);
    // 5. Compose: colour + the scattered (without blur: the unblurred) diffuse light, and the
    //    scene's depth, into the target: every pixel (clear), or over what it holds (clear false).
    this._composePass.scatteredTexture = blurred.length > 0 ? this._blur.scatteredTarget.texture : this._scenePass.diffuseTexture;
    // The box bounds where the blur wrote; without the blur the diffuse is read everywhere, as before.
    this._composePass.setMaskBox(blurred.length > 0 ? unionBox(blurred.map((view) => view.box)) : null);
    const one = this._views.length === 1 ? this._views[0] : null;
    this._composePass.setScatteredShare(one?.plan.blur ? one.plan.fade : 1); // the blur fading in (blurPlan.js)
    this._composePass.renderToScreen = this.renderToScreen;
    this._composePass.setClear(this.clear, this.clearDepth);
    const autoClear = renderer.autoClear;
    renderer.autoClear = false; // the full-screen quad would clear what clear = false keeps
    try {
      this._stage('compose', () => {
        this._composePass.render(renderer, readBuffer, null);
        // An ArrayCamera's views its plan fades in or leaves unblurred, again with their own.
        if (!one && blurred.length > 0) this._composeViews(renderer, readBuffer);
      });
      // 6. Transparent objects over the composed image, depth-tested against the scene.
      this._stage('transparent', () => this._scenePass.renderTransparent(renderer, target));
    } finally {
      renderer.autoClear = autoClear;
    }
  }

  /**
   * Whether this frame is three's own: no subsurface mesh on the screen (nor an override drawing
   * the scene), the final image shown into the composer's buffer (to the screen the compose
   * tone-maps as OutputPass would), and the scene's depth not asked of the pipeline.
   * @private
   */
  _drawsPlain() {
    return this._scenePass.subsurfaceMeshes.length === 0 && this.debugView === 'final' && !this._depthTextureRead && !this.renderToScreen;
  }

  /**
   * The frame as three's RenderPass draws it: the scene into `target` (null: the screen), cleared
   * first as `clear`, `clearDepth`, `clearColor` and `clearAlpha` say.
   * @private @param {import('three').WebGLRenderer} renderer @param {import('three').WebGLRenderTarget|null} target
   */
  _renderPlain(renderer, target) {
    const { scene, camera } = this;
    if (!this.clear) this._composePass.releaseDepth(); // drawn over what the target holds: its own depth
    preservingRendererState(renderer, scene, () => {
      renderer.autoClear = false;
      renderer.setRenderTarget(target);
      if (this.clearColor !== null || this.clearAlpha !== null) {
        renderer.setClearColor(this.clearColor ?? renderer.getClearColor(_clearColor), this.clearAlpha ?? renderer.getClearAlpha());
      }
      if (this.clear) renderer.clear(renderer.autoClearColor, renderer.autoClearDepth, renderer.autoClearStencil);
      else if (this.clearDepth) renderer.clearDepth();
      holdingMatrices(scene, () => renderer.render(scene, camera)); // updated by collect
    });
  }

  /**
   * Compiles every shader program the next frames draw with, before they draw (no first-frame
   * stall), in parallel where the browser has KHR_parallel_shader_compile: the scene's materials as
   * the split and a plain frame draw them, each light's depth materials, and the pipeline's passes
   * with the variants a frame switches between as the view moves (kernelGroups 'auto''s counts,
   * the output's depth). three's own `renderer.compileAsync(scene, camera)` compiles the scene's
   * materials for the screen only. Call it again after a setting that recompiles (README).
   * ```js
   * await sss.compileAsync(renderer, composer.readBuffer);
   * renderer.setAnimationLoop(() => composer.render());
   * ```
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget|null} [readBuffer=null] what render() is given to
   *   draw into (the composer's read buffer; `multisampling: 'auto'` follows its `samples`); null
   *   where it is not at hand (renderer.setEffects): any target compiles the same programs
   * @returns {Promise<void>} resolved once every program is ready to draw with
   */
  compileAsync(renderer, readBuffer = null) {
    assertFloatRenderTargets(renderer, 'SubsurfaceScattering.compileAsync');
    if (readBuffer !== null && readBuffer?.isRenderTarget !== true) {
      throw new TypeError(`SubsurfaceScattering.compileAsync: readBuffer must be a THREE.WebGLRenderTarget or null, got ${describe(readBuffer)}`);
    }
    const { scene, camera } = this;
    if (this.light === CAST_SHADOW) this._useLights(lightsOf(CAST_SHADOW, scene));
    const msaaSamples = this.multisampling === 'auto' ? (readBuffer?.samples ?? 0) : this.multisampling;
    if (this._scenePass.setSamples(msaaSamples)) this._blur.setMultisampled(msaaSamples > 0);
    this._composePass.setClear(this.clear, this.clearDepth);
    // three keys a program by whether it draws to the screen, not by which target: any stands in.
    const target = this.renderToScreen ? null : readBuffer ?? this._blur.scatteredTarget;
    return Promise.all([
      compileSceneInto(renderer, scene, camera, this._scenePass.renderTarget), // the split
      compileSceneInto(renderer, scene, camera, target), // a plain frame; the transparent objects
      ...this._lightDepths.map((lightDepth) => lightDepth.compileAsync(renderer, scene)),
      compilePassPrograms(renderer, this._blur.warmUpMaterials(), this._blur.scatteredTarget),
      compilePassPrograms(renderer, this._composePass.warmUpMaterials(target), target),
    ]).then(() => undefined);
  }

  /**
   * Stage 4 alone over the last scene split, into the scattered target, as the last frame planned
   * it (the bench re-runs it to time it).
   * @private @param {import('three').WebGLRenderer} renderer
   */
  _renderScattering(renderer) {
    const timed = (stage, draw) => this._stage(stage, draw);
    const [first] = this._views;
    if (this._views.length === 1 && first.whole) this._blur.render(renderer, first.camera, timed, first.plan, first.box);
    else this._blur.renderViews(renderer, this._views, timed);
  }

  /**
   * The frame's views (src/support/cameraViews.js), each with its plan and its subsurface pixels'
   * box in the target: the camera's one view, the whole frame; an ArrayCamera's each at its own
   * camera's scale, the box found as that camera alone would see the meshes.
   * @private @param {import('three').Camera} camera
   */
  _planViews(camera) {
    const { width, height } = this._scenePass.renderTarget;
    const views = cameraViews(camera, width, height);
    for (const view of views) {
      view.plan = this._blur.plan(this._pixelsPerMm(view));
      view.box = view.whole ? this._scenePass.subsurfaceBox
        : boxInTarget(view, subsurfaceScreenBox(this._scenePass.subsurfaceMeshes, view.camera, view.viewport.width, view.viewport.height));
    }
    return views;
  }

  /**
   * Composes again, each within its rectangle, an ArrayCamera's views whose plan is not the
   * frame's: fading in (their share of the scattered light) or not blurred (their unblurred light).
   * @private
   */
  _composeViews(renderer, readBuffer) {
    for (const view of this._views) {
      if (view.plan.blur && view.plan.fade === 1) continue;
      this._composePass.scatteredTexture = view.plan.blur ? this._blur.scatteredTarget.texture : this._scenePass.diffuseTexture;
      this._composePass.setMaskBox(view.plan.blur ? view.box : null);
      this._composePass.setScatteredShare(view.plan.blur ? view.plan.fade : 1);
      this._composePass.renderIn(renderer, readBuffer, view.rect);
    }
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
   * Whether `light` can send transmitted light to a subsurface mesh of this pipeline on the screen
   * this frame (lightFromBehind at each one's nearest point); the thickness view always reads the map.
   * @private
   */
  _transmits(light, camera) {
    if (materialOutputOf(this.debugView) === 'thickness') return true;
    return lightReachesFromBehind(light, this._scenePass.frame.onScreen, camera, this._transmitsThrough);
  }

  /**
   * The largest on-screen size of a profile mm over the subsurface meshes the split drew, in
   * `view` (default: the camera's, the whole frame).
   * @private @param {{ camera: import('three').Camera, viewport: { width: number, height: number } }} [view]
   */
  _pixelsPerMm(view = { camera: this.camera, viewport: this._scenePass.renderTarget }) {
    const { width, height } = view.viewport;
    return estimatePixelsPerMm(this._scenePass.subsurfaceMeshes, view.camera, { width, height },
      (m) => (this._scenePass.categoryOf(m) === 'subsurface' ? this._subsurfaceMaterials.widthWorldOf(m) : undefined));
  }

  // ---- Materials, size, disposal.

  /**
   * Makes `material` scatter with this pipeline's profile, scale and light (see makeSubsurface):
   * settings of this pipeline's own, so another pipeline can draw the same material with its own.
   * @param {import('three').MeshStandardMaterial} material
   * @param {import('./options.js').SubsurfaceMaterialOptions} [options]
   * @returns {import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding}
   */
  makeSubsurface(material, options = {}) {
    const binding = this._subsurfaceMaterials.bind(material, options);
    this._useProfiles();
    return binding;
  }

  /**
   * Undoes makeSubsurface for this pipeline: the material renders as without it here, and gets its
   * own shader back once no pipeline has it.
   * @param {import('three').MeshStandardMaterial} material
   * @returns {boolean} whether it was subsurface in this pipeline
   */
  removeSubsurface(material) {
    const removed = this._subsurfaceMaterials.unbind(material);
    this._useProfiles();
    return removed;
  }

  /**
   * The tables of `profile`: the pipeline's own for its profile, else one kept per profile.
   * @private @param {object} profile
   */
  _lookupOf(profile) {
    if (profile === this.profile) return this._profileLookup;
    if (!this._otherLookups.has(profile)) this._otherLookups.set(profile, new ProfileLookup(profile));
    return this._otherLookups.get(profile);
  }

  /**
   * Refuses materials' `profiles` that `method` cannot blur in one frame, or more than MAX_PROFILES
   * (the error names `caller`); `fallback`: the pipeline's profile.
   * @private
   */
  _checkProfiles(method, profiles, fallback, caller) {
    this._blur.checkProfileCount(method, profileSlots(profiles, fallback, caller).profiles.length);
  }

  /**
   * Points the blur, the multi-target and each material at the slots of the profiles the materials
   * use now (src/profiles/profileSlots.js): one profile, the frame as without this feature.
   * @private
   */
  _useProfiles() {
    const { profiles, slots } = profileSlots(this._subsurfaceMaterials.profiles(), this.profile);
    // The tables of profiles no material uses any more go (a material rebound with new profile
    // objects would otherwise pile them up).
    for (const [profile, lookup] of this._otherLookups) {
      if (profiles.includes(profile)) continue;
      lookup.dispose();
      this._otherLookups.delete(profile);
    }
    this._blur.setProfiles(profiles.map((profile) => this._lookupOf(profile)));
    this._scenePass.setProfileCount(profiles.length);
    [...this._subsurfaceMaterials.entries.values()].forEach(({ hook }, i) => { hook.profileSlot = slots[i]; });
  }

  /**
   * The materials made subsurface through this pipeline, each with its binding and options.
   * @type {Map<import('three').MeshStandardMaterial, { hook: import('./2-scene-split/subsurfaceMaterial.js').SubsurfaceBinding, options: import('./options.js').SubsurfaceMaterialOptions }>}
   */
  get materials() { return this._subsurfaceMaterials.entries; }

  /**
   * Sizes every target, as the composer does on composer.setSize. At least 1 × 1; larger than the
   * GPU's largest render target (MAX_TEXTURE_SIZE, MAX_RENDERBUFFER_SIZE) is a RangeError, here once
   * a frame has told the pipeline the GPU's limits, else on the next frame.
   * @param {number} width device pixels @param {number} height device pixels
   */
  setSize(width, height) {
    checkTargetSize(width, height, 'SubsurfaceScattering.setSize', this._limits);
    this._size = { width, height };
    this._scenePass.setSize(width, height);
    this._blur.setSize(width, height);
    this._composePass.setSize(width, height);
  }

  /** Frees every target, material, texture and quad the pipeline created, and unbinds its materials. */
  dispose() {
    stopWatching(this);
    this._subsurfaceMaterials.dispose();
    this._scenePass.dispose();
    this._blur.dispose();
    this._composePass.dispose();
    for (const lightDepth of this._lightDepths) lightDepth.dispose();
    this._profileLookup.dispose();
    for (const lookup of this._otherLookups.values()) lookup.dispose();
  }
}

// enabled, needsSwap, clear and renderToScreen (three's Pass fields) and clearDepth: booleans only.
booleanFields(SubsurfaceScattering.prototype, [...PASS_BOOLEANS, 'clearDepth']);
// 0.1's `enabled = false` turned the blur off; now it skips the pass. Said once where it freezes the frame.
warnWhenDisabledFreezes(SubsurfaceScattering.prototype, 'SubsurfaceScattering: enabled is false and nothing else draws its ' +
  'scene, so the composer shows the last frame it drew, frozen (enabled = false skips the pass, as for any pass). To turn ' +
  'the blur off, set scattering = false (in version 0.1 that was enabled = false); to draw the scene without the ' +
  'pipeline, enable a RenderPass in its place.');

nameClass(SubsurfaceScattering, 'SubsurfaceScattering'); // its name in messages, minified or not
