// Stage 1, renderer-free: the light's camera, its frustum checks and fit, and which materials it
// sees, shared by LightDepthTarget and the WebGPU LightDepthNodeTarget (src/webgpu/1-light-depth/),
// which bring the target, the depth material and the render.
import { Box3, Frustum, Layers, Matrix4, OrthographicCamera, PerspectiveCamera, Sphere, Vector3 } from 'three';
import { intersectsFrustum, materialsOf } from '../frameMeshes.js';
import { localBoundsOf } from '../support/meshBounds.js';
import { checkInteger, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { LIGHT_DEPTH_SIZES, PIPELINE_DEFAULTS } from '../options.js';
import { nameClass } from '../support/className.js';

const _target = new Vector3();
const _frustum = new Frustum();
const _projScreen = new Matrix4();
const _open = new Vector3(); // a plane of normal 0 and constant 1: every point is inside it

/** The light's view frustum wider than three's by a fraction of its depth range: what lies on its edge gets a depth material (three may take the projection reversed). */
const FRUSTUM_SLACK = 1e-4;

/** Sets _frustum to `camera`'s view, each plane moved out by `slack` world units. */
function setFrustum(camera, slack) {
  _frustum.setFromProjectionMatrix(_projScreen.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse), camera.coordinateSystem, camera.reversedDepth);
  if (slack > 0) for (const plane of _frustum.planes) plane.constant += slack;
  return _frustum;
}
const _corner = new Vector3();
const _inverse = new Matrix4();

/**
 * The fit (LightDepthView.fit): its margin, a fraction of its depth and of its window; a
 * perspective near's least share of far (the 24-bit depth buffer orders the surfaces over
 * near..far); the window's sides per octave (its side grows in steps of 2^(1/STEPS), about 9 %,
 * so the texels stay put while a mesh moves within a step).
 */
export const FIT = Object.freeze({ MARGIN: 0.02, MIN_NEAR: 1e-3, STEPS: 8 });

/**
 * Where objects lie in a light's view: across it, the tangents of the view axis (x / depth,
 * y / depth) for a perspective light, world units for an orthographic one; along it, the depth
 * (for a point light's six faces, the depth on the face each corner falls in: the largest of its
 * distances along the axes). `bounded` is false where a corner is on or behind a perspective
 * light's plane (its tangents are unbounded).
 */
class LightViewBounds {
  constructor() { this.makeEmpty(); }

  makeEmpty() {
    this.minX = this.minY = this.near = Infinity;
    this.maxX = this.maxY = this.far = -Infinity;
    this.bounded = true;
    return this;
  }

  /** Whether the bounds across meet `window` ({ x0, y0, side }). */
  overlaps({ x0, y0, side }) {
    return this.maxX >= x0 && this.minX <= x0 + side && this.maxY >= y0 && this.minY <= y0 + side;
  }
}

const _targetBounds = new LightViewBounds();
const _objectBounds = new LightViewBounds();
const _movedBox = new Box3();
const _movedSize = new Vector3();

/**
 * Grows `into` by the corners of `objects`' bounds (localBoundsOf) seen through `view`. An object
 * that moves its vertices its own way (`moves`: a hook, a position node) counts with the cube
 * around its bounding sphere, the bound three's frustum culling holds displaced vertices to: a leaf
 * bent out of its plane stays in the map.
 * @param {LightViewBounds} into @param {Iterable<import('three').Object3D>} objects
 * @param {Matrix4} view world → the light's view @param {boolean} perspective @param {boolean} cube
 * @param {(object: import('three').Object3D) => boolean} moves
 */
