// Stage 1 for WebGPURenderer: linear depth seen from the light, for transmittance, as the WebGL
// path's LightDepthTarget (src/1-light-depth/LightDepthTarget.js) stores it: distance along the
// light's view axis in world units, 0 = no surface, and the entry cosine |N·L| beside it, in a
// two-channel float target. The camera and what the light sees (and which materials keep their
// cut-out and clipping) are LightDepthView's, shared with it; the depth materials are node materials, drawn in place of each object's through a
// render object function (as three's shadow maps do).
import { MeshBasicNodeMaterial, NodeMaterial, RenderTarget, RendererUtils } from 'three/webgpu';
import { DoubleSide, FloatType, NearestFilter, RGFormat } from 'three';
import { Fn, abs, dot, float, normalView, positionView, vec3, vec4 } from 'three/tsl';
import { LightDepthView, boundsNoVolume } from '../../1-light-depth/LightDepthView.js';
import { holdingLevels } from '../../frameMeshes.js';
import { nameClass } from '../../support/className.js';

let _state;

/**
 * |N·L| where the mesh has normals; a mesh without them lets the whole light in, as on the WebGL
 * path (there the missing attribute reads 0 and the cosine is 1; three's normalView would take
 * (0, 1, 0) and warn). Decided per geometry when three builds the material for an object.
 */
const entryCosine = (toLight) => Fn((builder) => (builder.geometry?.hasAttribute('normal') === false ? float(1) : abs(dot(normalView, toLight))))();

/**
 * Distance along the light's view axis: linear, unlike the depth buffer (Jimenez et al. 2010); and
 * the entry cosine |N·L| (shaders/1-light-depth/lightDepth.frag.glsl), towards the light along the
 * view axis (directional: orthographic) or to the eye (spot). A texture channel for each.
 */
const lightDepthOutput = (toLight) => vec4(positionView.z.negate(), entryCosine(toLight), 0, 1);
const LIGHT_DEPTH_PERSPECTIVE = /*@__PURE__*/ lightDepthOutput(positionView.negate().normalize()); // a spot light's camera
const LIGHT_DEPTH_ORTHOGRAPHIC = /*@__PURE__*/ lightDepthOutput(vec3(0, 0, 1)); // a directional light's
/** The output for the light's camera. */
const lightDepthOf = (camera) => (camera.isOrthographicCamera ? LIGHT_DEPTH_ORTHOGRAPHIC : LIGHT_DEPTH_PERSPECTIVE);

/**
 * A node material's own vertex position for the light, as three's shadow maps take it
 * (castShadowPositionNode, else positionNode), or null.
 */
const positionNodeOf = (material) => [material.castShadowPositionNode, material.positionNode].find((node) => node?.isNode === true) ?? null;

/** A depth material's settings: both sides (thin open shells still record their nearest surface), no fog (it would blend the depths). */
const asDepthMaterial = (material, name) => Object.assign(material, { name, side: DoubleSide, fog: false });

/**
 * Renders the scene from a SpotLight, DirectionalLight or PointLight into linear light depth (see
 * the file's header); a point light's six faces side by side (LightDepthView.pointFace) where it
 * is not aimed.
 */
export class LightDepthNodeTarget extends LightDepthView {
  /**
   * @param {import('three').SpotLight | import('three').DirectionalLight | import('three').PointLight} light
   * @param {{ size?: number, near?: number, far?: number }} [options] see LightDepthView
   */
  constructor(light, options = {}) {
    super('LightDepthNodeTarget', light, options);
    this.material = asDepthMaterial(new NodeMaterial(), 'LightDepthNodeMaterial');
    this.material.fragmentNode = lightDepthOf(this.camera);
    this.renderTarget = new RenderTarget(1, 1, {
      type: FloatType, format: RGFormat, minFilter: NearestFilter, magFilter: NearestFilter, depthBuffer: true,
    });
    this.renderTarget.texture.name = 'LightDepthNodeTarget.texture';
    this.setSize(this.size);
  }

  /** Another kind of light, another camera: the depth materials' output follows it. */
  onCameraChange() {
    this.material.fragmentNode = lightDepthOf(this.camera);
    this.material.needsUpdate = true;
    for (const material of [...this._shaped.keys()]) this._forget(material); // made again with the new output
  }

  /**
   * Renders `scene` from the light; the renderer's state and the scene's background, environment
   * and override are put back after (also on an exception). With the frame's lists, on the light's
   * layers (fit) with the LODs at the camera's levels.
   * @param {import('three/webgpu').Renderer} renderer
   * @param {import('three').Scene} scene
   * @param {import('../../frameMeshes.js').FrameMeshes|null} [frame]
   */
  render(renderer, scene, frame = null) {
    this.updateCamera();
    this.camera.layers.mask = this.layers.mask;
    _state = RendererUtils.resetRendererAndSceneState(renderer, scene, _state);
    try {
      renderer.setRenderObjectFunction((object, s, camera, geometry, own, group, lightsNode, clippingContext, passId) => {
        const depthMaterial = boundsNoVolume(object) ? null : this.depthMaterialFor(own);
        if (depthMaterial) renderer.renderObject(object, s, camera, geometry, depthMaterial, group, lightsNode, clippingContext, passId);
      });
      renderer.setRenderTarget(this.renderTarget);
      renderer.setClearColor(0x000000, 0); // 0 = no surface
      holdingLevels(frame ? frame.lods : [], () => (this.isCube ? this._renderFaces(renderer, scene) : renderer.render(scene, this.camera)));
      this.valid = true;
    } finally {
      RendererUtils.restoreRendererAndSceneState(renderer, scene, _state);
    }
  }

  /**
   * A point light's six faces, each into its viewport of the target (LightDepthView.pointFace; y
   * counts from the top here, as WebGPURenderer's viewports and TSL's reads both do), after one
   * clear of the whole target: a render pass's clear is the whole target's, not its viewport's.
   */
  _renderFaces(renderer, scene) {
    const { renderTarget, camera } = this;
    renderer.clear();
    renderer.autoClear = false;
    camera.matrixWorldAutoUpdate = false; // the faces' turns are set by hand
    try {
      for (let k = 0; k < 6; k++) {
        renderTarget.viewport.set(...this.pointFace(k));
        renderer.render(scene, camera);
      }
    } finally {
      camera.matrixWorldAutoUpdate = true;
      renderTarget.viewport.set(0, 0, renderTarget.width, renderTarget.height);
    }
  }

  /**
   * A depth material of its own for a cut-out or clipped material (LightDepthView._shapedMaterial
   * gives it the map, alphaMap, alphaTest and clipping planes): a basic node material, whose alpha
   * test three builds from them, with the light depth as its output.
   */
  createShapedMaterial(material) {
    const shaped = asDepthMaterial(new MeshBasicNodeMaterial(), `LightDepthNodeMaterial(${material.name || material.type})`);
    shaped.outputNode = lightDepthOf(this.camera);
    return shaped;
  }

  /** A material that places its vertices with a node of its own (positionNodeOf): the light's depth material takes it. */
  hasOwnVertexStage(material) {
    return positionNodeOf(material) !== null;
  }

  /** The opacity the alpha test compares with the map's alpha; the material's own position node. */
  updateShapedMaterial(shaped, material) {
    shaped.opacity = material.opacity;
    const position = positionNodeOf(material);
    if (shaped.positionNode !== position) {
      shaped.positionNode = position;
      shaped.needsUpdate = true;
    }
  }
}

nameClass(LightDepthNodeTarget, 'LightDepthNodeTarget'); // its name in messages, minified or not
