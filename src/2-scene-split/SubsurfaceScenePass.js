// Stage 2 (render): draws the scene's opaque part into the multi-target
// (src/2-scene-split/subsurfaceTarget.js: colour | diffuse | surface | depth). Chromium refuses
// draws whose shader lacks an output for an active draw buffer, and three's ordinary materials
// write location 0 only. So the opaque scene is drawn in two calls, each with its own draw buffers
// and the materials of one category shown:
//   1. opaque ordinary materials into the colour attachment only; subsurface materials are HIDDEN
//      (their triangles clipped in the vertex shader, no fragment rasterised). Shadow maps are rendered here, with every caster
//      present: transparent materials are drawn with colour and depth writes off, only so that
//      they still cast shadows;
//   2. SPLIT: subsurface materials alone into all attachments, depth-tested against call 1, so
//      occluded subsurface fragments never reach the diffuse and surface attachments, which stay 0
//      there: the mask is exact by construction (subsurface against subsurface: the depth test
//      within the call, as in any opaque draw).
// So each subsurface object is rasterised once (a depth prepass would pay only where subsurface
// objects hide much of each other).
// Transparent materials come after the compose (renderTransparent): blended over the scattered
// image, depth-tested against the scene, exactly as three blends them over its opaque pass.
import { Color, FloatType, HalfFloatType } from 'three';
import { Pass } from 'three/addons/postprocessing/Pass.js';
import { followCopy, getSubsurface } from './subsurfaceMaterial.js';
import { FrameMeshes, materialsOf, renderingOnly } from '../frameMeshes.js';
import { subsurfaceScreenBox } from './subsurfaceScreenBox.js';
import { ATTACHMENTS, DRAW_BUFFERS, DRAW_PHASES, createSubsurfaceTarget, diffuseCarriesDepth, drawingInto, setDiffuseCarriesDepth, setSurfaceChannels } from './subsurfaceTarget.js';
import { assertFloatRenderTargets, describe } from '../support/rendererSupport.js';
import { checkOptions } from '../support/parameterChecks.js';
import { PASS_BOOLEANS, booleanFields } from '../support/booleanFields.js';
import { holdingMatrices, preservingRendererState } from '../support/rendererState.js';
import { checkThreeRevision } from '../support/threeVersion.js';
import { nameClass } from '../support/className.js';

const ZERO = new Float32Array(4);
const _clearColor = new Color();
/** Transparent subsurface materials already warned about (once each). */
const warnedTransparent = new WeakSet();

/** A material as a message names it: by the name the user gave it, else by its type and its mesh's name. */
function materialLabel(material, mesh) {
  if (material.name) return `material "${material.name}"`;
  return mesh.name ? `the ${material.type} of mesh "${mesh.name}"` : `an unnamed ${material.type} of an unnamed ${mesh.type}`;
}