function lightViewBounds(into, objects, view, perspective, cube, moves) {
  for (const object of objects) {
    let box = localBoundsOf(object);
    if (!box || box.isEmpty()) continue;
    if (moves(object)) {
      box.getBoundingSphere(_sphere);
      box = _movedBox.setFromCenterAndSize(_sphere.center, _movedSize.setScalar(2 * _sphere.radius));
    }
    for (let k = 0; k < 8; k++) {
      _corner.set(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z)
        .applyMatrix4(object.matrixWorld).applyMatrix4(view);
      const depth = cube ? Math.max(Math.abs(_corner.x), Math.abs(_corner.y), Math.abs(_corner.z)) : -_corner.z;
      into.near = Math.min(into.near, depth);
      into.far = Math.max(into.far, depth);
      if (perspective && !(depth > 0)) {
        into.bounded = false;
        continue;
      }
      const x = perspective ? _corner.x / depth : _corner.x;
      const y = perspective ? _corner.y / depth : _corner.y;
      into.minX = Math.min(into.minX, x);
      into.maxX = Math.max(into.maxX, x);
      into.minY = Math.min(into.minY, y);
      into.maxY = Math.max(into.maxY, y);
    }
  }
  return into;
}

/**
 * The layers a light's pass draws, as three's shadow maps take them: its shadow camera's where
 * they name more than layer 0, else the camera's.
 * @param {import('three').Light} light @param {import('three').Camera} camera
 */
export function lightLayers(light, camera) {
  const own = light.shadow?.camera?.layers;
  return own && (own.mask & 0xfffffffe) !== 0 ? own : camera.layers;
}

const nameOf = (object) => (object.name ? `mesh "${object.name}"` : `an unnamed ${object.type}`);

/**
 * Whether a material's own shape matters from the light (a cut-out or clipping planes; besides, a
 * vertex stage of its own: LightDepthView.hasOwnVertexStage); other materials share one depth material.
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

/** Refuses what is not a SpotLight, DirectionalLight or PointLight, naming `who`. */
function checkLight(who, light) {
  if (!light || !(light.isSpotLight || light.isDirectionalLight || light.isPointLight)) {
    throw new TypeError(`${who}: light must be a THREE.SpotLight, THREE.DirectionalLight or THREE.PointLight, got ${describe(light)}`);
  }
}

/**
 * A point light's map: six square faces, three across and two up (face k at column k % 3, row
 * k / 3 from the bottom), face k looking from the light along +axis (even k) or −axis (odd k),
 * axis k / 2 (x, y, z), its up +y (+z for the ±y faces). shaders/2-scene-split/transmittance.glsl's
 * sssPointTransmittanceFrom reads them the same way.
 */
export const POINT_FACES = Object.freeze({ ACROSS: 3, UP: 2 });

/** The widest cone, degrees, a point light's map is aimed into (beyond, its six faces: finer than one map that wide). */
export const POINT_AIM_DEG = 120;
const _box = new Box3();
const _worldBox = new Box3();
const _sphere = new Sphere();
const [_faceForward, _faceUp, _faceX, _faceY] = [new Vector3(), new Vector3(), new Vector3(), new Vector3()];

/** Face `k`'s camera basis (x, y, and z = −forward), as the shader builds it. @param {Matrix4} into */
function pointFaceBasis(k, into) {
  const axis = k >> 1;
  _faceForward.set(0, 0, 0).setComponent(axis, k & 1 ? -1 : 1);
  _faceUp.set(0, axis === 1 ? 0 : 1, axis === 1 ? 1 : 0);
  const back = _faceForward.negate();
  _faceX.crossVectors(_faceUp, back).normalize();
  _faceY.crossVectors(back, _faceX);
  return into.makeBasis(_faceX, _faceY, back);
}

