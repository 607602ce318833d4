// The WebGPURenderer version of the pipeline: a node for three's RenderPipeline, used as three's
// display nodes are. Its input is a scene pass whose MRT is subsurfaceMRT() (stage 2: the
// subsurface node materials write the diffuse light and the surface there); the node runs stage 3,
// the two separable blur passes (with kernelGroups, the isotropic blur's groups: the horizontal
// pass writes each to an attachment of its own, the vertical one sums them), before the frame
// (updateBefore), and is itself stage 4, the compose. With a `light` (or several) it runs stage 1
// too (./1-light-depth/LightStageNode.js): a light depth pass per light for transmittance, and the
// subsurface materials' transmittance uniforms, before the scene pass draws them. What the WebGL path's orchestrator does per frame
// (src/SubsurfaceScattering.js, steps 0 to 5) happens here in the same order, with the same CPU
// side: the profile tables, the footprint tables, the frame plan, the light's checks and the
// parameter checks are imported from src/, not copied.
//
//   const scenePass = pass(scene, camera);
//   scenePass.setMRT(subsurfaceMRT());
//   pipeline.outputNode = subsurfaceScattering(scenePass, { worldUnitInMm: 1000, light });
import { Node, NodeMaterial, NodeUpdateType, QuadMesh, RenderTarget, RendererUtils } from 'three/webgpu';
import { FloatType, HalfFloatType, RGFormat, Vector2, Vector3, Vector4 } from 'three';
import { passTexture, uniform } from 'three/tsl';
import { MAX_KERNEL_GROUPS } from '../3-blur/kernelGroups.js';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { FootprintTable } from '../profiles/FootprintTable.js';
import { AUTO_MAX_SAMPLES } from '../profiles/footprints.js';
import { computeKernel } from '../profiles/kernel.js';
import { estimatePixelsPerMm } from '../framePlan.js';
import { subsurfaceScreenBox } from '../2-scene-split/subsurfaceScreenBox.js';
import { planBlur } from '../3-blur/blurPlan.js';
import { isPerspective } from '../support/screenScale.js';
import { describe } from '../support/rendererSupport.js';
import { LightStageNode } from './1-light-depth/LightStageNode.js';
import { FrameMeshes } from '../frameMeshes.js';
import {
  NODE_SCHEMA, checkNodeOptions, lightsOf, propertiesOf,
} from '../options.js';
import { withSettings } from '../support/settings.js';
import { FrameChecks } from '../support/frameChecks.js';
import { WEBGPU_THREE, checkThreeRevision } from '../support/threeVersion.js';
import { ATTACHMENT_NAMES } from './2-scene-split/attachments.js';
import { subsurfaceBlurNode } from './3-blur/subsurfaceBlurTsl.js';
import { texelTexture } from './common/surfaceTsl.js';
import { GroupFractionTexture } from './3-blur/GroupFractionTexture.js';

import { composeNode, debugViewUniform } from './4-compose/composeTsl.js';
import { DEBUG_VIEWS } from '../4-compose/debugViews.js';

/** The methods the node has: the WebGL pipeline's default (the fixed-tap ones are the WebGL pipeline's only). */
export const NODE_METHODS = Object.freeze(['footprint']);

/** A method of the schema the node lacks is refused, naming the pipeline that has it. */
function checkNodeMethod(method) {
  if (!NODE_METHODS.includes(method)) {
    throw new RangeError(`method '${method}' is not available on the WebGPU node (only ${NODE_METHODS.map((m) => `'${m}'`).join(', ')}); the WebGL pipeline has the others`);
  }
}

const _quadMesh = /*@__PURE__*/ new QuadMesh();
const _size = /*@__PURE__*/ new Vector2();
let _rendererState;

/** three's Node with the node's settings as properties (src/options.js's schema; src/support/settings.js). */
const NodeWithSettings = /** @type {new (type: string) => Node & import('../options.js').NodeSettings} */ (
  withSettings(Node, NODE_SCHEMA, 'SubsurfaceScatteringNode'));

