// The WebGPURenderer version of the pipeline: a node for three's RenderPipeline, used as three's
// display nodes are. Its input is a scene pass whose MRT is subsurfaceMRT() (stage 2: the
// subsurface node materials write the diffuse light and the surface there); the node runs stage 3,
// the two separable blur passes, before the frame (updateBefore), and is itself stage 4, the
// compose. What the WebGL path's orchestrator does per frame (src/SubsurfaceScattering.js, steps
// 3 to 5) happens here in the same order, with the same CPU side: the profile tables, the footprint
// tables, the frame plan and the parameter checks are imported from src/, not copied.
//
//   const scenePass = pass(scene, camera);
//   scenePass.setMRT(subsurfaceMRT());
//   pipeline.outputNode = subsurfaceScattering(scenePass, { worldUnitInMm: 1000 });
import { Node, NodeMaterial, NodeUpdateType, QuadMesh, RenderTarget, RendererUtils } from 'three/webgpu';
import { FloatType, HalfFloatType, Vector2, Vector3 } from 'three';
import { passTexture, texture, uniform } from 'three/tsl';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { FootprintTable } from '../profiles/FootprintTable.js';
import { AUTO_MAX_SAMPLES } from '../profiles/footprints.js';
import { computeKernel } from '../profiles/kernel.js';
import { getProfile } from '../profiles/presets.js';
import { estimatePixelsPerMm, planFrame } from '../framePlan.js';
import { isPerspective } from '../support/screenScale.js';
import { checkBoolean, checkNumber, checkOneOf, checkOptions, checkRgb } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { FOLLOW_SURFACE_MODES } from '../options.js';
import {
  KERNEL_OPTIONS, NODE_DEFAULTS, checkDepthThreshold, checkMethod, checkWorldUnit,
} from './nodeOptions.js';
import { ATTACHMENT_NAMES } from './2-scene-split/attachments.js';
import { subsurfaceBlurNode } from './3-blur/subsurfaceBlurTsl.js';
import { checkWebgpuThree } from './threeVersion.js';
import { NODE_DEBUG_VIEWS, composeNode, debugViewUniform } from './4-compose/composeTsl.js';
import { DEBUG_VIEWS } from '../4-compose/debugViews.js';

const _quadMesh = /*@__PURE__*/ new QuadMesh();
const _size = /*@__PURE__*/ new Vector2();
let _rendererState;

export class SubsurfaceScatteringNode extends Node {
  static get type() {
    return 'SubsurfaceScatteringNode';
  }

