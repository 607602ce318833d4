// Stage 1 for the WebGPU node, and what stage 2's materials read of it: each frame, before the
// scene pass draws, the light depth map (when the light works, shines and reaches a transmitting
// material from behind, as the WebGL orchestrator decides: src/SubsurfaceScattering.js step 1),
// then each subsurface material's transmittance uniforms, written by the WebGL hook's writer
// (writeTransmittedLight). It is a node because three runs a node's inputs' updateBefore first,
// in the order they were built: SubsurfaceScatteringNode builds this one ahead of the scene
// pass's textures, so the map and the uniforms are this frame's when the scene pass draws
// (without it, transmittance came one frame late, none on the first frame).
import { Node, NodeUpdateType } from 'three/webgpu';
import { FrameChecks } from '../../support/frameChecks.js';
import { MATERIAL_OUTPUTS, materialOutputOf } from '../../4-compose/debugViews.js';
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
   *   pass, profile, scale, debug view and `transmittance` this stage reads each frame
   * @param {import('three').SpotLight|import('three').DirectionalLight|null} light
   * @param {number} size the light depth map's, pixels
   */
  constructor(owner, light, size) {
    super('void');
    this.owner = owner;
    /** The map, made with the first light (kept from then on: the materials read its texture). @type {LightDepthNodeTarget|null} */
    this.lightDepth = light === null ? null : new LightDepthNodeTarget(light, { size });
    /** The light's checks (FrameChecks: finite, in the scene, a frustum), warned about once each. */
    this.checks = new FrameChecks('SubsurfaceScatteringNode');
    /** The subsurface materials handed transmittance uniforms (taken back on dispose). */
    this._materials = new Set();
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
    // then what the frame covers (src/frameMeshes.js), for the light's map and the node's plan.
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    const frame = this.owner.frame.update(scene, camera, isSubsurfaceNodeMaterial);
    if (this.owner.light === null) { // none (any more): the materials handed uniforms send nothing
      this.checks.begin().withoutLight(this.owner._transmittanceAsked, this.owner.debugView).end();
      for (const material of this._materials) {
        if (!material.transmittanceNodes) continue;
        material.transmittanceNodes.sssTransmits.value = false;
        material.transmittanceNodes.sssDebugOutput.value = MATERIAL_OUTPUTS.indexOf('diffuse'); // a light's view cannot stay without one
      }
      return;
    }
    this._renderLightDepth(renderer, frame, camera);
    this._writeUniforms(subsurfaceMaterialsOf(frame.onScreen), scene, camera);
  }

  /**
   * Follows `light` from the next frame (null: none; the map and the materials' uniforms stay,
   * sending nothing). Built once with the node, this stage needs no rebuild of the node's graph.
   * @param {import('three').SpotLight|import('three').DirectionalLight|null} light
   */
  setLight(light) {
    if (light === null) this.lightDepth?.invalidate();
    else if (this.lightDepth) this.lightDepth.setLight(light);
    else this.lightDepth = new LightDepthNodeTarget(light, { size: this.owner.lightDepthSize });
  }

  /** The map, or marked out of date (nothing is transmitted from it) when it would go unread or the light does not work. */
  _renderLightDepth(renderer, frame, camera) {
    const { lightDepth, owner } = this;
    const { scene } = frame;
    const checks = this.checks.begin();
    const works = checks.light(lightDepth, frame, owner.transmittance, transmits);
    checks.end();
    const read = materialOutputOf(owner.debugView) === 'thickness' || lightReachesFromBehind(lightDepth.light, frame.onScreen, camera, transmits);
    if (works && isShining(lightDepth.light, scene, camera) && read) lightDepth.render(renderer, scene, frame);
    else lightDepth.invalidate();
  }

  /** Each subsurface material's transmittance uniforms for this frame. */
  _writeUniforms(materials, scene, camera) {
    const { lightDepth, owner } = this;
    const lookup = owner.profileLookup;
    const output = MATERIAL_OUTPUTS.indexOf(materialOutputOf(owner.debugView));
    for (const material of materials) {
      const u = material.useTransmittance({ lightDepthMap: lightDepth.texture, profileLookup: lookup.texture });
      this._materials.add(material);
      u.sssDebugOutput.value = output;
      u.sssTransmits.value = false;
      if (!owner.transmittance || !material.transmittance) continue;
      const { widthMm, translucency, shrinkMm } = material;
      writeTransmittedLight(u, transmittanceSettings({ lightDepth, lookup, worldUnitInMm: owner.worldUnitInMm, widthMm, translucency, shrinkMm }, LightDepthNodeTarget), scene, camera);
    }
  }

  /** Frees the map; the materials it handed uniforms to are rebuilt without transmittance (they read its map). */
  dispose() {
    for (const material of this._materials) {
      material.transmittanceNodes = null;
      material.needsUpdate = true;
    }
    this._materials.clear();
    this.lightDepth?.dispose();
    super.dispose();
  }
}
