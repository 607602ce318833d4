// What every GPU stage needs from the renderer: WebGL2 (multiple render targets, texelFetch) and
// renderable float colour targets (light is HDR: 8-bit targets would clamp and band it).
import { describeValue } from './parameterChecks.js';

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

/**
 * A value for error messages: a three.js object by its `type` and name, the constructor's name only
 * when nothing else says it (production builds minify those).
 */
export function describe(value) {
  if (value && typeof value === 'object' && !Array.isArray(value) && !ArrayBuffer.isView(value)) {
    if (typeof value.type === 'string' && value.type !== '') return value.name ? `${value.type} '${value.name}'` : `${/^[AEIOU]/.test(value.type) ? 'an' : 'a'} ${value.type}`;
    return value.constructor?.name ?? describeValue(value);
  }
  return describeValue(value);
}
