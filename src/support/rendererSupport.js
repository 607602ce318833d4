// What every GPU stage needs from the renderer: WebGL2 (multiple render targets, texelFetch) and
// renderable float colour targets (light is HDR: 8-bit targets would clamp and band it).
import { describeValue } from './parameterChecks.js';
import { classNameOf } from './className.js';

/**
 * @param {import('three').WebGLRenderer} renderer
 * @param {string} who the class or function asking, for the message
 * @throws {TypeError} when `renderer` is not a WebGLRenderer
 * @throws {Error} on WebGL1 or without EXT_color_buffer_float
 */
export function assertFloatRenderTargets(renderer, who) {
  if (!renderer || renderer.isWebGLRenderer !== true || typeof renderer.getContext !== 'function') {
    throw new TypeError(`${who}: renderer must be a THREE.WebGLRenderer, got ${describe(renderer)}`);
  }
  if (renderer.capabilities.isWebGL2 === false) {
    throw new Error(`${who}: needs a WebGL2 context (multiple render targets); this renderer is WebGL1`);
  }
  if (!renderer.extensions.has('EXT_color_buffer_float')) {
    throw new Error(`${who}: needs renderable float render targets (EXT_color_buffer_float), which this device lacks`);
  }
}

const article = (name) => (/^[AEIOU]/.test(name) ? 'an' : 'a');

/**
 * A value for error messages: a three.js object by its `type` and name, one of this library's by
 * the name its class states (src/support/className.js), anything else as describeValue says it;
 * never by `constructor.name`, which production builds minify.
 */
export function describe(value) {
  if (value && typeof value === 'object' && !Array.isArray(value) && !ArrayBuffer.isView(value)) {
    if (typeof value.type === 'string' && value.type !== '') return value.name ? `${value.type} '${value.name}'` : `${article(value.type)} ${value.type}`;
    const ours = classNameOf(value);
    if (ours) return `${article(ours)} ${ours}`;
  }
  return describeValue(value);
}

/**
 * Refuses a material with `transmission` (glTF's KHR_materials_transmission) for subsurface
 * scattering, naming it as the user named it: three draws such a material over a picture of the
 * opaque scene taken in the same draw, which the scene split leaves without the rest of the scene
 * (the box behind it vanished).
 * @param {import('three').Material} material
 * @param {string} who the function refusing it
 */
export function refuseTransmission(material, who) {
  if (!(material.transmission > 0)) return;
  throw new TypeError(`${who}: ${describe(material)} has transmission ${material.transmission}, which subsurface scattering cannot draw ` +
    '(what is behind it would vanish): set its transmission to 0 to make it scatter, or leave it as three draws it');
}
