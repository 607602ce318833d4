// Stage 2 (render): draws the scene into the multi-target (src/2-scene-split/subsurfaceTarget.js:
// colour | diffuse | surface). Chromium refuses draws whose shader lacks an output for an active
// draw buffer, and three's ordinary materials write location 0 only. So the scene is drawn in up
// to three calls, each with its own draw buffers and the materials of one category shown:
//   1. DEPTH: opaque ordinary materials into the colour attachment only; subsurface materials
//      write depth only (shadow maps are rendered here, with every caster present);
//   2. SPLIT: subsurface materials alone into all attachments, depth-tested against call 1, so
//      occluded subsurface fragments never reach the diffuse and surface attachments, which stay 0
//      there: the mask is exact by construction;
//   3. PLAIN: transparent materials, colour attachment only, over everything. In call 1 they are
//      drawn with colour and depth writes off, only so that they still cast shadows.
import { FloatType, HalfFloatType } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { getSubsurface } from './subsurfaceMaterial.js';
import { ATTACHMENTS, DRAW_BUFFERS, DRAW_PHASES, createSubsurfaceTarget, setDrawPhase } from './subsurfaceTarget.js';
import { assertFloatRenderTargets, describe } from '../support/rendererSupport.js';
import { preservingRendererState } from '../support/rendererState.js';

const ZERO = new Float32Array(4);

/** The category each visible material is drawn in. */
const CATEGORIES = Object.freeze({ SUBSURFACE: 'subsurface', OPAQUE: 'opaque', TRANSPARENT: 'transparent' });

/**
 * Renders the scene into the multi-target; writes nothing to the composer's buffers. Used by
 * SubsurfaceScattering; usable on its own before your own blur.
 */
export class SubsurfaceScenePass extends Pass {
  /**
   * @param {import('three').Scene} scene
   * @param {import('three').Camera} camera
   * @param {object} [options]
   * @param {number} [options.type=HalfFloatType] HalfFloatType or FloatType for the colour and diffuse attachments
   * @param {import('../1-light-depth/LightDepthTarget.js').LightDepthTarget|null} [options.lightDepth=null]
   *   rendered first, when given (transmittance, when the pass is used on its own; the orchestrator
   *   renders its light depth itself)
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
    /** The multi-target (see subsurfaceTarget.js for what each attachment holds). */
    this.renderTarget = createSubsurfaceTarget(type);

    this._visibility = new Map();
    this._writes = new Map();
    this._categories = new Map();
  }

  /** The colour attachment: specular + emissive of subsurface pixels, full colour elsewhere. */
  get colorTexture() { return this.renderTarget.textures[ATTACHMENTS.COLOR]; }
  /** The diffuse attachment: the light to scatter; alpha, the mask. */
  get diffuseTexture() { return this.renderTarget.textures[ATTACHMENTS.DIFFUSE]; }
  /** The surface attachment: linear view depth and world units per profile mm. */
  get surfaceTexture() { return this.renderTarget.textures[ATTACHMENTS.SURFACE]; }
  /** The old name of colorTexture (it holds more than light: see colorTexture). */
  get lightTexture() { return this.colorTexture; }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.renderTarget.setSize(width, height);
  }

  /** 'subsurface', 'opaque' or 'transparent' for a material seen in the last render, else undefined. */
  categoryOf(material) {
    return this._categories.get(material);
  }

  /** Sorts the scene's visible materials into the three categories; returns how many are transparent. */
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
        const category = m.transparent ? CATEGORIES.TRANSPARENT : getSubsurface(m) ? CATEGORIES.SUBSURFACE : CATEGORIES.OPAQUE;
        categories.set(m, category);
        if (category === CATEGORIES.TRANSPARENT) transparent++;
        if (category === CATEGORIES.SUBSURFACE) hasSubsurface = true;
      }
      if (hasSubsurface) this.subsurfaceMeshes.push(object);
    });
    return transparent;
  }

  /** Shows the materials one call draws: `phase` DEPTH shows every category, the others their own. */
  _show(phase, category) {
    for (const [material, c] of this._categories) {
      material.visible = phase === DRAW_PHASES.DEPTH || c === category;
      // In the depth call transparent materials only cast shadows: they draw nothing.
      const silent = phase === DRAW_PHASES.DEPTH && c === CATEGORIES.TRANSPARENT;
      const writes = this._writes.get(material);
      material.colorWrite = silent ? false : writes.colorWrite;
      material.depthWrite = silent ? false : writes.depthWrite;
    }
  }

  /** One call: the draw phase for hooked materials, the draw buffers, the categories shown. */
  _draw(renderer, phase, drawBuffers, category) {
    setDrawPhase(this.renderTarget, phase);
    renderer.getContext().drawBuffers(drawBuffers);
    this._show(phase, category);
    renderer.render(this.scene, this.camera);
  }

  render(renderer /* , writeBuffer, readBuffer */) {
    assertFloatRenderTargets(renderer, 'SubsurfaceScenePass');
    const { scene, renderTarget: target } = this;
    const gl = renderer.getContext();
    const transparent = this._classify();
    this._visibility.clear();
    this._writes.clear();
    for (const material of this._categories.keys()) {
      this._visibility.set(material, material.visible);
      this._writes.set(material, { colorWrite: material.colorWrite, depthWrite: material.depthWrite });
    }

    preservingRendererState(renderer, scene, () => {
      try {
        if (this.lightDepth) this.lightDepth.render(renderer, scene);
        renderer.setRenderTarget(target);
        renderer.autoClear = false;
        renderer.clear(true, true, true); // the colour attachment takes the clear colour, like RenderPass
        gl.clearBufferfv(gl.COLOR, ATTACHMENTS.DIFFUSE, ZERO);
        gl.clearBufferfv(gl.COLOR, ATTACHMENTS.SURFACE, ZERO);

        // 1. opaque ordinary materials + subsurface depth; background and shadow maps.
        this._draw(renderer, DRAW_PHASES.DEPTH, DRAW_BUFFERS.COLOR_ONLY);
        scene.background = null; // drawn once; a Color background would clear the targets again
        renderer.shadowMap.autoUpdate = false;
        // 2. subsurface materials into every attachment.
        if (this.subsurfaceMeshes.length > 0) this._draw(renderer, DRAW_PHASES.SPLIT, DRAW_BUFFERS.ALL, CATEGORIES.SUBSURFACE);
        // 3. transparent materials over everything, colour only.
        if (transparent > 0) this._draw(renderer, DRAW_PHASES.PLAIN, DRAW_BUFFERS.COLOR_ONLY, CATEGORIES.TRANSPARENT);
      } finally {
        // three caches draw buffers per target: leave them as it set them.
        if (renderer.getRenderTarget() === target) gl.drawBuffers(DRAW_BUFFERS.ALL);
        setDrawPhase(target, DRAW_PHASES.PLAIN);
        for (const [material, visible] of this._visibility) material.visible = visible;
        for (const [material, { colorWrite, depthWrite }] of this._writes) Object.assign(material, { colorWrite, depthWrite });
      }
    });
  }

  dispose() {
    this.renderTarget.dispose();
    this._visibility.clear();
    this._writes.clear();
    this._categories.clear();
    this.subsurfaceMeshes.length = 0;
  }
}