/**
 * Screen-space subsurface scattering as a node of three's RenderPipeline (WebGPURenderer):
 * ```js
 * const scenePass = pass(scene, camera);
 * scenePass.setMRT(subsurfaceMRT());
 * const sss = subsurfaceScattering(scenePass, { worldUnitInMm: 1000, light });
 * pipeline.outputNode = sss;
 * sss.samples = 25;   // every option is a property, checked on assignment, as on the WebGL pipeline
 * ```
 */
export class SubsurfaceScatteringNode extends NodeWithSettings {
  static get type() {
    return 'SubsurfaceScatteringNode';
  }

  /**
   * @param {import('three/webgpu').PassNode} scenePass pass(scene, camera) with subsurfaceMRT()
   * @param {import('../options.js').SubsurfaceScatteringNodeOptions} [options]
   */
  constructor(scenePass, options) {
    checkThreeRevision('SubsurfaceScatteringNode', WEBGPU_THREE);
    super('vec4');
    if (!scenePass || scenePass.isPassNode !== true) throw new TypeError(`subsurfaceScattering: scenePass must be a PassNode (pass(scene, camera)), got ${describe(scenePass)}`);
    const o = checkNodeOptions(options); // every option checked here, once, against the schema
    checkNodeMethod(o.method);
    /** @internal The settings' values (read and assigned through their properties). */
    this._settings = Object.fromEntries(propertiesOf(NODE_SCHEMA).map(({ name }) => [name, o[name]]));
    /** @internal Whether the user set `transmittance` true, for the frame's word when there is no light (as the WebGL pipeline). */
    this._transmittanceAsked = Object.hasOwn(options ?? {}, 'transmittance') && o.transmittance;
    this.scenePass = scenePass;
    this.profileLookup = new ProfileLookup(o.profile);
    this.footprintTable = new FootprintTable(this.profileLookup);
    this._uniforms = {
      kernelRadiusMm: uniform(0), strength: uniform(new Vector3()), projectionScale: uniform(new Vector2(1, 1)),
      resolution: uniform(new Vector2(1, 1)), depthFalloff: uniform(1), perspective: uniform(1), mmToWorld: uniform(1e-3),
      marginalRangeMm: uniform(1), debugView: debugViewUniform(), debugDepthRange: uniform(1), debugThicknessRangeMm: uniform(1), scatteredShare: uniform(1),
      subsurfaceBox: uniform(new Vector4(0, 0, 1, 1)), // the subsurface pixels' box: x0, y0, x1, y1, pixels from the top left
      lightShown: uniform(0), // the light's views show nothing without one (the WebGL materials write 0 there): set with the light stage's lights
    };
    /** What the frame covers (src/frameMeshes.js), made by the light stage each frame before the scene pass draws. */
    this.frame = new FrameMeshes();
    /** The frame's own checks (the light's are the light stage's), each warned about once. */
    this._checks = new FrameChecks('SubsurfaceScatteringNode');
    /** Stage 1 and the materials' transmittance uniforms, before the scene pass (built with or without a light: `light` is assignable). */
    this._lightStage = new LightStageNode(this, o.lightDepthSize);
    for (const name of ['worldUnitInMm', 'samples', 'strength', 'debugView', 'debugDepthRange', 'debugThicknessRangeMm']) this._applySetting(name, o[name]);
    /** What the last frame ran: { samples, kernelPixels, blur, passes, groups, groupings } (see src/3-blur/blurPlan.js). */
    this.plan = { samples: 0, tapBlend: null, kernelPixels: 0, blur: false, fade: 0, passes: 'separable', groups: 1, groupings: null };

    // The surface needs the 32-bit mantissa (mm differences at metres), two channels of it (every
    // draw of the pass writes it: 8 B a pixel, not 16); the light is half float.
    Object.assign(scenePass.getTexture(ATTACHMENT_NAMES.SURFACE), { type: FloatType, format: RGFormat });
    scenePass.getTexture(ATTACHMENT_NAMES.DIFFUSE).type = HalfFloatType;
    // 32 bits: without MSAA it carries the depth to the vertical pass (the WebGL blur's target too).
    this._horizontalTarget = new RenderTarget(1, 1, { type: FloatType, depthBuffer: false });
    this._horizontalTarget.texture.name = 'subsurface.horizontal';
    this._scatteredTarget = new RenderTarget(1, 1, { type: HalfFloatType, depthBuffer: false });
    this._scatteredTarget.texture.name = 'subsurface.scattered';
    /** @type {import('three/webgpu').TextureNode} what the compose adds: the scattered light (or the unblurred light when the plan skips the blur) */
    this._scatteredNode = /** @type {any} */ (passTexture(this, this._scatteredTarget.texture));
    /** @type {Map<number, { key: string, materials: NodeMaterial[] }>} the blur passes' two materials per group count (1: one kernel), built for the switches in `key` */
    this._materials = new Map();
    // The isotropic blur, built when a frame first blurs in groups: the multi-target between the
    // passes (an attachment per group), the fractions' texture and each group's energy share.
    /** @type {RenderTarget|null} */
    this._groupTarget = null;
    this._groupFractions = new GroupFractionTexture();
    this._groupFractionNode = null;
    this._groupEnergies = Array.from({ length: MAX_KERNEL_GROUPS }, () => uniform(new Vector3()));
    this._profileNode = texelTexture(this.profileLookup.texture);
    this._footprintNode = texelTexture(this.footprintTable.update(this.samples === 'auto' ? 'auto' : this.samples));
    // Planned per render, not per frame: a setting changed between two renders of one animation
    // frame (scattering, samples) is this render's (the scene pass still draws once a frame).
    this.updateBeforeType = NodeUpdateType.RENDER;
    this.isSubsurfaceScatteringNode = true;
  }