  /**
   * @param {import('three/webgpu').PassNode} scenePass pass(scene, camera) with subsurfaceMRT()
   * @param {Partial<typeof NODE_DEFAULTS>} [options]
   */
  constructor(scenePass, options) {
    super('vec4');
    checkWebgpuThree();
    if (!scenePass || scenePass.isPassNode !== true) throw new TypeError(`subsurfaceScattering: scenePass must be a PassNode (pass(scene, camera)), got ${describe(scenePass)}`);
    const o = { ...NODE_DEFAULTS, ...checkOptions('subsurfaceScattering options', options, Object.keys(NODE_DEFAULTS)) };
    this.method = checkMethod(o.method);
    this.scenePass = scenePass;
    this.scattering = true;
    this.profileLookup = new ProfileLookup(getProfile(o.profile));
    this.footprintTable = new FootprintTable(this.profileLookup);
    this._uniforms = {
      kernelRadiusMm: uniform(0), strength: uniform(new Vector3(1, 1, 1)), projectionScale: uniform(new Vector2(1, 1)),
      resolution: uniform(new Vector2(1, 1)), depthFalloff: uniform(1), perspective: uniform(1), mmToWorld: uniform(1e-3),
      marginalRangeMm: uniform(1), debugView: debugViewUniform(), debugDepthRange: uniform(1),
    };
    /** What the output shows: 'final' or one ingredient (see setDebugView). */
    this.debugView = 'final';
    this.worldUnitInMm = o.worldUnitInMm;
    this.setKernel({ samples: o.samples, strength: o.strength });
    this.setFollowSurface(o.followSurface, o.depthThresholdMm);
    this.setForeshortening(o.foreshortening);
    /** What the last frame ran: { samples, kernelPixels, blur } (see planFrame). */
    this.plan = { samples: 0, kernelPixels: 0, blur: false };

    // The surface needs the 32-bit mantissa (mm differences at metres); the light is half float.
    scenePass.getTexture(ATTACHMENT_NAMES.SURFACE).type = FloatType;
    scenePass.getTexture(ATTACHMENT_NAMES.DIFFUSE).type = HalfFloatType;
    this._horizontalTarget = new RenderTarget(1, 1, { type: HalfFloatType, depthBuffer: false });
    this._horizontalTarget.texture.name = 'subsurface.horizontal';
    this._scatteredTarget = new RenderTarget(1, 1, { type: HalfFloatType, depthBuffer: false });
    this._scatteredTarget.texture.name = 'subsurface.scattered';
    /** @type {import('three/webgpu').TextureNode} what the compose adds: the scattered light (or the unblurred light when the plan skips the blur) */
    this._scatteredNode = /** @type {any} */ (passTexture(this, this._scatteredTarget.texture));
    this._materials = null; // the two blur passes' materials, built for _blurKey
    this._blurKey = '';
    this._profileNode = texture(this.profileLookup.texture);
    this._footprintNode = texture(this.footprintTable.update(this.samples === 'auto' ? 'auto' : this.samples));
    this.updateBeforeType = NodeUpdateType.FRAME;
    this.isSubsurfaceScatteringNode = true;
  }

  /** Millimetres per world unit (three.js: metres, 1000). */
  get worldUnitInMm() {
    return this._worldUnitInMm;
  }

  set worldUnitInMm(mm) {
    this._worldUnitInMm = checkWorldUnit(mm);
    this._uniforms.mmToWorld.value = 1 / mm;
    if (this.depthThresholdMm !== undefined) this.setFollowSurface(this.followSurface, this.depthThresholdMm);
  }

  /** Whether the blur runs (false: the output equals the scene without scattering). */
  get scattering() {
    return this._scattering;
  }

  set scattering(enabled) {
    this._scattering = checkBoolean('SubsurfaceScatteringNode.scattering', enabled);
  }

  /** @param {boolean} enabled the grazing-angle correction (shrink the step by cos(tilt), compare depths with the local plane) */
  setForeshortening(enabled) {
    this.foreshortening = checkBoolean('foreshortening', enabled);
  }

  /** The diffusion profile object (set it with setKernel({ profile })). */
  get profile() {
    return this.profileLookup.profile;
  }

  /**
   * The profile, the taps and the strength, checked as the WebGL pipeline checks them (the profile
   * by getProfile, the taps and the strength by computeKernel's marginal kernel, which 'footprint'
   * builds on); the profile tables are refilled only when the profile changes.
   * @param {{ profile?: string|object, method?: 'footprint', samples?: number|'auto', strength?: number[] }} options
   */
  setKernel(options) {
    if (options === null || typeof options !== 'object' || Array.isArray(options)) {
      throw new TypeError(`setKernel: options must be an object { profile, method, samples, strength, falloff }, got ${describe(options)}`);
    }
    checkOptions('setKernel options', options, KERNEL_OPTIONS);
    const { profile, method = this.method, samples = this.samples, strength = this.strength } = options;
    checkMethod(method);
    const p = profile === undefined ? this.profileLookup.profile : getProfile(profile);
    computeKernel({ profile: p, method: 'marginal', samples: samples === 'auto' ? AUTO_MAX_SAMPLES : samples, strength });
    if (p !== this.profileLookup.profile) this.profileLookup.setProfile(p); // tens of ms: only on a change
    this.samples = samples;
    this.strength = checkRgb('strength', strength, { min: 0, max: 1 });
    this._uniforms.strength.value.fromArray(this.strength);
  }