/** Whether a material is made subsurface (by any pipeline). */
const isSubsurface = (material) => getSubsurface(material) !== undefined;

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
   * @param {object} [options.owner] whose material settings the subsurface materials draw with
   *   (SubsurfaceScattering passes itself; default: this pass)
   */
  constructor(scene, camera, options = {}) {
    checkThreeRevision('SubsurfaceScenePass');
    super();
    const { type = HalfFloatType, lightDepth = null, owner = this } = checkOptions('SubsurfaceScenePass options', options, ['type', 'lightDepth', 'owner']);
    if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScenePass: scene must be a THREE.Scene, got ${describe(scene)}`);
    if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScenePass: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (type !== HalfFloatType && type !== FloatType) {
      throw new RangeError('SubsurfaceScenePass: type must be THREE.HalfFloatType or THREE.FloatType (light needs HDR targets)');
    }
    this.scene = scene;
    this.camera = camera;
    this.lightDepth = lightDepth;
    this.owner = owner;
    /** As RenderPass: the clear colour and alpha of the colour attachment (null: the renderer's). */
    this.clearColor = null;
    this.clearAlpha = null;
    this.needsSwap = false; // writes its own targets, not the composer's
    /** What the frame covers (collect): the meshes drawn, on the screen, the lights' solids, the LODs. */
    this.frame = new FrameMeshes();
    /** Copies of subsurface materials the last frame met and could not make subsurface: material → why. */
    this.copiesNotFollowed = new Map();
    /** Whether a material is subsurface, a copy of one made so first (_subsurfaceOf): what the frame's lists are sorted by. */
    this._isSubsurface = (material) => this._subsurfaceOf(material) !== undefined;
    this._collected = false;
    this._splitObjects = [];
    /** The meshes with an opaque subsurface material on the screen in the last render (the plan, the box). */
    this.subsurfaceMeshes = [];
    /**
     * The last render's subsurface pixels lie in this box (device pixels; null: anywhere), from
     * the meshes' bounds (subsurfaceScreenBox.js): the blur is scissored to it.
     */
    this.subsurfaceBox = null;
    /** The multi-target (see subsurfaceTarget.js for what each attachment holds). */
    this.renderTarget = createSubsurfaceTarget(type);
    this._type = type;
    this._applyDiffuseLayout();

    this._visibility = new Map();
    this._writes = new Map();
    this._categories = new Map();
  }

  /** The colour attachment: specular + emissive of subsurface pixels, full colour elsewhere. */
  get colorTexture() { return this.renderTarget.textures[ATTACHMENTS.COLOR]; }
  /** The diffuse attachment: the light to scatter; alpha, the depth or the coverage (diffuseCarriesDepth). */
  get diffuseTexture() { return this.renderTarget.textures[ATTACHMENTS.DIFFUSE]; }
  /** The surface attachment: linear view depth and world units per profile mm. */
  get surfaceTexture() { return this.renderTarget.textures[ATTACHMENTS.SURFACE]; }
  /** The scene's depth (of its opaque part), a DepthTexture. */
  get depthTexture() { return this.renderTarget.depthTexture; }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.renderTarget.setSize(width, height);
  }

  /**
   * Whether the diffuse attachment's alpha carries the depth (shaders/common/carriedDepth.glsl):
   * without MSAA (32-bit float), so the blur's taps read light and depth in one fetch; with MSAA
   * its alpha is the coverage. Either way the alpha is 0 off the mask and non-zero on it.
   */
  get diffuseCarriesDepth() { return diffuseCarriesDepth(this.renderTarget); }

  _applyDiffuseLayout() {
    setDiffuseCarriesDepth(this.renderTarget, this.renderTarget.samples === 0, this._type);
  }

  /**
   * MSAA samples of the multi-target (0: none); three resolves it by averaging, so the blur must
   * then read its inputs as coverage-weighted (SurfacePass.setMultisampled).
   * @param {number} samples
   * @returns {boolean} whether the count changed
   */
  setSamples(samples) {
    if (this.renderTarget.samples === samples) return false;
    this.renderTarget.samples = samples;
    this.renderTarget.dispose(); // three rebuilds its buffers, multisampled or not, on the next use
    this._applyDiffuseLayout(); // MSAA keeps the coverage in the diffuse alpha
    return true;
  }

  /**
   * How many profiles the subsurface materials write (their slots): several grow the surface
   * attachment by the slot channel (subsurfaceTarget.js's setSurfaceChannels).
   * @param {number} count
   */
  setProfileCount(count) {
    setSurfaceChannels(this.renderTarget, count);
  }

  /** 'subsurface', 'opaque' or 'transparent' for a material seen in the last render, else undefined. */
  categoryOf(material) {
    return this._categories.get(material);
  }

  /**
   * Decides what this frame covers (src/frameMeshes.js: visible, on the camera's layers, LOD
   * levels, the frustum) and sorts the materials drawn into the three categories. render() calls
   * it unless it was called since the last render (the orchestrator calls it first: the light's
   * pass and the plan read the same lists). The world matrices are updated as three's render does.
   * @returns {FrameMeshes}
   */
  collect() {
    const { scene, camera } = this;
    if (scene.matrixWorldAutoUpdate === true) scene.updateMatrixWorld();
    if (camera.parent === null && camera.matrixWorldAutoUpdate === true) camera.updateMatrixWorld();
    this.copiesNotFollowed.clear();
    this.frame.update(scene, camera, this._isSubsurface);
    if (scene.overrideMaterial) this._classifyOverridden();
    else this._classify();
    this._collected = true;
    return this.frame;
  }

  /**
   * A material's subsurface binding; a copy of a subsurface material (its userData's mark) is bound
   * as its source first (followCopy), or kept in `copiesNotFollowed` with the reason.
   */
  _subsurfaceOf(material) {
    const binding = getSubsurface(material);
    if (binding) return binding;
    const copy = followCopy(material);
    if (copy?.follows === false) this.copiesNotFollowed.set(material, copy.reason);
    return getSubsurface(material);
  }

  /** Sorts the frame's drawn materials into the three categories; returns how many are transparent. */
  _classify() {
    const categories = this._categories;
    categories.clear();
    this.subsurfaceMeshes.length = 0;
    let transparent = 0;
    for (const object of this.frame.drawn) {
      const material = object.material;
      if (!material) continue;
      for (const m of Array.isArray(material) ? material : [material]) {
        if (!m || !m.visible || categories.has(m)) continue;
        const category = m.transparent ? CATEGORIES.TRANSPARENT : isSubsurface(m) ? CATEGORIES.SUBSURFACE : CATEGORIES.OPAQUE;
        if (m.transparent && isSubsurface(m) && !warnedTransparent.has(m)) {
          warnedTransparent.add(m);
          console.warn(`SubsurfaceScattering: ${materialLabel(m, object)} is transparent, so it is blended over the scattered image without scattering (as three blends transparent objects). Set transparent = false to make it scatter; alphaTest or alphaHash keep its cut-outs.`);
        }
        categories.set(m, category);
        if (category === CATEGORIES.TRANSPARENT) transparent++;
      }
    }
    // On the screen: an opaque subsurface material (a transparent one draws as transparent).
    for (const object of this.frame.onScreen) {
      if (materialsOf(object).some((m) => categories.get(m) === CATEGORIES.SUBSURFACE)) this.subsurfaceMeshes.push(object);
    }
    this.transparentCount = transparent;
    return transparent;
  }

  /**
   * scene.overrideMaterial draws every object with one material, as three draws it: into the
   * colour attachment alone (it writes location 0 only), without the split and the transparent
   * draw (three draws the transparent objects with the override too, in the same call).
   */
  _classifyOverridden() {
    this._categories.clear();
    this.subsurfaceMeshes.length = 0;
    this.transparentCount = 0;
    return 0;
  }

  /** Shows the materials one call draws: the first call (HIDDEN) every category, the others their own. */
  _show(phase, category) {
    const first = phase === DRAW_PHASES.HIDDEN;
    for (const [material, c] of this._categories) {
      material.visible = first || c === category;
      // In the first call transparent materials only cast shadows: they draw nothing.
      const silent = first && c === CATEGORIES.TRANSPARENT;
      const writes = this._writes.get(material);
      material.colorWrite = silent ? false : writes.colorWrite;
      material.depthWrite = silent ? false : writes.depthWrite;
    }
  }

  /** One call: the draw phase for hooked materials, the draw buffers, the categories shown. */
  _draw(renderer, phase, drawBuffers, category) {
    drawingInto(this.renderTarget, phase, this.owner, () => {
      renderer.getContext().drawBuffers(drawBuffers);
      this._show(phase, category);
      if (phase !== DRAW_PHASES.SPLIT) {
        renderer.render(this.scene, this.camera);
        return;
      }
      // The split draws the subsurface meshes on the screen, lit by the frame's lights: three
      // visits those alone, not the whole scene again (its matrices are call 1's).
      this._splitObjects.length = 0;
      this._splitObjects.push(...this.frame.lights, ...this.subsurfaceMeshes);
      holdingMatrices(this.scene, () => renderingOnly(this.scene, this._splitObjects, () => renderer.render(this.scene, this.camera)));
    });
  }

  /** Runs `draw` and puts every classified material's visibility and writes back as they were. */
  _restoringMaterials(draw) {
    this._visibility.clear();
    this._writes.clear();
    for (const material of this._categories.keys()) {
      this._visibility.set(material, material.visible);
      this._writes.set(material, { colorWrite: material.colorWrite, depthWrite: material.depthWrite });
    }
    try {
      draw();
    } finally {
      for (const [material, visible] of this._visibility) material.visible = visible;
      for (const [material, { colorWrite, depthWrite }] of this._writes) Object.assign(material, { colorWrite, depthWrite });
    }
  }

  /** Draws the scene's opaque part into the multi-target (the two calls of the header). */
  render(renderer /* , writeBuffer, readBuffer */) {
    assertFloatRenderTargets(renderer, 'SubsurfaceScenePass');
    const { scene, renderTarget: target } = this;
    const gl = renderer.getContext();
    if (!this._collected) this.collect();
    this._collected = false;
    preservingRendererState(renderer, scene, () => this._restoringMaterials(() => {
      try {
        if (this.lightDepth) this.lightDepth.render(renderer, scene);
        renderer.setRenderTarget(target);
        renderer.autoClear = false;
        // The colour attachment takes the clear colour, like RenderPass. Set now, with the target
        // bound: three converts it for the target current when it is set, and this one is linear.
        renderer.setClearColor(this.clearColor ?? renderer.getClearColor(_clearColor), this.clearAlpha ?? renderer.getClearAlpha());
        renderer.clear(true, true, true);
        gl.clearBufferfv(gl.COLOR, ATTACHMENTS.DIFFUSE, ZERO);
        gl.clearBufferfv(gl.COLOR, ATTACHMENTS.SURFACE, ZERO);
        // 1. opaque ordinary materials; background and shadow maps.
        // With MSAA three resolves the target after every render() into it, the depth once per
        // attachment: after call 1 the depth is not resolved when call 2 follows and resolves it.
        // Before r186 (no storeMultisampledDepthBuffer) three also invalidates the multisampled
        // depth it does not resolve, where it invalidates (the Oculus Browser): not there.
        const keepsDepth = 'storeMultisampledDepthBuffer' in target;
        target.resolveDepthBuffer = !(keepsDepth && target.samples > 0 && this.subsurfaceMeshes.length > 0);
        try {
          this._draw(renderer, DRAW_PHASES.HIDDEN, DRAW_BUFFERS.COLOR_ONLY);
        } finally {
          target.resolveDepthBuffer = true;
        }
        // 2. subsurface materials into every attachment (no background: a Color one would clear).
        scene.background = null;
        renderer.shadowMap.autoUpdate = false;
        if (this.subsurfaceMeshes.length > 0) this._draw(renderer, DRAW_PHASES.SPLIT, DRAW_BUFFERS.ALL, CATEGORIES.SUBSURFACE);
        // With the matrices as the draws left them.
        this.subsurfaceBox = subsurfaceScreenBox(this.subsurfaceMeshes, this.camera, target.width, target.height);
      } finally {
        // three caches draw buffers per target: leave them as it set them.
        if (renderer.getRenderTarget() === target) gl.drawBuffers(DRAW_BUFFERS.ALL);
      }
    }));
  }

  /**
   * Draws the transparent materials of the last render into `target` (null: the screen) over what
   * it holds, depth-tested against its depth, which must be this scene's (the compose writes it):
   * three's own order, back to front, after the opaque scene.
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget|null} target
   */
  renderTransparent(renderer, target) {
    if (!(this.transparentCount > 0)) return;
    const { scene } = this;
    preservingRendererState(renderer, scene, () => this._restoringMaterials(() => {
      renderer.setRenderTarget(target);
      renderer.autoClear = false;
      scene.background = null;
      renderer.shadowMap.autoUpdate = false; // drawn with this frame's, in call 1
      drawingInto(target, DRAW_PHASES.PLAIN, this.owner, () => {
        this._show(DRAW_PHASES.PLAIN, CATEGORIES.TRANSPARENT);
        renderer.render(scene, this.camera);
      });
    }));
  }

  dispose() {
    this.renderTarget.dispose();
    this._visibility.clear();
    this._writes.clear();
    this._categories.clear();
    this.subsurfaceMeshes.length = 0;
  }
}

booleanFields(SubsurfaceScenePass.prototype, PASS_BOOLEANS);

nameClass(SubsurfaceScenePass, 'SubsurfaceScenePass'); // its name in messages, minified or not
