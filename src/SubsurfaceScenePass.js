// Stage 2 (render): draws the scene into the subsurface multi-target:
//   attachment 0 "light"   (half float): specular + emissive of subsurface pixels, full colour elsewhere
//   attachment 1 "diffuse" (half float): diffuse light + transmittance of subsurface pixels, alpha 1
//                                         (the mask, whatever the width); 0 elsewhere
//   attachment 2 "surface" (float RG):   linear view depth (world units), world units per kernel mm; 0 elsewhere
// Chromium refuses draws whose shader lacks an output for an active draw buffer, and three's
// ordinary materials write location 0 only. So the scene is drawn in up to three calls:
//   1. 'depth': opaque ordinary materials into attachment 0 only; subsurface materials write depth
//      only (shadow maps are rendered here, with every caster present);
//   2. 'split': subsurface materials alone into all attachments, depth-tested against call 1, so
//      occluded subsurface fragments never reach attachments 1 and 2, which stay 0 there;
//   3. 'plain': transparent materials, attachment 0 only, over everything. In call 1 they are drawn
//      with colour and depth writes off, only so that they still cast shadows.
import { FloatType, HalfFloatType, NearestFilter, RGFormat, WebGLRenderTarget, Color } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { getSubsurface, SUBSURFACE_TARGET_FLAG } from './subsurfaceMaterial.js';
import { assertFloatRenderTargets, describe } from './rendererSupport.js';

const _clearColor = new Color();
const ZERO = new Float32Array(4);
const NONE = 0; // gl.NONE
const COLOR_ATTACHMENT0 = 0x8ce0;
const ONLY_LIGHT = [COLOR_ATTACHMENT0, NONE, NONE];
const ALL_THREE = [COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2];

/**
 * Renders the scene into the subsurface multi-target (light, diffuse, surface); writes nothing to the
 * composer's buffers. Used by SubsurfaceScattering; usable on its own before your own blur.
 */
