// Stage 1: linear depth seen from the light, for transmittance (Jimenez et al. 2010). Unlike a
// shadow map it stores distance along the light's view axis in world units, so the thickness of
// an object is a plain difference of two depths.
import {
  DoubleSide, FloatType, Matrix3, NearestFilter, OrthographicCamera, PerspectiveCamera, RedFormat,
  ShaderMaterial, Vector3, WebGLRenderTarget,
} from 'three';
import vertexShader from '../../shaders/1-light-depth/lightDepth.vert.glsl?raw';
import fragmentShader from '../../shaders/1-light-depth/lightDepth.frag.glsl?raw';
import { checkInteger, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { assertFloatRenderTargets, describe } from '../support/rendererSupport.js';
import { preservingRendererState } from '../support/rendererState.js';

const _target = new Vector3();

/** Drawn in place of what the light pass leaves out: three culls a material with visible false. */
const HIDDEN = new ShaderMaterial({ name: 'LightDepthHidden', visible: false });

/**
 * Whether a material's own shape matters from the light: a cut-out (alphaTest with a map or an
 * alphaMap, or alphaToCoverage, which three's shadow maps also read as alphaTest 0.5) or local
 * clipping planes. Other materials share one depth material.
 * @param {import('three').Material} material
 */
function hasOwnShape(material) {
  const cutOut = (material.alphaTest > 0 || material.alphaToCoverage === true) && Boolean(material.map || material.alphaMap);
  const clipped = Array.isArray(material.clippingPlanes) && material.clippingPlanes.length > 0;
  return cutOut || clipped;
}

/** A texture's uv transform, as three's own materials upload it. */
function uvTransform(texture, into) {
  if (texture.matrixAutoUpdate === true) texture.updateMatrix();
  return into.copy(texture.matrix);
}

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
      clipping: true, // the renderer's clipping planes cut what the light sees as they cut the view
    });
    this.renderTarget = new WebGLRenderTarget(1, 1, {
      type: FloatType,
      format: RedFormat,
      minFilter: NearestFilter, // R32F is not filterable everywhere
      magFilter: NearestFilter,
      depthBuffer: true,
    });
    this.renderTarget.texture.name = 'LightDepthTarget.texture';
    /** @type {Map<import('three').Material, ShaderMaterial>} depth materials of cut-out or clipped materials */
    this._shaped = new Map();
    this._onMaterialDispose = (event) => this._forget(event.target);
    /**
     * Whether the map holds the scene as last rendered: false until the first render and after
     * `invalidate()`; materials send no transmittance from a map that does not.
     */
    this.valid = false;
    this.setSize(size);
  }

  /** Marks the map out of date (its pass was skipped this frame): no transmittance until the next render. */
  invalidate() {
    this.valid = false;
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
   * What `object` is drawn with from the light: the shared depth material, a depth material that
   * keeps its material's cut-out and clipping, or nothing. Left out: transparent and transmissive
   * materials (glass or a veil between the light and the skin would read as tissue and hide the
   * glow behind it; the pipeline draws them after the compose anyway), materials with visible
   * false, and points, lines and sprites (they bound no volume).
   * @param {import('three').Object3D} object
   * @returns {ShaderMaterial | ShaderMaterial[] | null} null: not a drawable mesh, leave it
   */
  depthMaterialOf(object) {
    if (object.isPoints || object.isLine || object.isSprite) return HIDDEN;
    if (!object.isMesh) return null;
    const of = (material) => {
      if (!material || material.visible === false || material.transparent === true || material.transmission > 0) return HIDDEN;
      return hasOwnShape(material) ? this._shapedMaterial(material) : this.material;
    };
    return Array.isArray(object.material) ? object.material.map(of) : of(object.material);
  }

  /** The depth material following `material`'s cut-out and clipping, its uniforms read now. */
  _shapedMaterial(material) {
    let shaped = this._shaped.get(material);
    if (!shaped) {
      shaped = this.material.clone();
      shaped.name = `LightDepthMaterial(${material.name || material.type})`;
      Object.assign(shaped.uniforms, {
        map: { value: null }, mapTransform: { value: new Matrix3() },
        alphaMap: { value: null }, alphaMapTransform: { value: new Matrix3() },
        alphaTest: { value: 0 }, opacity: { value: 1 },
      });
      this._shaped.set(material, shaped);
      material.addEventListener('dispose', this._onMaterialDispose);
    }
    // Three derives USE_MAP, USE_ALPHAMAP, USE_ALPHATEST and their uv channels from these fields,
    // for a ShaderMaterial as for its own; the uniforms it leaves to us.
    const alphaTest = material.alphaToCoverage === true ? 0.5 : material.alphaTest;
    shaped.map = material.map ?? null;
    shaped.alphaMap = material.alphaMap ?? null;
    shaped.alphaTest = shaped.map || shaped.alphaMap ? alphaTest : 0;
    shaped.clippingPlanes = material.clippingPlanes;
    shaped.clipIntersection = material.clipIntersection;
    const u = shaped.uniforms;
    u.map.value = shaped.map;
    u.alphaMap.value = shaped.alphaMap;
    if (shaped.map) uvTransform(shaped.map, u.mapTransform.value);
    if (shaped.alphaMap) uvTransform(shaped.alphaMap, u.alphaMapTransform.value);
    u.alphaTest.value = shaped.alphaTest;
    u.opacity.value = material.opacity;
    return shaped;
  }

  _forget(material) {
    material.removeEventListener('dispose', this._onMaterialDispose);
    this._shaped.get(material)?.dispose();
    this._shaped.delete(material);
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
   * Renders `scene` from the light, each mesh drawn with `depthMaterialOf(mesh)` (its own material
   * is put back after, also on an exception). Restores the renderer's render target, clear
   * colour/alpha, autoClear and the scene's background and overrideMaterial.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Scene} scene
   */
  render(renderer, scene) {
    assertFloatRenderTargets(renderer, 'LightDepthTarget.render');
    if (!scene || scene.isObject3D !== true) {
      throw new TypeError(`LightDepthTarget.render: scene must be a THREE.Scene, got ${describe(scene)}`);
    }
    this.updateCamera();
    /** @type {[import('three').Object3D, any][]} */
    const swapped = [];
    preservingRendererState(renderer, scene, () => {
      try {
        // Per mesh rather than scene.overrideMaterial: an override would draw a leaf card's
        // cut-away corners and a glass pane as solid (three's shadow maps do the same per mesh).
        scene.traverseVisible((object) => {
          const depthMaterial = this.depthMaterialOf(object);
          if (depthMaterial === null) return;
          swapped.push([object, object.material]);
          object.material = depthMaterial;
        });
        scene.overrideMaterial = null;
        scene.background = null;
        renderer.shadowMap.autoUpdate = false; // the light's view needs no shadow maps
        renderer.setRenderTarget(this.renderTarget);
        renderer.setClearColor(0x000000, 0); // 0 = no surface
        renderer.autoClear = false;
        renderer.clear(true, true, false);
        renderer.render(scene, this.camera);
        this.valid = true;
      } finally {
        for (const [object, material] of swapped) object.material = material;
      }
    });
  }

  /** Frees the target and the depth materials. */
  dispose() {
    this.renderTarget.dispose();
    this.material.dispose();
    for (const material of [...this._shaped.keys()]) this._forget(material);
  }
}
