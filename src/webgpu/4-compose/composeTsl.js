// Stage 4 for WebGPURenderer: the scattered diffuse light back on top of the rest of the scene's
// light, linear HDR, before three's output (tone mapping, colour space). A port of
// shaders/4-compose/compose.frag.glsl's DEBUG_VIEW_FINAL branch: pixels that are not subsurface
// keep exactly what their material wrote; the result is never NaN or Inf.
import { Fn, select, vec3, vec4 } from 'three/tsl';
import { finite3 } from '../3-blur/surfaceTsl.js';

/**
 * @param {object} o texture nodes sampled at the output's pixel
 * @param {object} o.colour the pass's colour (specular + emissive of subsurface pixels, full colour elsewhere)
 * @param {object} o.unscattered the diffuse light before the blur; a: the mask
 * @param {object} o.scattered the blurred diffuse light (premultiplied by its coverage, like the colour)
 */
export function composeNode({ colour, unscattered, scattered }) {
  return Fn(() => {
    const light = vec4(colour).toVar();
    const subsurface = unscattered.a.greaterThan(0);
    const result = light.rgb.add(select(subsurface, vec3(scattered.rgb), vec3(0))).toVar();
    // Never hand NaN or Inf to tone mapping.
    return vec4(select(finite3(result), result, vec3(0)), light.a);
  })();
}
