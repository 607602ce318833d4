// Stage 1 for the WebGPU node, and what stage 2's materials read of it: each frame, before the
// scene pass draws, a light depth map per light (when the light works, shines and reaches a
// transmitting material from behind, as the WebGL orchestrator decides: src/SubsurfaceScattering.js
// steps 0 and 1; `light: 'castShadow'` finds the scene's casters first), then each subsurface
// material's transmittance uniforms, one set per light, written by the WebGL hook's writer
// (writeTransmittedLight). It is a node because three runs a node's inputs' updateBefore first,
// in the order they were built: SubsurfaceScatteringNode builds this one ahead of the scene
// pass's textures, so the maps and the uniforms are this frame's when the scene pass draws
// (without it, transmittance came one frame late, none on the first frame).
import { Node, NodeUpdateType } from 'three/webgpu';
import { FrameChecks } from '../../support/frameChecks.js';
import { MATERIAL_OUTPUTS, materialOutputOf } from '../../4-compose/debugViews.js';
import { CAST_SHADOW, MAX_LIGHTS, lightsOf } from '../../options.js';
import {
  isShining, lightReachesFromBehind, transmittanceSettings, writeTransmittedLight,
} from '../../2-scene-split/transmittanceModel.js';
import { isSubsurfaceNodeMaterial, subsurfaceMaterialsOf } from '../2-scene-split/subsurfaceNodeMaterial.js';
import { LightDepthNodeTarget } from './LightDepthNodeTarget.js';

const transmits = (material) => material.isSubsurfaceNodeMaterial === true && material.transmittance;

export class LightStageNode extends Node {
  static get type() {
    return 'SubsurfaceLightStageNode';
  }

  /**
   * @param {import('../SubsurfaceScatteringNode.js').SubsurfaceScatteringNode} owner whose scene
   *   pass, `light`, profile, scale, debug view and `transmittance` this stage reads each frame
   * @param {number} size the light depth maps', pixels
   */
  constructor(owner, size) {
    super('void');
    this.owner = owner;
    /**
     * A map per light (up to MAX_LIGHTS), kept where there was one at its place (its materials
     * read it on); the first is kept without a light too, unread.
     * @type {LightDepthNodeTarget[]}
     */
    this.lightDepths = [];
    /** How many of `lightDepths` this frame's lights use. */
    this.count = 0;
    /** The lights' checks (FrameChecks: finite, in the scene, a frustum), warned about once each. */
    this.checks = new FrameChecks('SubsurfaceScatteringNode');
    /** The subsurface materials handed transmittance uniforms (taken back on dispose). */
    this._materials = new Set();
    this.setLights(lightsOf(owner.light), size);
    this.updateBeforeType = NodeUpdateType.FRAME;
  }

  /**
   * Stage 1 and the materials' uniforms, once a frame before the scene pass (updateBeforeType FRAME).
   * @param {import('three/webgpu').NodeFrame} frame
   * @returns {undefined}
   */
  updateBefore({ renderer }) {
    const { scene, camera } = this.owner.scenePass;
    // The matrices as the scene pass's render will see them (three updates them the same way),
    // then what the frame covers (src/frameMeshes.js), for the lights' maps and the node's plan.
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    const frame = this.owner.frame.update(scene, camera, isSubsurfaceNodeMaterial);
    const checks = this.checks.begin();
    // 'castShadow': the scene's lights that cast shadows now, more than MAX_LIGHTS said once.
    if (this.owner.light === CAST_SHADOW) this._castShadowLights(scene, checks);
    const maps = this.lightDepths.slice(0, this.count);
    if (maps.length === 0) checks.withoutLight(this.owner._transmittanceAsked, this.owner.debugView);
    // The lights' checks fit their maps to the transmitting meshes on the screen.
    const works = maps.map((lightDepth) => checks.light(lightDepth, frame, this.owner.transmittance, transmits));
    checks.end();
    maps.forEach((lightDepth, i) => this._renderLightDepth(lightDepth, works[i], renderer, frame, camera));
    // Without a light (any more) the materials keep a set for the map kept, sending nothing.
    if (this.lightDepths.length > 0) this._writeUniforms(maps, subsurfaceMaterialsOf(frame.onScreen), scene, camera);
  }