  /**
   * Acts on a setting just assigned (already checked and kept; a throw here puts the old value
   * back). The node reads the rest (kernelGroups, followSurface, foreshortening, scattering) each frame.
   * @private @param {string} name @param {*} value @param {*} [previous]
   */
  _applySetting(name, value, previous) {
    const u = this._uniforms;
    switch (name) {
      case 'worldUnitInMm': case 'depthThresholdMm':
        u.mmToWorld.value = 1 / this.worldUnitInMm;
        u.depthFalloff.value = this.worldUnitInMm / this.depthThresholdMm;
        return;
      case 'method':
        checkNodeMethod(value);
        return;
      case 'samples': // the kernel must be buildable with that many taps
        computeKernel({ profile: this.profile, method: 'marginal', samples: value === 'auto' ? AUTO_MAX_SAMPLES : value });
        return;
      case 'profile':
        if (value !== this.profileLookup.profile) this.profileLookup.setProfile(value); // tens of ms: only on a change
        return;
      case 'strength': // undefined: the method's own, no mix
        u.strength.value.fromArray(value ?? [1, 1, 1]);
        return;
      case 'transmittance':
        this._transmittanceAsked = value;
        return;
      case 'light': // as the WebGL pipeline: transmittance and debugView stay as set, acting through the light there is
        if (value === previous) return;
        this._lightStage.setLights(lightsOf(value)); // 'castShadow': found each frame
        return;
      case 'debugView':
        u.debugView.value = DEBUG_VIEWS.indexOf(value);
        return;
      case 'debugDepthRange': case 'debugThicknessRangeMm':
        u[name].value = value;
        return;
      case 'lightDepthSize':
        for (const lightDepth of this._lightStage?.lightDepths ?? []) lightDepth.setSize(value); // kept while the light is null, for the next one
        return;
      default:
    }
  }

  /**
   * The diffusion profile of the materials that name none: a preset's name or a profile object,
   * read back as the profile object; the tables are refilled only on a change.
   * @type {import('../options.js').DiffusionProfile}
   */
  get profile() { return super.profile; }

  /** @param {import('../options.js').ProfileName|object} profile */
  set profile(profile) { super.profile = profile; }