export class SubsurfaceScenePass extends Pass {
  /**
   * @param {import('three').Scene} scene
   * @param {import('three').Camera} camera
   * @param {object} [options]
   * @param {number} [options.type=HalfFloatType] HalfFloatType or FloatType for the light targets
   * @param {import('./LightDepthTarget.js').LightDepthTarget|null} [options.lightDepth=null]
   *   rendered first, when given (transmittance)
   */
  constructor(scene, camera, { type = HalfFloatType, lightDepth = null } = {}) {
    super();
    if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScenePass: scene must be a THREE.Scene, got ${describe(scene)}`);
    if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScenePass: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (type !== HalfFloatType && type !== FloatType) {
      throw new RangeError('SubsurfaceScenePass: type must be THREE.HalfFloatType or THREE.FloatType (light needs HDR targets)');
    }
    this.scene = scene;
    this.camera = camera;
    this.lightDepth = lightDepth;
    this.needsSwap = false; // writes its own targets, not the composer's
    /** Meshes with a subsurface material seen in the last render (for the on-screen width estimate). */
    this.subsurfaceMeshes = [];

    const target = new WebGLRenderTarget(1, 1, { count: 3, type, depthBuffer: true });
    const [light, diffuse, surface] = target.textures;
    light.name = 'subsurface.light';
    diffuse.name = 'subsurface.diffuse';
    surface.name = 'subsurface.surface';
    surface.type = FloatType; // depth needs 24 bits of mantissa, not 11
    surface.format = RGFormat;
    surface.minFilter = surface.magFilter = NearestFilter;
    target[SUBSURFACE_TARGET_FLAG] = true;
    target.subsurfacePhase = 'plain';
    this.renderTarget = target;

    this._visibility = new Map();
    this._writes = new Map();
    this._categories = new Map();
  }

  get lightTexture() { return this.renderTarget.textures[0]; }
  get diffuseTexture() { return this.renderTarget.textures[1]; }
  get surfaceTexture() { return this.renderTarget.textures[2]; }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.renderTarget.setSize(width, height);
  }

  /** 'subsurface', 'opaque' or 'transparent' for a material seen in the last render, else undefined. */
  categoryOf(material) {
    return this._categories.get(material);
  }

  /** Sorts the scene's visible materials into 'subsurface', 'opaque' and 'transparent'. */
  _classify() {
    const categories = this._categories;
    categories.clear();
    this.subsurfaceMeshes.length = 0;
    let transparent = 0;
    this.scene.traverseVisible((object) => {
      const material = object.material;
      if (!material) return;
      let hasSubsurface = false;
      for (const m of Array.isArray(material) ? material : [material]) {
        if (!m || !m.visible) continue;
        const category = m.transparent ? 'transparent' : getSubsurface(m) ? 'subsurface' : 'opaque';
        categories.set(m, category);
        if (category === 'transparent') transparent++;
        if (category === 'subsurface') hasSubsurface = true;
      }
      if (hasSubsurface) this.subsurfaceMeshes.push(object);
    });
    return { transparent };
  }

  _show(category) {
    for (const [material, c] of this._categories) {
      material.visible = c === category || category === 'depth';
      // In the depth call transparent materials only cast shadows: they draw nothing.
      const silent = category === 'depth' && c === 'transparent';
      material.colorWrite = silent ? false : this._writes.get(material).colorWrite;
      material.depthWrite = silent ? false : this._writes.get(material).depthWrite;
    }
  }

  render(renderer /* , writeBuffer, readBuffer */) {
    assertFloatRenderTargets(renderer, 'SubsurfaceScenePass');
    const { scene, camera, renderTarget: target } = this;
    const gl = renderer.getContext();
    const { transparent } = this._classify();

    const previous = {
      target: renderer.getRenderTarget(),
      autoClear: renderer.autoClear,
      clearAlpha: renderer.getClearAlpha(),
      clearColor: renderer.getClearColor(_clearColor),
      background: scene.background,
      shadowAutoUpdate: renderer.shadowMap.autoUpdate,
    };
    this._visibility.clear();
    this._writes.clear();
    for (const material of this._categories.keys()) {
      this._visibility.set(material, material.visible);
      this._writes.set(material, { colorWrite: material.colorWrite, depthWrite: material.depthWrite });
    }

    try {
      if (this.lightDepth) this.lightDepth.render(renderer, scene);
      renderer.setRenderTarget(target);
      renderer.autoClear = false;
      renderer.clear(true, true, true); // attachment 0 takes the clear colour, like RenderPass
      gl.clearBufferfv(gl.COLOR, 1, ZERO);
      gl.clearBufferfv(gl.COLOR, 2, ZERO);

      // 1. opaque ordinary materials + subsurface depth; background and shadow maps.
      target.subsurfacePhase = 'depth';
      gl.drawBuffers(ONLY_LIGHT);
      this._show('depth');
      renderer.render(scene, camera);

      scene.background = null; // drawn once; a Color background would clear the targets again
      renderer.shadowMap.autoUpdate = false;

      // 2. subsurface materials into every attachment.
      if (this.subsurfaceMeshes.length > 0) {
        target.subsurfacePhase = 'split';
        gl.drawBuffers(ALL_THREE);
        this._show('subsurface');
        renderer.render(scene, camera);
      }

      // 3. transparent materials over everything, colour only.
      if (transparent > 0) {
        target.subsurfacePhase = 'plain';
        gl.drawBuffers(ONLY_LIGHT);
        this._show('transparent');
        renderer.render(scene, camera);
      }
    } finally {
      // three caches draw buffers per target: leave them as it set them.
      if (renderer.getRenderTarget() === target) {
        gl.drawBuffers(ALL_THREE);
      }
      target.subsurfacePhase = 'plain';
      for (const [material, visible] of this._visibility) material.visible = visible;
      for (const [material, { colorWrite, depthWrite }] of this._writes) Object.assign(material, { colorWrite, depthWrite });
      scene.background = previous.background;
      renderer.shadowMap.autoUpdate = previous.shadowAutoUpdate;
      renderer.autoClear = previous.autoClear;
      renderer.setClearColor(previous.clearColor, previous.clearAlpha);
      renderer.setRenderTarget(previous.target);
    }
  }

  dispose() {
    this.renderTarget.dispose();
    this._visibility.clear();
    this._writes.clear();
    this._categories.clear();
    this.subsurfaceMeshes.length = 0;
  }
}
