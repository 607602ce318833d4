// The node's options in one place: what subsurfaceScattering(scenePass, { ... }) accepts (each
// also a property of the node), their defaults (the WebGL pipeline's, src/options.js) and their checks (the WebGL
// pipeline's messages: test/node/webgpu/webgpuBadInputs.test.js runs the bad-input table on both).
import { METHODS, PIPELINE_DEFAULTS } from '../options.js';
import { checkOneOf } from '../support/parameterChecks.js';

/** The methods the node has: the WebGL path's default ('footprint'). */
export const NODE_METHODS = Object.freeze(['footprint']);

/** What subsurfaceScattering(scenePass, { ... }) accepts, with its defaults (the WebGL pipeline's). */
export const NODE_DEFAULTS = Object.freeze({
  worldUnitInMm: PIPELINE_DEFAULTS.worldUnitInMm,
  profile: PIPELINE_DEFAULTS.profile,
  method: PIPELINE_DEFAULTS.method,
  samples: PIPELINE_DEFAULTS.samples,
  kernelGroups: /** @type {'auto'|number} */ (PIPELINE_DEFAULTS.kernelGroups),
  strength: /** @type {number[]} */ ([1, 1, 1]),
  followSurface: PIPELINE_DEFAULTS.followSurface,
  depthThresholdMm: PIPELINE_DEFAULTS.depthThresholdMm,
  foreshortening: PIPELINE_DEFAULTS.foreshortening,
  /** The light shining through thin parts (transmittance); null: none. */
  light: /** @type {import('three').SpotLight|import('three').DirectionalLight|null} */ (PIPELINE_DEFAULTS.light),
  lightDepthSize: /** @type {number} */ (PIPELINE_DEFAULTS.lightDepthSize),
});

/** The WebGL pipeline's methods are accepted by name; the node has 'footprint' only (the others validate the WebGL path). */
export function checkMethod(method) {
  checkOneOf('method', method, METHODS);
  if (!NODE_METHODS.includes(method)) {
    throw new RangeError(`subsurfaceScattering: method '${method}' is not available on the node (only ${NODE_METHODS.map((m) => `'${m}'`).join(', ')}; the WebGL pipeline has the others, for validation)`);
  }
  return method;
}
