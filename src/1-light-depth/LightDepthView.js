// Stage 1, renderer-free: the light's camera, its frustum checks and which materials it sees,
// shared by LightDepthTarget and the WebGPU LightDepthNodeTarget (src/webgpu/1-light-depth/),
// which bring the target, the depth material and the render.
import { OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { checkInteger, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { LIGHT_DEPTH_SIZES, PIPELINE_DEFAULTS } from '../options.js';

const _target = new Vector3();

/**
 * Whether a material's own shape matters from the light (a cut-out or clipping planes); other
 * materials share one depth material.
 * @param {import('three').Material} material
 */
export function hasOwnShape(material) {
  const cutOut = (material.alphaTest > 0 || material.alphaToCoverage === true) && Boolean(material.map || material.alphaMap);
  const clipped = Array.isArray(material.clippingPlanes) && material.clippingPlanes.length > 0;
  return cutOut || clipped;
}

/**
 * Whether the light pass draws a surface of `material`: not transparent or transmissive ones (glass
 * between the light and the skin would read as tissue and hide the glow), nor invisible ones.
 * @param {import('three').Material|undefined|null} material
 */
export function lightSees(material) {
  return Boolean(material) && material.visible !== false && material.transparent !== true && !(material.transmission > 0);
}

/** Left out whatever the material: they bound no volume. */
export const boundsNoVolume = (object) => object.isPoints === true || object.isLine === true || object.isSprite === true;

/**
 * The light's view of a SpotLight (perspective) or DirectionalLight (orthographic). The subclass
 * makes `renderTarget` and `material`, calls setSize(this.size), and implements
 * createShapedMaterial (and updateShapedMaterial where uniforms need the material's values).
 */
export class LightDepthView {
  /**
   * @param {string} who the class named in errors
   * @param {import('three').SpotLight | import('three').DirectionalLight} light
   * @param {{ size?: number, near?: number, far?: number }} [options] size: of the square target,
   *   pixels (16..8192, default 1024); near and far: world units (default: the light's shadow camera)
   */
  constructor(who, light, options = {}) {
    if (!light || !(light.isSpotLight || light.isDirectionalLight)) {
      throw new TypeError(`${who}: light must be a THREE.SpotLight or THREE.DirectionalLight, got ${describe(light)}`);
    }
    const { size = PIPELINE_DEFAULTS.lightDepthSize, near, far } = checkOptions(`${who} options`, options, ['size', 'near', 'far']);
    if (near !== undefined) checkNumber('near', near, { min: 0, minExclusive: true, unit: 'world units' });
    if (far !== undefined) checkNumber('far', far, { min: near ?? 0, minExclusive: true, unit: 'world units' });
    this.light = light;
    this.near = near;
    this.far = far;
    this.camera = light.isSpotLight ? new PerspectiveCamera() : new OrthographicCamera();
    /** Pixels: checked by the subclass's setSize(this.size). */
    this.size = size;
    /** Whether the map holds the scene as last rendered; no transmittance from one that does not. */
    this.valid = false;
    /** @type {Map<import('three').Material, import('three').Material>} depth materials of cut-out or clipped materials */
    this._shaped = new Map();
    this._onMaterialDispose = (event) => this._forget(event.target);
  }

  /**
   * What a surface of `material` is drawn with from the light; null: left out.
   * @param {import('three').Material|undefined|null} material
   */
  depthMaterialFor(material) {
    if (!lightSees(material)) return null;
    return hasOwnShape(material) ? this._shapedMaterial(material) : this.material;
  }

  /** One per material, its settings read now. */
  _shapedMaterial(material) {
    let shaped = this._shaped.get(material);
    if (!shaped) {
      shaped = this.createShapedMaterial(material);
      this._shaped.set(material, shaped);
      material.addEventListener('dispose', this._onMaterialDispose);
    }
    // alphaToCoverage counts as alphaTest 0.5, as in three's shadow maps.
    const alphaTest = material.alphaToCoverage === true ? 0.5 : material.alphaTest;
    const map = material.map ?? null;
    const alphaMap = material.alphaMap ?? null;
    Object.assign(shaped, {
      map, alphaMap, alphaTest: map || alphaMap ? alphaTest : 0, clippingPlanes: material.clippingPlanes, clipIntersection: material.clipIntersection,
    });
    this.updateShapedMaterial?.(shaped, material);
    return shaped;
  }

  _forget(material) {
    material.removeEventListener('dispose', this._onMaterialDispose);
    this._shaped.get(material)?.dispose();
    this._shaped.delete(material);
  }

  dispose() {
    this.renderTarget.dispose();
    this.material.dispose();
    for (const material of [...this._shaped.keys()]) this._forget(material);
  }

  /** Its pass was skipped this frame: no transmittance until the next render. */
  invalidate() {
    this.valid = false;
  }

  /** The linear light depth, world units (R channel). */
  get texture() {
    return this.renderTarget.texture;
  }

  /** @param {number} size pixels, 16..8192 */
  setSize(size) {
    checkInteger('size', size, LIGHT_DEPTH_SIZES.min, LIGHT_DEPTH_SIZES.max, 'pixels');
    this.size = size;
    this.renderTarget.setSize(size, size);
  }

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
   * Places the light camera and says what makes its frustum unusable, or null.
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
}
