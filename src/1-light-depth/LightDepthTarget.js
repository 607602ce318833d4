// Stage 1: linear depth seen from the light, for transmittance (Jimenez et al. 2010). Unlike a
// shadow map it stores world units along the light's axis, so a thickness is a plain difference
// of two depths; beside it the entry cosine |N·L| (shaders/1-light-depth/lightDepth.frag.glsl).
import {
  DoubleSide, FloatType, Matrix3, NearestFilter, RGFormat, ShaderMaterial, WebGLRenderTarget,
} from 'three';
import vertexShader from '../../shaders/1-light-depth/lightDepth.vert.glsl?raw';
import fragmentShader from '../../shaders/1-light-depth/lightDepth.frag.glsl?raw';
import { assertFloatRenderTargets, describe } from '../support/rendererSupport.js';
import { userProgramKeyOf, userShaderHook } from '../support/userHooks.js';
import { preservingRendererState } from '../support/rendererState.js';
import { LightDepthView, boundsNoVolume } from './LightDepthView.js';
import { holdingLevels, isDrawable, renderingOnly } from '../frameMeshes.js';
import { nameClass } from '../support/className.js';
import { compileSceneInto } from '../support/compilePrograms.js';

/** The drawable objects of `scene` visible with their ancestors (a LightDepthTarget used alone). */
function visibleObjects(scene) {
  const objects = [];
  scene.traverseVisible((object) => { if (isDrawable(object)) objects.push(object); });
  return objects;
}

/** Drawn in place of what the light pass leaves out: three culls a material with visible false. */
const HIDDEN = new ShaderMaterial({ name: 'LightDepthHidden', visible: false });

function uvTransform(texture, into) {
  if (texture.matrixAutoUpdate === true) texture.updateMatrix();
  return into.copy(texture.matrix);
}

/**
 * A uniform the user's hook made for the light's depth program, read from and written to the one of
 * that name in the material's own program where it has one (three keeps the last program's uniforms
 * per material): three's examples keep the shader a hook saw and animate its uniforms, and the
 * depth program and the material's, compiled in either order, then move alike.
 */
function sharedUniform(renderer, material, name, own) {
  const main = () => {
    const uniform = renderer.properties.get(material).uniforms?.[name];
    return uniform && uniform !== shared ? uniform : own;
  };
  const shared = {
    get value() { return main().value; },
    set value(value) { main().value = value; },
  };
  return shared;
}

/**
 * The onBeforeCompile of a depth material for `material`: the user's hook on the light's depth
 * shader, which has three's vertex chunks (shaders/1-light-depth/lightDepth.vert.glsl), so that the
 * vertices move as the camera sees them. Its fragment edits are for the material's shading and
 * are left out (the depth shader has none of its fragment chunks); the uniforms it makes are
 * shared with the material's own (sharedUniform). A hook that throws on the depth shader leaves
 * the mesh drawn unmoved, said once (`failed`).
 */
function runningUserHook(material, hook, ownUniforms, failed) {
  return function (shader, renderer) {
    const { fragmentShader, vertexShader } = shader;
    try {
      hook.call(material, shader, renderer);
    } catch (error) {
      Object.assign(shader, { fragmentShader, vertexShader });
      failed(`its onBeforeCompile throws on the light's depth shader (${error?.message ?? error}), so the light sees its mesh unmoved by it`);
      return;
    }
    shader.fragmentShader = fragmentShader;
    for (const name of Object.keys(shader.uniforms)) {
      if (!ownUniforms.has(name)) shader.uniforms[name] = sharedUniform(renderer, material, name, shader.uniforms[name]);
    }
  };
}

/**
 * The WebGL light depth map: r linear depth, world units (0: no surface), g the entry cosine; a
 * point light's six faces side by side (LightDepthView.pointFace) where it is not aimed.
 */