  /**
   * @param {'drop'|'lerp'|'off'} mode what a tap on another surface does
   * @param {number} [depthThresholdMm] depth step (mm) treated as another surface
   */
  setFollowSurface(mode, depthThresholdMm = this.depthThresholdMm) {
    checkOneOf('followSurface', mode, FOLLOW_SURFACE_MODES);
    checkDepthThreshold(depthThresholdMm);
    this.followSurface = mode;
    this.depthThresholdMm = depthThresholdMm;
    this._uniforms.depthFalloff.value = this.worldUnitInMm / depthThresholdMm; // 1 / threshold in world units
  }

  /**
   * Shows one ingredient instead of the final image, as the WebGL pipeline's setDebugView does:
   * 'final', 'diffuse' (the scattered diffuse light), 'specular' (the rest of subsurface pixels),
   * 'mask', 'depth' (linear view depth, white at 0, black at `depthRange` world units).
   * A uniform: switching rebuilds nothing.
   * @param {'final'|'diffuse'|'specular'|'mask'|'depth'} view
   * @param {{ depthRange?: number }} [options]
   */
  setDebugView(view, options) {
    const { depthRange = 1 } = checkOptions('setDebugView options', options, ['depthRange']);
    checkOneOf('view', view, DEBUG_VIEWS);
    if (!NODE_DEBUG_VIEWS.includes(view)) {
      throw new RangeError(`setDebugView: view '${view}' needs transmittance, which the node does not have yet (it has ${NODE_DEBUG_VIEWS.map((v) => `'${v}'`).join(', ')})`);
    }
    checkNumber('depthRange', depthRange, { min: 0, minExclusive: true, unit: 'world units' });
    this._uniforms.debugView.value = DEBUG_VIEWS.indexOf(view);
    this._uniforms.debugDepthRange.value = depthRange;
    this.debugView = view;
  }

  /** @returns {import('three/webgpu').TextureNode} the scattered diffuse light, premultiplied by its coverage */
  getTextureNode() {
    return this._scatteredNode;
  }

  /** The frame plan (src/framePlan.js): the on-screen reach of the kernel, the taps, whether the blur runs. */
  _planFrame(camera, width, height) {
    const meshes = [];
    this.scenePass.scene.traverseVisible((object) => {
      if (!object.isMesh) return;
      const materials = Array.isArray(object.material) ? object.material : [object.material];
      if (materials.some((m) => m?.isSubsurfaceNodeMaterial)) meshes.push(object);
    });
    const pixelsPerMm = estimatePixelsPerMm(meshes, camera, { width, height },
      (m) => (m?.isSubsurfaceNodeMaterial ? m.widthMm / this.worldUnitInMm : undefined));
    return planFrame({
      scattering: this.scattering,
      pixelsPerMm,
      samples: this.samples,
      autoRadiusMm: this.profileLookup.marginalRadiusMm,
      radiusMmOf: () => this.profileLookup.marginalRadiusMm, // 'footprint': the radius holding 99 % (BlurStage.radiusMmOf)
      autoSamples: () => AUTO_MAX_SAMPLES, // footprints choose per pixel (BlurStage.autoSamplesFor)
    });
  }

  /** The two blur materials, rebuilt when a compile-time switch changes (taps, depth rule, MSAA). */
  _blurMaterials(samples, coverage) {
    const key = JSON.stringify([samples, this.followSurface, this.foreshortening, coverage]);
    if (this._materials && key === this._blurKey) return this._materials;
    this._materials ??= [new NodeMaterial(), new NodeMaterial()];
    const common = {
      samples, followSurface: this.followSurface, foreshorten: this.foreshortening, coverage, uniforms: this._uniforms,
      surface: this.scenePass.getTextureNode(ATTACHMENT_NAMES.SURFACE), profile: this._profileNode,
      profileSize: this.profileLookup.texture.image.width, footprints: this._footprintNode,
    };
    const inputs = [this.scenePass.getTextureNode(ATTACHMENT_NAMES.DIFFUSE), texture(this._horizontalTarget.texture)];
    this._materials.forEach((material, axis) => {
      material.fragmentNode = subsurfaceBlurNode({ ...common, axis, diffuse: inputs[axis] });
      material.name = `SubsurfaceBlur(${axis === 0 ? 'horizontal' : 'vertical'})`;
      material.needsUpdate = true;
    });
    this._blurKey = key;
    return this._materials;
  }