  /** What the last frame found wrong with the lights or the camera, one message each (empty when all is well). @type {readonly string[]} */
  get problems() {
    const [light, frame] = [this._lightStage.checks.current, this._checks.current];
    return frame.length === 0 ? light : Object.freeze([...light, ...frame]);
  }

  /**
   * Stage 1: the light depth maps for transmittance, one per light (with `'castShadow'`: the last
   * frame's casters), empty without a light.
   * @type {readonly import('./1-light-depth/LightDepthNodeTarget.js').LightDepthNodeTarget[]}
   */
  get lightDepths() { return this._lightStage.lightDepths.slice(0, this._lightStage.count); }

  /** The first light's map (the one the thickness view shows), or null without a light. @type {import('./1-light-depth/LightDepthNodeTarget.js').LightDepthNodeTarget|null} */
  get lightDepth() { return this.lightDepths[0] ?? null; }

  /** @returns {import('three/webgpu').TextureNode} the scattered diffuse light, premultiplied by its coverage */
  getTextureNode() {
    return this._scatteredNode;
  }

  /** The frame plan (src/3-blur/blurPlan.js): the on-screen reach of the kernel, the taps, whether the blur runs. */
  _planFrame(meshes, camera, width, height) {
    const pixelsPerMm = estimatePixelsPerMm(meshes, camera, { width, height },
      (m) => (m?.isSubsurfaceNodeMaterial ? m.widthMm / this.worldUnitInMm : undefined));
    // Stage 3 plans itself from its own settings, as on the WebGL path (src/3-blur/blurPlan.js).
    return planBlur({
      method: this.method, samples: this.samples, scattering: this.scattering,
      marginalRadiusMm: this.profileLookup.marginalRadiusMm, denseRadiusMm: 0, kernelReachMm: {},
      kernelGroups: this.kernelGroups, profiles: [this.profile],
    }, pixelsPerMm);
  }

  /**
   * The blur materials for a frame of `groups` groups (1: one kernel): [horizontal, vertical],
   * rebuilt when a compile-time switch changes (taps, depth rule, MSAA). One pair is kept per
   * count, so 'auto' switching between one kernel and groups as a head zooms compiles nothing twice.
   */
  _blurMaterials(samples, coverage, groups) {
    const key = JSON.stringify([samples, this.followSurface, this.foreshortening, coverage]);
    const held = this._materials.get(groups);
    if (held?.key === key) return held.materials;
    this._freeMaterials(groups);
    const common = {
      samples, followSurface: this.followSurface, foreshorten: this.foreshortening, coverage, uniforms: this._uniforms,
      surface: this.scenePass.getTextureNode(ATTACHMENT_NAMES.SURFACE), profile: this._profileNode,
      profileSize: this.profileLookup.texture.image.width, footprints: this._footprintNode,
    };
    const diffuse = this.scenePass.getTextureNode(ATTACHMENT_NAMES.DIFFUSE);
    const material = (fragmentNode, name) => Object.assign(new NodeMaterial(), { fragmentNode, name });
    let materials;
    if (groups === 1) {
      // Without MSAA the horizontal pass hands the depth on in its alpha (the coverage is 1 on the
      // mask): the vertical pass's taps fetch one texel each, not two (carriedDepth.glsl).
      const carried = !coverage;
      materials = [
        material(subsurfaceBlurNode({ ...common, axis: 0, diffuse, carryDepth: carried }), 'SubsurfaceBlur(horizontal)'),
        material(subsurfaceBlurNode({ ...common, axis: 1, diffuse: texelTexture(this._horizontalTarget.texture), carriesDepth: carried }), 'SubsurfaceBlur(vertical)'),
      ];
    } else {
      this._groupFractionNode ??= texelTexture(this._groupFractions.texture);
      const { textures } = this._groupTarget;
      const lights = textures.map((t) => texelTexture(t));
      const split = { count: groups, fractions: this._groupFractionNode };
      materials = [
        material(subsurfaceBlurNode({ ...common, axis: 0, diffuse, groups: { ...split, names: textures.map((t) => t.name), energies: this._groupEnergies } }), `SubsurfaceBlur(horizontal, ${groups} groups)`),
        material(subsurfaceBlurNode({ ...common, axis: 1, diffuse: lights[0], groups: { ...split, lights } }), `SubsurfaceBlur(vertical, ${groups} groups)`),
      ];
    }
    this._materials.set(groups, { key, materials });
    return materials;
  }