export class LightDepthTarget extends LightDepthView {
  /**
   * @param {import('three').SpotLight | import('three').DirectionalLight} light
   * @param {object} [options]
   * @param {number} [options.size=1024] resolution of the square target, pixels (16..8192)
   * @param {number} [options.near] near plane, world units (default: the light's shadow camera)
   * @param {number} [options.far] far plane, world units (default: the light's shadow camera)
   */
  constructor(light, options = {}) {
    super('LightDepthTarget', light, options);
    this.material = new ShaderMaterial({
      name: 'LightDepthMaterial',
      vertexShader,
      fragmentShader,
      side: DoubleSide, // thin open shells still record their nearest surface
      clipping: true, // the renderer's clipping planes cut what the light sees as they cut the view
    });
    this.renderTarget = new WebGLRenderTarget(1, 1, {
      type: FloatType,
      format: RGFormat,
      minFilter: NearestFilter, // RG32F is not filterable everywhere
      magFilter: NearestFilter,
      depthBuffer: true,
    });
    this.renderTarget.texture.name = 'LightDepthTarget.texture';
    this.setSize(this.size);
  }

  /**
   * What `object` is drawn with from the light (HIDDEN: what lightSees leaves out, points, lines).
   * @param {import('three').Object3D} object
   * @returns {ShaderMaterial | ShaderMaterial[] | null} null: not a drawable mesh, leave it
   */
  depthMaterialOf(object) {
    if (boundsNoVolume(object)) return HIDDEN;
    if (!object.isMesh) return null;
    const of = (material) => this.depthMaterialFor(material) ?? HIDDEN;
    return Array.isArray(object.material) ? object.material.map(of) : of(object.material);
  }

  /** A material whose own onBeforeCompile may move its vertices: the light runs it too (updateShapedMaterial). */
  hasOwnVertexStage(material) {
    return userShaderHook(material) !== null;
  }

  /** For a cut-out, clipped or hooked material (LightDepthView._shapedMaterial). */
  createShapedMaterial(material) {
    const shaped = this.material.clone();
    shaped.name = `LightDepthMaterial(${material.name || material.type})`;
    Object.assign(shaped.uniforms, {
      map: { value: null }, mapTransform: { value: new Matrix3() },
      alphaMap: { value: null }, alphaMapTransform: { value: new Matrix3() },
      alphaTest: { value: 0 }, opacity: { value: 1 },
    });
    shaped.userData.ownUniforms = new Set(Object.keys(shaped.uniforms));
    return shaped;
  }

  /**
   * three derives USE_MAP, USE_ALPHAMAP, USE_ALPHATEST from the fields but leaves a ShaderMaterial's
   * uniforms to us. A user's hook is taken again where the material changed since (three recompiles
   * a material on needsUpdate, its version: so does its depth material), keyed as three keys it.
   */
  updateShapedMaterial(shaped, material) {
    const u = shaped.uniforms;
    u.map.value = shaped.map;
    u.alphaMap.value = shaped.alphaMap;
    if (shaped.map) uvTransform(shaped.map, u.mapTransform.value);
    if (shaped.alphaMap) uvTransform(shaped.alphaMap, u.alphaMapTransform.value);
    u.alphaTest.value = shaped.alphaTest;
    u.opacity.value = material.opacity;
    const { userData } = shaped;
    if (userData.version === material.version && userData.hook === userShaderHook(material)) return;
    userData.version = material.version;
    userData.hook = userShaderHook(material);
    const key = userData.hook && !userData.failed ? userProgramKeyOf(material) : '';
    shaped.onBeforeCompile = userData.hook && !userData.failed
      ? runningUserHook(material, userData.hook, userData.ownUniforms, (reason) => this._hookFailed(material, shaped, reason))
      : ShaderMaterial.prototype.onBeforeCompile;
    shaped.customProgramCacheKey = () => key;
    shaped.needsUpdate = true;
  }

  /** The light's depth program could not run `material`'s hook: drawn unmoved from the next compile on, said once. */
  _hookFailed(material, shaped, reason) {
    shaped.userData.failed = true;
    shaped.userData.version = undefined; // taken again without the hook
    this.shapeProblems.set(`lightShape:${material.uuid}`, `${material.name ? `material "${material.name}"` : `an unnamed ${material.type}`}: ${reason}`);
  }

  /** A point light's six faces, each into its viewport of the target (LightDepthView.pointFace). */
  _renderFaces(renderer, scene) {
    const { renderTarget, camera } = this;
    camera.matrixWorldAutoUpdate = false; // the faces' turns are set by hand
    try {
      for (let k = 0; k < 6; k++) {
        renderTarget.viewport.set(...this.pointFace(k));
        renderer.setRenderTarget(renderTarget); // three takes the viewport when the target is set
        renderer.render(scene, camera);
      }
    } finally {
      camera.matrixWorldAutoUpdate = true;
      renderTarget.viewport.set(0, 0, renderTarget.width, renderTarget.height);
    }
  }

