// What a frame covers, decided once, as three decides what it draws (WebGLRenderer's and
// WebGPURenderer's projectObject): an object counts while it and its ancestors are `visible`; it
// is drawn where it is on the camera's layers and, unless `frustumCulled` is false, inside the
// camera's frustum (three's own test: Frustum.intersectsObject / intersectsSprite, one frustum per
// view of an ArrayCamera); an LOD shows the level the camera picks. The frame plan, the screen
// box, the scene split and every light's map read these lists, so a subsurface mesh off the
// screen costs nothing: it enters no plan, no box and no light's map.
//
// The lights' passes draw with the light's camera, which three's renderer would also use to pick
// LOD levels; `holdingLevels` keeps the camera's levels while they draw (three's shadow maps never
// switch an LOD either).
import { Frustum, Matrix4 } from 'three';

const _projScreen = new Matrix4();

/** Three's frustum test of one object (r182+: object.intersectsFrustum; before, the frustum's own). */
export function intersectsFrustum(object, frustum) {
  if (typeof object.intersectsFrustum === 'function') return object.intersectsFrustum(frustum);
  return object.isSprite ? frustum.intersectsSprite(object) : frustum.intersectsObject(object);
}

/** The objects three draws geometry for: meshes (instanced, batched, skinned), lines, points, sprites. */
export const isDrawable = (object) => object.isMesh === true || object.isLine === true || object.isPoints === true || object.isSprite === true;

/** An object's materials as a list (a multi-material mesh's array, or its one material). */
export const materialsOf = (object) => (Array.isArray(object.material) ? object.material : [object.material]);

/** The frusta of `camera`'s views: its own, or one per sub-camera of an ArrayCamera (as three's FrustumArray). */
class CameraFrusta {
  constructor() {
    /** @type {Frustum[]} */
    this.frusta = [];
    this.count = 0;
  }

  /** @param {import('three').Camera} camera (matrices up to date) */
  setFromCamera(camera) {
    const views = camera.isArrayCamera === true && camera.cameras.length > 0 ? camera.cameras : [camera];
    views.forEach((view, i) => {
      _projScreen.multiplyMatrices(view.projectionMatrix, view.matrixWorldInverse);
      this.frusta[i] ??= new Frustum();
      this.frusta[i].setFromProjectionMatrix(_projScreen, view.coordinateSystem, view.reversedDepth);
    });
    this.count = views.length;
    return this;
  }

  /** Whether three draws `object` in some view (its bounds meet that view's frustum, or it is never culled). */
  sees(object) {
    if (object.frustumCulled === false) return true;
    for (let i = 0; i < this.count; i++) if (intersectsFrustum(object, this.frusta[i])) return true;
    return false;
  }
}

/**
 * The lists of one frame, refilled by `update` (no allocation per frame once they have grown):
 * - `drawn`: the drawable objects visible with their ancestors on the camera's layers, whatever the
 *   frustum (three may draw them: their materials are the scene split's to sort);
 * - `onScreen`: those of `drawn` inside the camera's frustum that have a subsurface material
 *   (`isSubsurface`), visible: the meshes whose pixels the frame scatters;
 * - `solids`: every drawable object visible with its ancestors, any layers (a light's pass takes
 *   those on its layers: LightDepthView.layersOf);
 * - `lods`: the LODs visible with their ancestors (holdingLevels);
 * - `lights`: the lights three lights the frame with (visible, on the camera's layers), in its order.
 */
export class FrameMeshes {
  constructor() {
    /** @type {import('three').Object3D[]} */
    this.drawn = [];
    /** @type {import('three').Mesh[]} */
    this.onScreen = [];
    /** @type {import('three').Object3D[]} */
    this.solids = [];
    /** @type {import('three').LOD[]} */
    this.lods = [];
    /** @type {import('three').Light[]} */
    this.lights = [];
    /** The scene and the camera the lists were made for. @type {import('three').Object3D|null} */
    this.scene = null;
    /** @type {import('three').Camera|null} */
    this.camera = null;
    this._frusta = new CameraFrusta();
    this._isSubsurface = () => false;
  }

  /**
   * The lists for `scene` drawn with `camera`, whose world matrices must be up to date (as three's
   * render makes them). LODs on the camera's layers pick their level for `camera` now, as three's
   * render is about to.
   * @param {import('three').Object3D} scene
   * @param {import('three').Camera} camera
   * @param {(material: import('three').Material) => boolean} isSubsurface
   * @returns {this}
   */
  update(scene, camera, isSubsurface) {
    this.drawn.length = 0;
    this.onScreen.length = 0;
    this.solids.length = 0;
    this.lods.length = 0;
    this.lights.length = 0;
    this.scene = scene;
    this.camera = camera;
    this._isSubsurface = isSubsurface;
    this._frusta.setFromCamera(camera);
    this._visitObject(scene);
    return this;
  }

  /** One object, then its children: projectObject's order and tests. @private */
  _visitObject(object) {
    if (object.visible === false) return;
    const onLayers = object.layers.test(this.camera.layers);
    if (object.isLOD === true) {
      this.lods.push(object);
      if (onLayers && object.autoUpdate === true) object.update(this.camera);
    } else if (object.isLight === true) {
      if (onLayers) this.lights.push(object);
    } else if (isDrawable(object)) {
      this.solids.push(object);
      if (onLayers) {
        this.drawn.push(object);
        if (object.material && this._hasSubsurface(object) && this._frusta.sees(object)) this.onScreen.push(object);
      }
    }
    const { children } = object;
    for (let i = 0; i < children.length; i++) this._visitObject(children[i]);
  }

  /** @private */
  _hasSubsurface(object) {
    const materials = materialsOf(object);
    for (let i = 0; i < materials.length; i++) {
      const material = materials[i];
      if (material && material.visible !== false && this._isSubsurface(material)) return true;
    }
    return false;
  }

  /**
   * Runs `draw` (a light's pass) with every LOD holding the level the camera picked.
   * @template T @param {() => T} draw @returns {T}
   */
  holdingLevels(draw) {
    return holdingLevels(this.lods, draw);
  }
}

/**
 * Runs `draw` with each of `lods` holding its level: three's renderer would switch them to the
 * levels of the camera `draw` renders with (a light's), where three's shadow maps keep the view's.
 * @template T @param {Iterable<import('three').LOD>} lods @param {() => T} draw @returns {T}
 */
export function holdingLevels(lods, draw) {
  const held = [];
  for (const lod of lods) {
    if (lod.autoUpdate !== true) continue;
    lod.autoUpdate = false;
    held.push(lod);
  }
  try {
    return draw();
  } finally {
    for (const lod of held) lod.autoUpdate = true;
  }
}

/**
 * Runs `draw` (a render of `scene`) with the scene's children taken to be `objects` alone: three's
 * renderer then visits those (and what hangs below them) instead of the whole graph, where a stage
 * draws a few of its objects (the split's subsurface meshes, a light's view). The objects keep
 * their parents and world matrices (held: holdingMatrices); one below another in the list is
 * reached through it, not listed again.
 * @template T
 * @param {import('three').Object3D} scene
 * @param {Iterable<import('three').Object3D>} objects
 * @param {() => T} draw
 * @returns {T}
 */
export function renderingOnly(scene, objects, draw) {
  const listed = new Set(objects);
  const roots = [];
  for (const object of listed) {
    let above = object.parent;
    while (above && above !== scene && !listed.has(above)) above = above.parent;
    if (!above || above === scene) roots.push(object);
  }
  const { children } = scene;
  scene.children = roots;
  try {
    return draw();
  } finally {
    scene.children = children;
  }
}
