// What the orchestrator checks before each frame, where three itself would draw silently:
// - the size against the GPU's largest render target (a RangeError: three's buffers fail there too);
// - the camera, the scene (an overrideMaterial), the light, settings that ask for a light where
//   there is none, and an MSAA output that cannot take the scene's depth per sample: a console
//   warning once per pipeline and a message in `sss.problems` while it lasts; the frame is drawn
//   as three would draw it, never with NaN pixels.
import { checkNumber } from './parameterChecks.js';
import { LIGHT_VIEWS, MAX_TARGET_SIZE } from '../options.js';

const GL_MAX_TEXTURE_SIZE = 0x0d33;
const GL_MAX_RENDERBUFFER_SIZE = 0x84e8;

/** renderer → { texture, renderbuffer, size }: the GPU's limits, read once per renderer. */
const limitsByRenderer = new WeakMap();

/**
 * The largest render target `renderer`'s GPU makes, pixels per side, and the two limits behind it.
 * @param {import('three').WebGLRenderer} renderer
 * @returns {{ texture: number, renderbuffer: number, size: number }}
 */
export function renderTargetLimits(renderer) {
  let limits = limitsByRenderer.get(renderer);
  if (!limits) {
    const gl = renderer.getContext();
    const texture = gl.getParameter(GL_MAX_TEXTURE_SIZE);
    const renderbuffer = gl.getParameter(GL_MAX_RENDERBUFFER_SIZE);
    // A lost context answers null: nothing is known yet, so nothing is refused.
    if (!(texture > 0) || !(renderbuffer > 0)) return { texture: Infinity, renderbuffer: Infinity, size: Infinity };
    limits = { texture, renderbuffer, size: Math.min(texture, renderbuffer) };
    limitsByRenderer.set(renderer, limits);
  }
  return limits;
}

/**
 * Checks a size given to setSize: at least 1 pixel (three's composer passes fractional ones with a
 * fractional pixel ratio), and within `limits` when known.
 * @param {*} width
 * @param {*} height
 * @param {string} who e.g. 'SubsurfaceScattering.setSize'
 * @param {{ texture: number, renderbuffer: number, size: number }} [limits]
 * @throws {TypeError} "SubsurfaceScattering.setSize: width must be a finite number, got undefined"
 * @throws {RangeError} "SubsurfaceScattering.setSize: width must be in [1, 65536] pixels, got 0"
 */
export function checkTargetSize(width, height, who, limits) {
  checkNumber(`${who}: width`, width, { min: 1, max: MAX_TARGET_SIZE, unit: 'pixels' });
  checkNumber(`${who}: height`, height, { min: 1, max: MAX_TARGET_SIZE, unit: 'pixels' });
  if (limits) checkWithin({ width, height }, limits, who);
}

function checkWithin({ width, height }, limits, who) {
  if (Math.floor(width) <= limits.size && Math.floor(height) <= limits.size) return;
  throw new RangeError(`${who}: ${width} × ${height} pixels is larger than this GPU's largest render target, ` +
    `${limits.size} × ${limits.size} (MAX_TEXTURE_SIZE ${limits.texture}, MAX_RENDERBUFFER_SIZE ${limits.renderbuffer}): ` +
    'lower the composer\'s size or pixel ratio');
}

/**
 * Checks the size last given to setSize against `renderer`'s GPU.
 * @param {import('three').WebGLRenderer} renderer
 * @param {{ width: number, height: number }} size
 * @param {string} who
 * @returns {{ texture: number, renderbuffer: number, size: number }} the limits
 */
export function checkTargetLimits(renderer, size, who) {
  const limits = renderTargetLimits(renderer);
  checkWithin(size, limits, `${who}.setSize`);
  return limits;
}

const format = (v) => (Number.isFinite(v) ? String(Number(v.toPrecision(6))) : String(v));

function finiteMatrix(matrix) {
  const e = matrix.elements;
  for (let i = 0; i < 16; i++) if (!Number.isFinite(e[i])) return false;
  return true;
}

/** A frame's checks: `begin()`, the checks, `end()`; `current` holds the last frame's messages. */
export class FrameChecks {
  /** @param {string} who the class named in the warnings */
  constructor(who) {
    this.who = who;
    /** @type {readonly string[]} the last frame's problems */
    this.current = Object.freeze([]);
    this._warned = new Set();
    this._next = null;
  }

  begin() {
    this._next = null;
    return this;
  }

  end() {
    this.current = this._next ? Object.freeze(this._next) : (this.current.length ? Object.freeze([]) : this.current);
  }

  /** Warns the first time only per `key`. */
  problem(key, message) {
    (this._next ??= []).push(message);
    if (this._warned.has(key)) return;
    this._warned.add(key);
    console.warn(`${this.who}: ${message}`);
  }