  /**
   * Renders `scene` from the light; the meshes' materials and the renderer's state are put back.
   * With the frame's lists (the pipeline's FrameMeshes, after fit) it draws what the camera's frame
   * holds (the LODs at the camera's levels) on the light's layers, and swaps depth materials in only
   * for what fit found in the light's view (`inView`); alone, for every visible object in its view.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Scene} scene
   * @param {import('../frameMeshes.js').FrameMeshes|null} [frame]
   */
  render(renderer, scene, frame = null) {
    assertFloatRenderTargets(renderer, 'LightDepthTarget.render');
    if (!scene || scene.isObject3D !== true) {
      throw new TypeError(`LightDepthTarget.render: scene must be a THREE.Scene, got ${describe(scene)}`);
    }
    this.updateCamera();
    const { camera } = this;
    camera.layers.mask = this.layers.mask;
    /** @type {[import('three').Object3D, any][]} */
    const swapped = [];
    // A user's static shadows (autoUpdate false, needsUpdate true) are for the scene's own draw:
    // three would draw them here, with the depth materials swapped in, and spend the flag.
    const shadowsNeedUpdate = renderer.shadowMap.needsUpdate;
    preservingRendererState(renderer, scene, () => {
      try {
        // What three culls from the light's view keeps its material: it is not drawn.
        const drawn = frame ? this.inView : this.inViewOf(this._candidates(scene));
        this._wearDepthMaterials(drawn, swapped);
        scene.overrideMaterial = null;
        scene.background = null;
        renderer.shadowMap.autoUpdate = false;
        renderer.shadowMap.needsUpdate = false;
        renderer.setRenderTarget(this.renderTarget);
        renderer.setClearColor(0x000000, 0); // 0 = no surface
        renderer.autoClear = false;
        renderer.clear(true, true, false);
        // Three visits what the light sees alone (with the frame's lists), the LODs held at the
        // camera's levels; the frame's lights too, though the depth material reads none: three
        // keys its light state by them, and a state without them would recompile nothing but make
        // every material check its program again on the next render.
        const render = () => (this.isCube ? this._renderFaces(renderer, scene) : renderer.render(scene, camera));
        holdingLevels(frame ? frame.lods : [], () => (frame ? renderingOnly(scene, [...frame.lights, ...drawn], render) : render()));
        this.valid = true;
      } finally {
        for (const [object, material] of swapped) object.material = material;
        renderer.shadowMap.needsUpdate = shadowsNeedUpdate;
      }
    });
  }

  /**
   * Compiles the programs render() draws `scene` with (each object's depth material, for every
   * visible object on the light's layers: whichever the light's view holds when it draws), through
   * three's renderer.compileAsync, in parallel where KHR_parallel_shader_compile exists.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').Scene} scene
   * @returns {Promise<void>} resolved once they are ready to draw with
   */
  compileAsync(renderer, scene) {
    this.camera.layers.mask = this.layers.mask;
    const swapped = [];
    try {
      this._wearDepthMaterials(this._candidates(scene), swapped);
      return compileSceneInto(renderer, scene, this.camera, this.renderTarget);
    } finally {
      for (const [object, material] of swapped) object.material = material;
    }
  }

  /** The visible drawable objects of `scene` on the light's layers (its view decides which it draws). */
  _candidates(scene) {
    return visibleObjects(scene).filter((object) => object.layers.test(this.camera.layers));
  }

  /**
   * Gives each of `objects` its depth material, listing [object, its material] in `swapped` for the
   * caller to put back. Per mesh, not scene.overrideMaterial, which would draw a leaf card's
   * cut-away corners and a glass pane as solid (three's shadow maps do the same).
   */
  _wearDepthMaterials(objects, swapped) {
    for (const object of objects) {
      const depthMaterial = this.depthMaterialOf(object);
      if (depthMaterial === null) continue;
      swapped.push([object, object.material]);
      object.material = depthMaterial;
    }
  }
}

nameClass(LightDepthTarget, 'LightDepthTarget'); // its name in messages, minified or not
