// Stage 1: linear depth seen from the light, for transmittance (Jimenez et al. 2010). Unlike a
// shadow map it stores distance along the light's view axis in world units, so the thickness of
// an object is a plain difference of two depths.
import {
  DoubleSide, FloatType, NearestFilter, OrthographicCamera, PerspectiveCamera, RedFormat,
  ShaderMaterial, Vector3, WebGLRenderTarget,
} from 'three';
import vertexShader from '../../shaders/1-light-depth/lightDepth.vert.glsl?raw';
import fragmentShader from '../../shaders/1-light-depth/lightDepth.frag.glsl?raw';
import { checkInteger, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { assertFloatRenderTargets, describe } from '../support/rendererSupport.js';
import { preservingRendererState } from '../support/rendererState.js';

const _target = new Vector3();

/**
 * Renders the scene from a SpotLight (perspective) or DirectionalLight (orthographic) into a
 * single-channel float target of linear depth in world units. 0 means "no surface".
 * The camera follows the light (position, target, angle) on every `render`.
 */
export class LightDepthTarget {
  /**
   * @param {import('three').SpotLight | import('three').DirectionalLight} light
   * @param {object} [options]
   * @param {number} [options.size=1024] resolution of the square target, pixels (16..8192)
   * @param {number} [options.near] near plane, world units (default: the light's shadow camera)
   * @param {number} [options.far] far plane, world units (default: the light's shadow camera)
   */
  constructor(light, options = {}) {
    if (!light || !(light.isSpotLight || light.isDirectionalLight)) {
      throw new TypeError(`LightDepthTarget: light must be a THREE.SpotLight or THREE.DirectionalLight, got ${describe(light)}`);
    }
    const { size = 1024, near, far } = checkOptions('LightDepthTarget options', options, ['size', 'near', 'far']);
    if (near !== undefined) checkNumber('near', near, { min: 0, minExclusive: true, unit: 'world units' });
    if (far !== undefined) checkNumber('far', far, { min: near ?? 0, minExclusive: true, unit: 'world units' });
    this.light = light;
    this.near = near;
    this.far = far;
    this.camera = light.isSpotLight ? new PerspectiveCamera() : new OrthographicCamera();
    this.material = new ShaderMaterial({
      name: 'LightDepthMaterial',
      vertexShader,
      fragmentShader,
      side: DoubleSide, // thin open shells still record their nearest surface
    });
    this.renderTarget = new WebGLRenderTarget(1, 1, {
      type: FloatType,
      format: RedFormat,
      minFilter: NearestFilter, // R32F is not filterable everywhere
      magFilter: NearestFilter,
      depthBuffer: true,
    });
    this.renderTarget.texture.name = 'LightDepthTarget.texture';
    this.setSize(size);
  }

  /** The linear light depth, world units (R channel). */
  get texture() {
    return this.renderTarget.texture;
  }

  /** @param {number} size pixels, 16..8192 */
  setSize(size) {
    checkInteger('size', size, 16, 8192, 'pixels');
    this.size = size;
    this.renderTarget.setSize(size, size);
  }

  /** Places the light camera on the light, looking at its target, with its angle or extent. */
  updateCamera() {
    const { light, camera } = this;
    light.updateMatrixWorld();
    light.target.updateMatrixWorld();
    const shadowCamera = light.shadow.camera;
    camera.position.setFromMatrixPosition(light.matrixWorld);
    camera.lookAt(_target.setFromMatrixPosition(light.target.matrixWorld));
    camera.near = this.near ?? shadowCamera.near;
    camera.far = this.far ?? shadowCamera.far;
    if (light.isSpotLight) {
      camera.fov = (2 * light.angle * 180) / Math.PI;
      camera.aspect = 1;
    } else {
      camera.left = shadowCamera.left;
      camera.right = shadowCamera.right;
      camera.top = shadowCamera.top;
      camera.bottom = shadowCamera.bottom;
    }
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld();
  }

  /**
   * Places the light camera (updateCamera) and says what makes its frustum unusable, or null: a
   * SpotLight angle outside (0, π/2], near ≤ 0 for a SpotLight, far ≤ near, a DirectionalLight's
   * shadow camera of zero width or height, or any other projection that is not finite.
   * @returns {string|null}
   */
  frustumProblem() {
    this.updateCamera();
    const { light, camera } = this;
    const { near, far } = camera;
    if (light.isSpotLight && !(light.angle > 0 && light.angle <= Math.PI / 2)) return `light.angle ${light.angle} is not in (0, π/2]`;
    if (light.isSpotLight && !(near > 0)) return `near ${near} is not above 0`;
    if (!(far > near)) return `far ${far} is not beyond near ${near} (light.shadow.camera, or the near and far options)`;
    if (!light.isSpotLight && !(camera.right !== camera.left && camera.top !== camera.bottom)) {
      return `light.shadow.camera spans left ${camera.left} to right ${camera.right}, bottom ${camera.bottom} to top ${camera.top}`;
    }
    if (!camera.projectionMatrix.elements.every(Number.isFinite)) return 'its projection is not finite';
    return null;
  }

  /**
   * Renders `scene` from the light. Restores the renderer's render target, clear colour/alpha,
   * autoClear and the scene's overrideMaterial.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Scene} scene
   */
  render(renderer, scene) {
    assertFloatRenderTargets(renderer, 'LightDepthTarget.render');
    if (!scene || scene.isObject3D !== true) {
      throw new TypeError(`LightDepthTarget.render: scene must be a THREE.Scene, got ${describe(scene)}`);
    }
    this.updateCamera();
    preservingRendererState(renderer, scene, () => {
      scene.overrideMaterial = this.material;
      scene.background = null;
      renderer.shadowMap.autoUpdate = false; // the light's view needs no shadow maps
      renderer.setRenderTarget(this.renderTarget);
      renderer.setClearColor(0x000000, 0); // 0 = no surface
      renderer.autoClear = false;
      renderer.clear(true, true, false);
      renderer.render(scene, this.camera);
    });
  }

  /** Frees the target and the depth material. */
  dispose() {
    this.renderTarget.dispose();
    this.material.dispose();
  }
}