  /** A camera whose projection is not finite draws nothing (in three too). */
  camera(camera) {
    const perspective = camera.isPerspectiveCamera === true;
    const { near, far } = camera;
    const broken = !finiteMatrix(camera.projectionMatrix) || (perspective && !(near > 0 && far > near));
    if (!broken) return true;
    const shape = perspective
      ? `near ${format(near)}, far ${format(far)}, aspect ${format(camera.aspect)}, fov ${format(camera.fov)}`
      : camera.isOrthographicCamera
        ? `left ${format(camera.left)}, right ${format(camera.right)}, top ${format(camera.top)}, bottom ${format(camera.bottom)}, near ${format(near)}, far ${format(far)}`
        : `near ${format(near)}, far ${format(far)}`;
    this.problem('camera', `the camera's projection is not finite or has far ≤ near (${shape}), so nothing is drawn, as in three; ` +
      'give it finite values with 0 < near < far and a non-zero view (an aspect of 0 or NaN comes from a canvas of zero size), then call camera.updateProjectionMatrix()');
    return false;
  }

  scene(scene) {
    if (!scene.overrideMaterial) return true;
    this.problem('overrideMaterial', 'scene.overrideMaterial is set: the scene is drawn with it as three draws it, without subsurface scattering or transmittance');
    return false;
  }

  /**
   * The light's colour and intensity (always: three lights the scene with them) and, with
   * transmittance on, its place in the scene and its frustum.
   * @param {import('../1-light-depth/LightDepthTarget.js').LightDepthTarget} lightDepth
   * @param {import('../frameMeshes.js').FrameMeshes} frame what the frame covers (its scene's
   *   meshes, the camera), world matrices up to date
   * @param {boolean} transmittance
   * @param {(material: import('three').Material) => boolean} transmits the materials whose
   *   thickness the map must hold (its near and far are fitted to them: LightDepthView.fit)
   * @returns {boolean} whether transmittance can be drawn from it this frame
   */
  light(lightDepth, frame, transmittance, transmits) {
    const { scene } = frame;
    const { light } = lightDepth;
    // Each light's problems apart (a pipeline may have four), named where the user named it.
    const the = light.name ? `the light "${light.name}"` : 'the light';
    const problem = (kind, message) => this.problem(`${kind}:${light.uuid}`, message);
    const { r, g, b } = light.color;
    if (!(Number.isFinite(r) && Number.isFinite(g) && Number.isFinite(b) && Number.isFinite(light.intensity))) {
      problem('lightValues', `${the}'s color (${format(r)}, ${format(g)}, ${format(b)}) or intensity (${format(light.intensity)}) is not finite: ` +
        'three lights the scene with NaN from it, drawn black here, and there is no transmittance until both are finite');
      return false;
    }
    if (!transmittance) return false;
    if (scene.overrideMaterial) return false;
    let root = light;
    while (root.parent) root = root.parent;
    if (root !== scene) {
      problem('lightRemoved', `${the} is not in the scene (removed, or never added): there is no transmittance until it is added (with its target), ` +
        'or set transmittance to false');
      return false;
    }
    const unfit = lightDepth.fit(frame, transmits);
    if (unfit) problem('lightInside', unfit);
    if (lightDepth.fitted === null) return false; // no transmitting mesh on the screen: its map would go unread
    const frustum = lightDepth.frustumProblem();
    if (frustum) {
      problem('lightFrustum', `${the}'s depth map has no valid frustum (${frustum}): there is no transmittance until it has one`);
      return false;
    }
    return true;
  }

  /**
   * The last frame's depth hand-off (SubsurfaceComposePass.depthHandOff): a string says why a
   * multisampled output could not take the scene's depth per sample.
   * @param {boolean|string} handOff
   */
  depthHandOff(handOff) {
    if (typeof handOff !== 'string') return;
    this.problem('depthHandOff', `the output buffer is multisampled unlike the scene split (${handOff}), so the scene's depth is handed on one per pixel: ` +
      'what is drawn after the opaque scene (transparent objects, a later pass) has an aliased edge along its silhouettes; ' +
      "give the buffer the pipeline's samples (`multisampling`) and no stencil buffer");
  }

  /**
   * Settings that ask for what a light gives, on a frame without one. They are kept as set (so
   * several set at once give the same in any order) and take effect when a light comes; until then
   * there is no transmittance and the light's views show none (black on the subsurface pixels).
   * @param {boolean} transmittanceAsked `transmittance` set true by the user (the default asks nothing)
   * @param {string} debugView
   * @returns {this}
   */
  withoutLight(transmittanceAsked, debugView) {
    if (transmittanceAsked) {
      this.problem('transmittanceWithoutLight', 'transmittance is true but there is no light (`light` is null, or no light casts shadows): ' +
        'nothing is transmitted until a light is set');
    }
    if (LIGHT_VIEWS.includes(debugView)) {
      this.problem(`${debugView}ViewWithoutLight`, `debugView '${debugView}' shows what the light gives, and there is no light ` +
        '(`light` is null, or no light casts shadows): it is black on the subsurface pixels until a light is set');
    }
    return this;
  }
}