/** The camera a light's view needs: orthographic for a directional light, perspective else. */
const cameraFor = (light) => (light.isDirectionalLight ? new OrthographicCamera() : new PerspectiveCamera());

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
   * @param {import('three').SpotLight | import('three').DirectionalLight | import('three').PointLight} light
   * @param {{ size?: number, near?: number, far?: number }} [options] size: of the square target,
   *   pixels (16..8192, default 1024); near and far: world units (default: fit's, else the light's
   *   shadow camera's)
   */
  constructor(who, light, options = {}) {
    checkLight(who, light);
    const { size = PIPELINE_DEFAULTS.lightDepthSize, near, far } = checkOptions(`${who} options`, options, ['size', 'near', 'far']);
    if (near !== undefined) checkNumber('near', near, { min: 0, minExclusive: true, unit: 'world units' });
    if (far !== undefined) checkNumber('far', far, { min: near ?? 0, minExclusive: true, unit: 'world units' });
    this.who = who;
    this.light = light;
    this.near = near;
    this.far = far;
    /** The near and far fitted to what the map must hold (fit), or null: the light's shadow camera's. */
    this.fitted = null;
    /** A point light's aim at the transmitting meshes ({ center, fov }: fit), or null: six faces. */
    this.aim = null;
    /** The window across the view that fit holds the transmitting meshes in (see _window), or null: the light's whole field. */
    this.window = null;
    /** The layers the light's pass draws (lightLayers: as three's shadow maps), set by fit. */
    this.layers = new Layers();
    /** What fit found in the light's view (its pass swaps depth materials in for these; three culls the rest). @type {import('three').Object3D[]} */
    this.inView = [];
    this.camera = cameraFor(light);
    /** World → the light's view (for a point light: centred on it, the world's axes; its faces turn from there). */
    this.viewMatrix = new Matrix4();
    /** Pixels: checked by the subclass's setSize(this.size). */
    this.size = size;
    /** Whether the map holds the scene as last rendered; no transmittance from one that does not. */
    this.valid = false;
    /** @type {Map<import('three').Material, import('three').Material>} depth materials of cut-out, clipped or displaced materials */
    this._shaped = new Map();
    /** What the depth pass could not draw as the camera sees it, each named once in `problems`: key → message. */
    this.shapeProblems = new Map();
    this._onMaterialDispose = (event) => this._forget(event.target);
  }

  /**
   * What a surface of `material` is drawn with from the light; null: left out.
   * @param {import('three').Material|undefined|null} material
   */
  depthMaterialFor(material) {
    if (!lightSees(material)) return null;
    return hasOwnShape(material) || this.hasOwnVertexStage(material) ? this._shapedMaterial(material) : this.material;
  }

  /**
   * Whether `material` moves its vertices its own way (a user's shader hook, a position node), so
   * that the light sees the shape the camera sees only through a depth material of its own: the
   * subclass's answer (here: none).
   * @param {import('three').Material} material
   * @returns {boolean}
   */
  hasOwnVertexStage(material) {
    return false;
  }

  /** Whether one of `object`'s materials moves its vertices its own way (hasOwnVertexStage). @private */
  _moves(object) {
    return materialsOf(object).some((m) => m && this.hasOwnVertexStage(m));
  }

  /** One per material, its settings read now. */
  _shapedMaterial(material) {
    let shaped = this._shaped.get(material);
    if (!shaped) {
      shaped = this.createShapedMaterial(material);
      this._shaped.set(material, shaped);
      material.addEventListener('dispose', this._onMaterialDispose);
    }
    // alphaToCoverage counts as alphaTest 0.5, as in three's shadow maps. The maps only cut out.
    const alphaTest = material.alphaToCoverage === true ? 0.5 : material.alphaTest;
    const map = alphaTest > 0 ? material.map ?? null : null;
    const alphaMap = alphaTest > 0 ? material.alphaMap ?? null : null;
    Object.assign(shaped, {
      map, alphaMap, alphaTest: map || alphaMap ? alphaTest : 0, clippingPlanes: material.clippingPlanes, clipIntersection: material.clipIntersection,
    });
    this.updateShapedMaterial?.(shaped, material);
    return shaped;
  }

  _forget(material) {
    material.removeEventListener('dispose', this._onMaterialDispose);
    this.shapeProblems.delete(`lightShape:${material.uuid}`);
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

  /** @param {number} size pixels, 16..8192 (a point light's faces: half of it each) */
  setSize(size) {
    checkInteger('size', size, LIGHT_DEPTH_SIZES.min, LIGHT_DEPTH_SIZES.max, 'pixels');
    this.size = size;
    const face = this.faceSize;
    if (this.isCube) this.renderTarget.setSize(POINT_FACES.ACROSS * face, POINT_FACES.UP * face);
    else this.renderTarget.setSize(size, size);
  }

  /** Whether the map is a point light's six faces (POINT_FACES), not one view. */
  get isCube() { return this.light.isPointLight === true && this.aim === null; }

  /** A point light's face, pixels a side (half the size: six faces cost 1.5 times one map). */
  get faceSize() { return Math.max(8, this.size >> 1); }

  /**
   * Turns the camera to a point light's face `k` (0..5, POINT_FACES) and returns the viewport it
   * is drawn into, [x, y, width, height] pixels.
   * @param {number} k
   */
  pointFace(k) {
    const { camera } = this;
    pointFaceBasis(k, camera.matrixWorld).setPosition(camera.position);
    camera.matrixWorldInverse.copy(camera.matrixWorld).invert();
    const face = this.faceSize;
    return [(k % POINT_FACES.ACROSS) * face, Math.floor(k / POINT_FACES.ACROSS) * face, face, face];
  }

  /**
   * Follows another light from the next render on; the target, read by the materials, stays (the
   * camera changes kind with the light's: onCameraChange).
   * @param {import('three').SpotLight | import('three').DirectionalLight | import('three').PointLight} light
   */
  setLight(light) {
    checkLight(this.who, light);
    const kindChanges = Boolean(light.isDirectionalLight) !== Boolean(this.light.isDirectionalLight);
    const wasCube = this.isCube;
    this.light = light;
    this.fitted = null;
    this.aim = null;
    this.valid = false;
    if (wasCube !== this.isCube) this.setSize(this.size); // six faces, or one map
    if (!kindChanges) return;
    this.camera = cameraFor(light);
    this.onCameraChange?.();
  }

  /**
   * Fits the light's view to what its map must hold this frame: the meshes of `frame` on the
   * screen whose material `transmits` (FrameMeshes.onScreen), and whatever the light sees in front
   * of them (it counts as thickness). Its window, across, holds those meshes' bounds (FIT.STEPS:
   * quantised and snapped to its own texels, so the texels stay put while they move), within the
   * spot's cone; its near and far, along, from the nearest such surface to their farthest corner
   * (the shadow camera's near and far clipped meshes away silently). A point light is aimed at
   * those meshes where they fit a cone of POINT_AIM_DEG, else it takes six faces (isCube). The
   * light's pass then draws what lies in that view (three's frustum culling), nothing else.
   * @param {import('../frameMeshes.js').FrameMeshes} frame the frame's lists (world matrices up to date)
   * @param {(material: import('three').Material) => boolean} transmits
   * @returns {string|null} what cannot be fitted: a spot light inside a transmitting mesh's bounds
   */
  fit(frame, transmits) {
    this.layers.mask = lightLayers(this.light, frame.camera).mask;
    const targets = [];
    for (const object of frame.onScreen) if (this._sees(object) && materialsOf(object).some((m) => m && transmits(m))) targets.push(object);
    if (this.light.isPointLight) this._aim(targets);
    this.window = null;
    this.fitted = null;
    this.inView.length = 0;
    this.updateCamera();
    const view = this.camera.matrixWorldInverse;
    const perspective = !this.light.isDirectionalLight;
    const cube = this.isCube;
    const moves = (object) => this._moves(object);
    const across = lightViewBounds(_targetBounds.makeEmpty(), targets, view, perspective, cube, moves);
    if (!(perspective ? across.far > 0 : Number.isFinite(across.far))) return null; // nothing to hold: the map goes unread
    const { far } = across;
    if (!cube && across.bounded) this.window = this._window(across);
    // What may stand between the light and the farthest transmitting surface: the objects in the
    // window (three's frustum test on its sides, `candidates`), and of those the surfaces before it.
    const candidates = this._inWindow(frame.solids);
    let near = Infinity;
    for (const object of candidates) {
      if (!this._sees(object)) continue;
      const bounds = lightViewBounds(_objectBounds.makeEmpty(), [object], view, perspective, cube, moves);
      // The farthest transmitting surface itself too: a flat mesh face-on to the light is all at `far`.
      if (!(bounds.far > (perspective ? 0 : -Infinity)) || !(bounds.near <= far)) continue;
      near = Math.min(near, bounds.near);
    }
    // A mesh flat in the light's view (a leaf face-on) has near = far: the margin gives it depth.
    const margin = FIT.MARGIN * Math.max(far - near, Math.abs(far), Math.abs(near), Number.MIN_VALUE) || FIT.MARGIN;
    near -= margin;
    if (perspective) near = Math.max(cube ? 0 : near, FIT.MIN_NEAR * far); // six faces: the nearest is not a corner's
    this.fitted = { near, far: far + margin };
    this.updateCamera();
    // What the light's pass draws: of the candidates, those in its view (three's test, a hair wider).
    this.inView.push(...this.inViewOf(candidates));
    const inside = this.light.isSpotLight ? targets.find((object) => this._inside(object)) : undefined;
    return inside ? `the spot light${this.light.name ? ` "${this.light.name}"` : ''} is inside the bounds of ${nameOf(inside)}, so its parts nearer than ${Number(this.fitted.near.toPrecision(3))} world units to the light are not in the light's depth map (no transmittance there): move the light out of it` : null;
  }

  /**
   * Of `objects`, those on the light's layers within its view's sides (its near and far left
   * open): every one for six faces, which turn to every side.
   * @private @param {Iterable<import('three').Object3D>} objects
   */
  _inWindow(objects) {
    const cube = this.isCube;
    if (!cube) {
      setFrustum(this.camera, 0);
      _frustum.planes[4].set(_open, 1); // far: open
      _frustum.planes[5].set(_open, 1); // near: open
    }
    const found = [];
    for (const object of objects) {
      if (!object.layers.test(this.layers)) continue;
      if (cube || object.frustumCulled === false || intersectsFrustum(object, _frustum)) found.push(object);
    }
    return found;
  }

  /**
   * Of `objects` on the light's layers, those three draws from the light's camera as it stands:
   * in its view by three's frustum test, a hair wider so that what lies on the edge counts (every
   * one for six faces, each its own frustum).
   * @param {Iterable<import('three').Object3D>} objects
   * @returns {import('three').Object3D[]}
   */
  inViewOf(objects) {
    const cube = this.isCube;
    if (!cube) setFrustum(this.camera, FRUSTUM_SLACK * Math.abs(this.camera.far - this.camera.near));
    const found = [];
    for (const object of objects) {
      if (cube || object.frustumCulled === false || intersectsFrustum(object, _frustum)) found.push(object);
    }
    return found;
  }

  /** Whether the light's pass draws `object` as a surface with bounds: a mesh on its layers with a material it sees. @private */
  _sees(object) {
    return object.isMesh === true && object.layers.test(this.layers) && materialsOf(object).some(lightSees) && localBoundsOf(object) !== null;
  }

  /**
   * The window across the light's view holding `bounds` (tangents of the view axis for a
   * perspective light, world units for a directional one): a square whose side is a step of
   * FIT.STEPS and whose corner lies on its own texel grid, so a mesh moving inside it keeps its
   * texels (a shadow map's stabilisation); within the spot's cone or the point light's aim, where
   * it would be no smaller than that field (null: the whole field).
   * @private @param {LightViewBounds} bounds @returns {{ x0: number, y0: number, side: number }|null}
   */
  _window(bounds) {
    const field = this.light.isSpotLight ? Math.tan(this.light.angle) : this.light.isPointLight ? Math.tan((this.aim.fov * Math.PI) / 360) : Infinity;
    const x0 = Math.max(bounds.minX, -field);
    const x1 = Math.min(bounds.maxX, field);
    const y0 = Math.max(bounds.minY, -field);
    const y1 = Math.min(bounds.maxY, field);
    const extent = Math.max(x1 - x0, y1 - y0);
    if (!(extent > 0) || !Number.isFinite(extent)) return null;
    // The side's step above the extent with a texel to spare each side (snapping moves the corner by up to one).
    let side = 2 ** (Math.ceil(Math.log2(extent * (1 + FIT.MARGIN)) * FIT.STEPS) / FIT.STEPS);
    while (side - 2 * (side / this.size) < extent) side *= 2 ** (1 / FIT.STEPS);
    if (side >= 2 * field) return null;
    const texel = side / this.size;
    const centre = (a, b) => Math.min(Math.max(Math.floor(((a + b) / 2 - side / 2) / texel) * texel, -field), field - side);
    return { x0: centre(x0, x1), y0: centre(y0, y1), side };
  }

  /** Whether the light is inside `object`'s bounds. */
  _inside(object) {
    _corner.setFromMatrixPosition(this.light.matrixWorld).applyMatrix4(_inverse.copy(object.matrixWorld).invert());
    return localBoundsOf(object).containsPoint(_corner);
  }

  /** A point light's aim at `targets` (their bounding sphere), or null (six faces) where they surround it; the map resized where that changes. */
  _aim(targets) {
    const wasCube = this.isCube;
    _box.makeEmpty();
    for (const object of targets) _box.union(_worldBox.copy(localBoundsOf(object)).applyMatrix4(object.matrixWorld));
    _box.getBoundingSphere(_sphere);
    const distance = _sphere.center.distanceTo(_corner.setFromMatrixPosition(this.light.matrixWorld));
    const halfAngle = distance > _sphere.radius ? Math.asin(_sphere.radius / distance) * (1 + FIT.MARGIN) : Infinity;
    this.aim = !_box.isEmpty() && halfAngle <= (POINT_AIM_DEG * Math.PI) / 360 ? { center: _sphere.center.clone(), fov: (2 * halfAngle * 180) / Math.PI } : null;
    if (this.isCube !== wasCube) this.setSize(this.size);
  }

  updateCamera() {
    const { light, camera } = this;
    light.updateMatrixWorld();
    light.target?.updateMatrixWorld();
    const shadowCamera = light.shadow.camera;
    camera.position.setFromMatrixPosition(light.matrixWorld);
    if (this.isCube) camera.rotation.set(0, 0, 0); // its faces turn from the world's axes (pointFace)
    else camera.lookAt(light.isPointLight ? this.aim.center : _target.setFromMatrixPosition(light.target.matrixWorld));
    camera.near = this.near ?? this.fitted?.near ?? shadowCamera.near;
    camera.far = this.far ?? this.fitted?.far ?? shadowCamera.far;
    const { window } = this;
    if (light.isDirectionalLight) {
      // The window across (fit) in world units, else the shadow camera's extent.
      camera.left = window ? window.x0 : shadowCamera.left;
      camera.right = window ? window.x0 + window.side : shadowCamera.right;
      camera.bottom = window ? window.y0 : shadowCamera.bottom;
      camera.top = window ? window.y0 + window.side : shadowCamera.top;
    } else {
      camera.fov = light.isSpotLight ? (2 * light.angle * 180) / Math.PI : this.aim?.fov ?? 90;
      camera.aspect = 1;
      // The window (fit) as a part of that field, in tangents: the field spans 2 · tan(fov / 2).
      const field = Math.tan((camera.fov * Math.PI) / 360);
      if (window) camera.setViewOffset(2 * field, 2 * field, window.x0 + field, field - window.y0 - window.side, window.side, window.side);
      else camera.clearViewOffset();
    }
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld();
    this.viewMatrix.copy(camera.matrixWorldInverse);
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
    if (!light.isDirectionalLight && !(near > 0)) return `near ${near} is not above 0`;
    if (!(far > near)) return `far ${far} is not beyond near ${near} (light.shadow.camera, or the near and far options)`;
    if (light.isDirectionalLight && !(camera.right !== camera.left && camera.top !== camera.bottom)) {
      return `light.shadow.camera spans left ${camera.left} to right ${camera.right}, bottom ${camera.bottom} to top ${camera.top}`;
    }
    if (!camera.projectionMatrix.elements.every(Number.isFinite)) return 'its projection is not finite';
    return null;
  }
}

nameClass(LightDepthView, 'LightDepthView'); // its name in messages, minified or not