  /**
   * Follows `lights` from the next frame (none: the maps and the materials' uniforms stay, sending
   * nothing): a map for each (up to MAX_LIGHTS), kept where there was one at its place and
   * retargeted to its light, the ones beyond freed (the materials are rebuilt for the new number
   * on the next frame). Built once with the node, this stage needs no rebuild of the node's graph.
   * @param {readonly (import('three').SpotLight|import('three').DirectionalLight|import('three').PointLight)[]} lights
   * @param {number} [size] the maps', pixels (default: the owner's lightDepthSize)
   */
  setLights(lights, size = this.owner.lightDepthSize) {
    const maps = this.lightDepths;
    const used = lights.slice(0, MAX_LIGHTS);
    used.forEach((light, i) => {
      if (!maps[i]) maps[i] = new LightDepthNodeTarget(light, { size });
      else if (maps[i].light !== light) maps[i].setLight(light);
    });
    for (const extra of maps.splice(Math.max(used.length, 1))) extra.dispose(); // the first stays, for the next light
    maps[0]?.invalidate(); // transmittance from it comes again once it is drawn for its light
    this.count = used.length;
    this.owner._uniforms.lightShown.value = this.count > 0 ? 1 : 0;
  }

  /** The maps of the scene's shadow-casting lights (`light` 'castShadow'), this frame's. */
  _castShadowLights(scene, checks) {
    const lights = lightsOf(CAST_SHADOW, scene);
    if (lights.length > MAX_LIGHTS) {
      checks.problem('castShadowLights', `${lights.length} lights cast shadows: transmittance comes from the first ${MAX_LIGHTS} in the scene's order (list the ones you want in \`light\`)`);
    }
    const now = this.lightDepths.slice(0, this.count).map((lightDepth) => lightDepth.light);
    const next = lights.slice(0, MAX_LIGHTS);
    if (now.length !== next.length || now.some((light, i) => light !== next[i])) this.setLights(next);
  }

  /** A light's map, or marked out of date (nothing is transmitted from it) when it would go unread or the light does not work. */
  _renderLightDepth(lightDepth, works, renderer, frame, camera) {
    const { scene } = frame;
    const read = materialOutputOf(this.owner.debugView) === 'thickness' || lightReachesFromBehind(lightDepth.light, frame.onScreen, camera, transmits);
    if (works && isShining(lightDepth.light, scene, camera) && read) lightDepth.render(renderer, scene, frame);
    else lightDepth.invalidate();
  }

  /**
   * Each subsurface material's transmittance uniforms for this frame: a set per map kept, written
   * for the lights of `maps` (this frame's; none: nothing is sent).
   */
  _writeUniforms(maps, materials, scene, camera) {
    const { owner } = this;
    const lookup = owner.profileLookup;
    // A light's debug view cannot stay without a light.
    const output = MATERIAL_OUTPUTS.indexOf(maps.length > 0 ? materialOutputOf(owner.debugView) : 'diffuse');
    const lightDepthMaps = this.lightDepths.map((lightDepth) => lightDepth.texture);
    for (const material of materials) {
      const u = material.useTransmittance({ lightDepthMaps, profileLookup: lookup.texture });
      this._materials.add(material);
      u.sssDebugOutput.value = output;
      u.sssTransmits.value = false;
      for (const light of u.lights) light.sssTransmits.value = false;
      if (!owner.transmittance || !material.transmittance) continue;
      const { widthMm, translucency, shrinkMm } = material;
      maps.forEach((lightDepth, i) => {
        const settings = transmittanceSettings({ lightDepth, lookup, worldUnitInMm: owner.worldUnitInMm, widthMm, translucency, shrinkMm }, LightDepthNodeTarget);
        writeTransmittedLight(u.lights[i], settings, scene, camera);
      });
      u.sssTransmits.value = u.lights.some((light) => light.sssTransmits.value === true);
    }
  }

  /** Frees the maps; the materials they handed uniforms to are rebuilt without transmittance (they read the maps). */
  dispose() {
    for (const material of this._materials) {
      material.transmittanceNodes = null;
      material.needsUpdate = true;
    }
    this._materials.clear();
    for (const lightDepth of this.lightDepths) lightDepth.dispose();
    this.lightDepths = [];
    super.dispose();
  }
}
