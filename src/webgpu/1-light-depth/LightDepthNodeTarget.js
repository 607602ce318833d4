// Stage 1 for WebGPURenderer: linear depth seen from the light, for transmittance, as the WebGL
// path's LightDepthTarget (src/1-light-depth/LightDepthTarget.js) stores it: distance along the
// light's view axis in world units, single-channel float, 0 = no surface. The camera and what the
// light sees are LightDepthView's, shared with it; the depth material is a node material, drawn in
// place of each object's through a render object function (as three's shadow maps do). Cut-outs
// (alphaTest) are drawn whole here: the WebGL path keeps their shape, this one does not yet.
import { NodeMaterial, RenderTarget, RendererUtils } from 'three/webgpu';
import { DoubleSide, FloatType, NearestFilter, RedFormat } from 'three';
import { positionView, vec4 } from 'three/tsl';
import { LightDepthView, boundsNoVolume, lightSees } from '../../1-light-depth/LightDepthView.js';

let _state;

/** Renders the scene from a SpotLight or DirectionalLight into linear light depth (see the file's header). */
export class LightDepthNodeTarget extends LightDepthView {
  /**
   * @param {import('three').SpotLight | import('three').DirectionalLight} light
   * @param {{ size?: number, near?: number, far?: number }} [options] see LightDepthView
   */
  constructor(light, options = {}) {
    super('LightDepthNodeTarget', light, options);
    this.material = new NodeMaterial();
    this.material.name = 'LightDepthNodeMaterial';
    this.material.side = DoubleSide; // thin open shells still record their nearest surface
    this.material.fog = false; // the scene's fog would blend the depths towards its colour
    // Distance along the light's view axis: linear, unlike the depth buffer (Jimenez et al. 2010).
    this.material.fragmentNode = vec4(positionView.z.negate(), 0, 0, 1);
    this.renderTarget = new RenderTarget(1, 1, {
      type: FloatType, format: RedFormat, minFilter: NearestFilter, magFilter: NearestFilter, depthBuffer: true,
    });
    this.renderTarget.texture.name = 'LightDepthNodeTarget.texture';
    this.setSize(this.size);
  }

  /**
   * Renders `scene` from the light; the renderer's state and the scene's background, environment
   * and override are put back after (also on an exception).
   * @param {import('three/webgpu').Renderer} renderer
   * @param {import('three').Scene} scene
   */
  render(renderer, scene) {
    this.updateCamera();
    _state = RendererUtils.resetRendererAndSceneState(renderer, scene, _state);
    const { material } = this;
    try {
      renderer.setRenderObjectFunction((object, s, camera, geometry, own, group, lightsNode, clippingContext, passId) => {
        if (boundsNoVolume(object) || !lightSees(own)) return;
        renderer.renderObject(object, s, camera, geometry, material, group, lightsNode, clippingContext, passId);
      });
      renderer.setRenderTarget(this.renderTarget);
      renderer.setClearColor(0x000000, 0); // 0 = no surface
      renderer.render(scene, this.camera);
      this.valid = true;
    } finally {
      RendererUtils.restoreRendererAndSceneState(renderer, scene, _state);
    }
  }

  /** Frees the target and the depth material. */
  dispose() {
    this.renderTarget.dispose();
    this.material.dispose();
  }
}