  updateBefore(frame) {
    const { renderer } = frame;
    const { scenePass } = this;
    const camera = scenePass.camera;
    const { scene } = scenePass;
    if (scene.fog && !this._warnedFog) {
      this._warnedFog = true; // said once, not silently wrong
      console.warn('SubsurfaceScatteringNode: scene.fog fogs the colour output only; the diffuse light of subsurface materials is not fogged on this renderer yet (the WebGL pipeline fades it)');
    }
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    // The pass's size as the pass sets it (PassNode.updateBefore), known before it renders.
    renderer.getDrawingBufferSize(_size);
    scenePass.setSize(_size.width, _size.height);
    const { width, height } = scenePass.renderTarget;
    this.plan = this._planFrame(camera, width, height);
    const diffuse = scenePass.getTexture(ATTACHMENT_NAMES.DIFFUSE);
    if (!this.plan.blur) {
      this._scatteredNode.value = diffuse; // the compose reads the unblurred light: the output equals no SSS
      return;
    }
    this._scatteredNode.value = this._scatteredTarget.texture;
    const projection = camera.projectionMatrix.elements;
    const u = this._uniforms;
    u.projectionScale.value.set(projection[0], projection[5]);
    u.perspective.value = isPerspective(camera) ? 1 : 0;
    u.resolution.value.set(width, height);
    u.kernelRadiusMm.value = this.profileLookup.marginalRadiusMm;
    u.marginalRangeMm.value = this.profileLookup.marginalRangeMm;
    this._footprintNode.value = this.footprintTable.update(this.samples === 'auto' ? 'auto' : this.samples);
    const coverage = scenePass.renderTarget.samples > 0;
    const [horizontal, vertical] = this._blurMaterials(this.plan.samples, coverage);
    this._horizontalTarget.setSize(width, height);
    this._scatteredTarget.setSize(width, height);

    _rendererState = RendererUtils.resetRendererState(renderer, _rendererState);
    _quadMesh.material = horizontal;
    _quadMesh.name = 'Subsurface blur [ horizontal ]';
    renderer.setRenderTarget(this._horizontalTarget);
    _quadMesh.render(renderer); // renders the scene pass first (its texture is this material's input)
    _quadMesh.material = vertical;
    _quadMesh.name = 'Subsurface blur [ vertical ]';
    renderer.setRenderTarget(this._scatteredTarget);
    _quadMesh.render(renderer);
    RendererUtils.restoreRendererState(renderer, _rendererState);
  }

  setup() {
    return composeNode({
      colour: this.scenePass.getTextureNode(ATTACHMENT_NAMES.COLOR),
      unscattered: this.scenePass.getTextureNode(ATTACHMENT_NAMES.DIFFUSE),
      scattered: this._scatteredNode,
      surface: this.scenePass.getTextureNode(ATTACHMENT_NAMES.SURFACE),
      view: this._uniforms.debugView,
      depthRange: this._uniforms.debugDepthRange,
    });
  }

  /** Frees the node's targets, tables and materials (the scene pass is the caller's). */
  dispose() {
    this._horizontalTarget.dispose();
    this._scatteredTarget.dispose();
    this.footprintTable.dispose();
    this.profileLookup.dispose();
    for (const material of this._materials ?? []) material.dispose();
    this._materials = null;
    super.dispose();
  }
}

/**
 * The subsurface scattering node over a scene pass (see the file's header).
 * @param {import('three/webgpu').PassNode} scenePass
 * @param {Partial<typeof NODE_DEFAULTS>} [options]
 */
export const subsurfaceScattering = (scenePass, options) => new SubsurfaceScatteringNode(scenePass, options);