  /** Frees the materials of frames in `groups` groups. */
  _freeMaterials(groups) {
    for (const material of this._materials.get(groups)?.materials ?? []) material.dispose();
    this._materials.delete(groups);
  }

  /** Frees the group target and the grouped materials that read it (back to one kernel, or another count). */
  _freeGroupTarget() {
    if (!this._groupTarget) return;
    this._groupTarget.dispose();
    this._groupTarget = null;
    for (const groups of [...this._materials.keys()]) if (groups > 1) this._freeMaterials(groups);
  }

  /**
   * The group targets, fractions and energy shares of a frame in groups (plan.groupings: the
   * node's one profile, slot 0).
   * @param {ReturnType<typeof import('../3-blur/kernelGroups.js').kernelGroups>} grouping
   */
  _groupFrame(grouping, width, height) {
    if (this._groupTarget?.textures.length !== grouping.count) {
      this._freeGroupTarget();
      this._groupTarget = new RenderTarget(1, 1, { type: HalfFloatType, depthBuffer: false, count: grouping.count });
      this._groupTarget.textures.forEach((t, g) => { t.name = `subsurfaceGroup${g + 1}`; }); // the horizontal pass's mrt() names
    }
    this._groupTarget.setSize(width, height);
    const fractions = this._groupFractions.update(grouping, this.footprintTable.table);
    if (this._groupFractionNode) this._groupFractionNode.value = fractions;
    this._groupFractions.energies.forEach((rgb, g) => this._groupEnergies[g].value.fromArray(rgb));
  }

