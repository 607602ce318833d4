// Stage 4 for WebGPURenderer: the scattered diffuse light back on top of the rest of the scene's
// light, linear HDR, before three's output (tone mapping, colour space). A port of
// shaders/4-compose/compose.frag.glsl: pixels that are not subsurface keep exactly what their
// material wrote; the result is never NaN or Inf. The debug views (src/4-compose/debugViews.js's,
// by name) are a uniform here, so switching one rebuilds nothing; the thickness and transmittance
// views read what the materials wrote into the diffuse attachment instead of the light (the node
// tells them: src/webgpu/2-scene-split/subsurfaceNodeMaterial.js).
import { Fn, If, bool, float, ivec2, mix, screenCoordinate, select, textureLoad, uniform, vec2, vec3, vec4 } from 'three/tsl';
import { DEBUG_VIEW, DEBUG_VIEWS } from '../../4-compose/debugViews.js';
import { finite3 } from '../common/surfaceTsl.js';

/** The uniform the compose reads: a view's position in DEBUG_VIEWS, compared by name below. */
export const debugViewUniform = () => uniform(DEBUG_VIEWS.indexOf(DEBUG_VIEW.FINAL), 'int');
const is = (u, view) => u.equal(DEBUG_VIEWS.indexOf(view));

/**
 * @param {object} o texture nodes read at the output's pixel (texelFetch in the GLSL: a filtered
 *   sample a hair off the texel centre gave background pixels a sliver of a neighbour's mask on
 *   WebGPU), and the view's uniforms
 * @param {object} o.colour the pass's colour (specular + emissive of subsurface pixels, full colour elsewhere)
 * @param {object} o.unscattered the diffuse light before the blur; a: the mask
 * @param {object} o.scattered the blurred diffuse light (premultiplied by its coverage, like the
 *   colour; a: the coverage, 0 off the mask), or the unscattered light where the blur is skipped
 * @param {object} o.surface r: linear view depth (world units)
 * @param {object} o.view debugViewUniform()
 * @param {object} o.depthRange world units mapped to white in the depth view (a float uniform)
 * @param {object} o.thicknessRangeMm profile mm mapped to white in the thickness view (a float uniform)
 * @param {object} o.share the share of the scattered light shown, the rest unblurred (a float
 *   uniform: the blur fading in, src/3-blur/blurPlan.js)
 * @param {object} o.box the subsurface pixels' box (a vec4 uniform: x0, y0, x1, y1, pixels from
 *   the top left): outside it only the colour is read, and inside it the mask comes from the
 *   scattered light's alpha (the unblurred light is read only where it is shown: the blur fading
 *   in, the thickness and transmittance views), as compose.frag.glsl's maskBox
 * @param {object} o.lightShown 1 with a light, 0 without (a float uniform): the thickness and
 *   transmittance views then show none, as on the WebGL pipeline, whose materials write 0 there
 */
export function composeNode({ colour, unscattered, scattered, surface, view, depthRange, thicknessRangeMm, share, box, lightShown }) {
  return Fn(() => {
    const pixel = ivec2(screenCoordinate.xy).toVar();
    const light = textureLoad(colour, pixel).toVar();
    const subsurface = bool(false).toVar();
    const diffuse = vec3(0).toVar();
    const before = vec3(0).toVar(); // the unblurred light, where it is read
    const at = vec2(pixel);
    If(at.x.greaterThanEqual(box.x).and(at.y.greaterThanEqual(box.y)).and(at.x.lessThan(box.z)).and(at.y.lessThan(box.w)), () => {
      const blurred = textureLoad(scattered, pixel).toVar();
      subsurface.assign(blurred.a.greaterThan(0));
      If(subsurface, () => {
        diffuse.assign(blurred.rgb);
        If(share.lessThan(1).or(is(view, DEBUG_VIEW.THICKNESS)).or(is(view, DEBUG_VIEW.TRANSMITTANCE)), () => {
          before.assign(textureLoad(unscattered, pixel).rgb);
          diffuse.assign(mix(before, blurred.rgb, share));
        });
      });
    });
    const result = light.rgb.add(diffuse).toVar();
    If(is(view, DEBUG_VIEW.DIFFUSE), () => { result.assign(diffuse); });
    If(is(view, DEBUG_VIEW.SPECULAR), () => { result.assign(select(subsurface, light.rgb, vec3(0))); });
    If(is(view, DEBUG_VIEW.MASK), () => { result.assign(vec3(select(subsurface, float(1), float(0)))); });
    If(is(view, DEBUG_VIEW.DEPTH), () => {
      const viewDepth = textureLoad(surface, pixel).r;
      result.assign(vec3(select(viewDepth.greaterThan(0), viewDepth.div(depthRange).oneMinus(), float(0))));
    });
    If(is(view, DEBUG_VIEW.THICKNESS), () => { result.assign(vec3(before.r.div(thicknessRangeMm)).mul(lightShown)); });
    If(is(view, DEBUG_VIEW.TRANSMITTANCE), () => { result.assign(before.mul(lightShown)); });
    // Never hand NaN or Inf to tone mapping.
    return vec4(select(finite3(result), result, vec3(0)), light.a);
  })();
}