  /**
   * Stage 3 before the frame (three calls it once a render: updateBeforeType RENDER).
   * @param {import('three/webgpu').NodeFrame} frame
   * @returns {undefined}
   */
  updateBefore(frame) {
    const { renderer } = frame;
    const { scenePass } = this;
    const camera = scenePass.camera;
    const { scene } = scenePass;
    if (scene.fogNode && !this._warnedFog) {
      this._warnedFog = true; // said once, not silently wrong
      console.warn('SubsurfaceScatteringNode: a custom scene.fogNode fogs the colour output only; the diffuse light of subsurface materials fades with scene.fog (Fog, FogExp2), not with a fog node');
    }
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    // The pass's size as the pass sets it (PassNode.updateBefore), known before it renders.
    renderer.getDrawingBufferSize(_size);
    scenePass.setSize(_size.width, _size.height);
    const { width, height } = scenePass.renderTarget;
    // An ArrayCamera's views would each need their own blur (the WebGL pipeline's): drawn unblurred, said.
    const views = camera.isArrayCamera === true;
    this._checks.begin();
    if (views) {
      this._checks.problem('arrayCamera', 'the camera is an ArrayCamera: the node blurs one view, so its views are drawn without scattering, ' +
        'as three draws them; the WebGL pipeline (SubsurfaceScattering) blurs each view at its own scale');
    }
    this._checks.end();
    const meshes = views ? [] : this.frame.onScreen; // the light stage's lists, this frame's
    this.plan = this._planFrame(meshes, camera, width, height);
    this._uniforms.scatteredShare.value = this.plan.blur ? this.plan.fade : 1; // the blur fading in (blurPlan.js)
    if (this.kernelGroups === 1) this._freeGroupTarget(); // back to one kernel: its 8 B per pixel and group go
    // Where the subsurface pixels can be (the meshes' bounds; null: anywhere): the blur runs there
    // only, and the compose reads the scattered light there only.
    const box = subsurfaceScreenBox(meshes, camera, width, height);
    const { x, y, width: w, height: h } = box ?? { x: 0, y: 0, width, height };
    const top = height - y - h; // WebGPURenderer's scissors and the shaders' pixels count from the top left
    this._uniforms.subsurfaceBox.value.set(x, top, x + w, top + h);
    const diffuse = scenePass.getTexture(ATTACHMENT_NAMES.DIFFUSE);
    if (!this.plan.blur || box?.width === 0) {
      this._scatteredNode.value = diffuse; // the compose reads the unblurred light: the output equals no SSS
      return undefined;
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
    const { groups } = this.plan;
    if (groups > 1) this._groupFrame(this.plan.groupings[0], width, height);
    else this._horizontalTarget.setSize(width, height);
    this._scatteredTarget.setSize(width, height);
    // The passes run in the box alone, their targets not cleared: a render pass's clear is its
    // whole attachment's, whatever the scissor (on SwiftShader it cost more than a pass over the
    // head). Every pixel of the box is written; outside it the taps and the compose read nothing.
    for (const target of [groups > 1 ? this._groupTarget : this._horizontalTarget, this._scatteredTarget]) {
      target.scissor.set(x, top, w, h);
      target.scissorTest = box !== null;
    }
    const [horizontal, vertical] = this._blurMaterials(this.plan.samples, coverage, groups);

    _rendererState = RendererUtils.resetRendererState(renderer, _rendererState);
    renderer.autoClear = false;
    _quadMesh.material = horizontal;
    _quadMesh.name = 'Subsurface blur [ horizontal ]';
    renderer.setRenderTarget(groups > 1 ? this._groupTarget : this._horizontalTarget);
    _quadMesh.render(renderer); // renders the scene pass first (its texture is this material's input)
    _quadMesh.material = vertical;
    _quadMesh.name = 'Subsurface blur [ vertical ]';
    renderer.setRenderTarget(this._scatteredTarget);
    _quadMesh.render(renderer);
    RendererUtils.restoreRendererState(renderer, _rendererState);
  }

  /** @param {import('three/webgpu').NodeBuilder} builder */
  setup(builder) {
    // three runs a node's inputs' updateBefore first (in the order they were built), so the
    // scene pass would draw before this node's updateBefore: the light stage is built ahead of it.
    this._lightStage.build(builder);
    // WebGPU multisamples no 32-bit float format (RGBA32Float): an MSAA scene pass keeps the
    // surface in half float there (depth steps of 1/2048 of the distance; WebGL 2 keeps 32 bits).
    if (builder.renderer.backend.isWebGPUBackend && this.scenePass.renderTarget.samples > 0) {
      this.scenePass.getTexture(ATTACHMENT_NAMES.SURFACE).type = HalfFloatType;
    }
    return composeNode({
      colour: this.scenePass.getTextureNode(ATTACHMENT_NAMES.COLOR),
      unscattered: this.scenePass.getTextureNode(ATTACHMENT_NAMES.DIFFUSE),
      scattered: this._scatteredNode,
      surface: this.scenePass.getTextureNode(ATTACHMENT_NAMES.SURFACE),
      view: this._uniforms.debugView,
      depthRange: this._uniforms.debugDepthRange,
      thicknessRangeMm: this._uniforms.debugThicknessRangeMm,
      share: this._uniforms.scatteredShare,
      box: this._uniforms.subsurfaceBox,
      lightShown: this._uniforms.lightShown,
    });
  }

  /**
   * Frees the node's targets, tables and materials (the scene pass is the caller's); the
   * subsurface materials it drew lose their transmittance (they are rebuilt without it).
   */
  dispose() {
    this._lightStage.dispose();
    this._horizontalTarget.dispose();
    this._scatteredTarget.dispose();
    this._freeGroupTarget();
    this._groupFractions.dispose();
    this.footprintTable.dispose();
    this.profileLookup.dispose();
    for (const groups of [...this._materials.keys()]) this._freeMaterials(groups);
    super.dispose();
  }
}

/**
 * The subsurface scattering node over a scene pass (see the file's header).
 * @param {import('three/webgpu').PassNode} scenePass
 * @param {import('../options.js').SubsurfaceScatteringNodeOptions} [options]
 */
export const subsurfaceScattering = (scenePass, options) => new SubsurfaceScatteringNode(scenePass, options);
