// The chunks the surface passes share, in TSL: ports of shaders/common/finite.glsl,
// screenScale.glsl, surfaceSample.glsl, surfaceSlope.glsl, surfaceTap.glsl and
// profileLookup.glsl, function by function under the same names (sssFinite → finite3, ...), so a
// change to one GLSL chunk has one place to follow here. The numbers are samplingModel.js's.
// Each builder takes the pass's inputs ({ diffuse, surface }: texture nodes read with
// textureLoad), its uniforms and its compile-time switches (axis, followSurface, coverage).
import {
  abs, all, bitAnd, clamp, float, floatBitsToUint, int, ivec2, max, min, mix, notEqual, select, sqrt, texture as textureNode, textureLoad, uvec3, vec2, vec3, vec4,
} from 'three/tsl';
import { MAX_PLANE_SLOPE, MAX_SLOPE, PLANE_SLOPE_AGREEMENT, SLOPE_FADE } from '../../3-blur/samplingModel.js';

const EXPONENT = 0x7f800000;

/**
 * shaders/common/carriedDepth.glsl's SSS_DEPTH_ZERO: the alpha carrying a depth of 0 (normal, far
 * below any threshold), so a carried depth marks the mask by being non-zero whatever its sign.
 */
export const DEPTH_ZERO = 1e-30;

/** carriedDepth.glsl's sssCarriedDepth: the alpha that carries `depth` on the mask. */
export const carriedDepth = (depth) => select(depth.equal(0), float(DEPTH_ZERO), depth);

/**
 * A texture node for textureLoad alone: without the uv transform three applies to a texture node
 * made without uvs (a mat3 product and two conversions per fetch, for coordinates that are texels).
 * @param {import('three').Texture} texture
 */
export const texelTexture = (texture) => textureNode(texture).setUpdateMatrix(false);

/**
 * finite.glsl's sssFinite: no component NaN or Inf. WGSL has no isnan and compilers may fold
 * x != x away, so the exponent bits are read instead (all ones: Inf or NaN).
 * @param {import('three/tsl').ShaderNodeObject} c vec3
 */
export const finite3 = (c) => all(notEqual(bitAnd(floatBitsToUint(vec3(c)), uvec3(EXPONENT)), uvec3(EXPONENT)));

/** The same for one float (the footprint table marks its last footprint with +Inf). */
export const finite1 = (x) => bitAnd(floatBitsToUint(float(x)), EXPONENT >>> 0).notEqual(EXPONENT >>> 0);

/** One component of a vec2/ivec2 along the pass's axis (0: x, 1: y). */
export const along = (v, axis) => (axis === 0 ? v.x : v.y);

/** `pixel` with its component along `axis` replaced by `value` (an int node). */
export const withAlong = (pixel, axis, value) => (axis === 0 ? ivec2(value, pixel.y) : ivec2(pixel.x, value));

/**
 * screenScale.glsl: how large a profile millimetre is on screen. `surface.y` is the material's
 * widthMm here (see ../2-scene-split/attachments.js), times `mmToWorld` (1 / worldUnitInMm) the
 * world units per profile mm of the GLSL.
 * @param {{ perspective, projectionScale, resolution, mmToWorld }} u uniforms
 */
export function screenScale(u) {
  // `perspective`: 1 for a perspective camera, 0 for an orthographic one (a float: WGSL uniforms hold no bool).
  const viewDepth = (surface) => select(u.perspective.greaterThan(0.5), surface.x, float(1));
  return {
    viewDepth,
    /** Pixels one profile millimetre spans along x and y. */
    pixelsPerMm: (surface) => vec2(surface.y.mul(u.mmToWorld)).mul(u.projectionScale).div(viewDepth(surface).mul(2)).mul(u.resolution),
    /** World units one pixel spans across the view at this depth, along x and y. */
    pixelWorld: (surface) => vec2(viewDepth(surface).mul(2)).div(u.projectionScale.mul(u.resolution)),
  };
}

/**
 * surfaceSample.glsl: reading the surface and the diffuse light at a texel, coverage divided out
 * when the inputs were resolved from MSAA (`coverage`).
 */
export function surfaceSample({ diffuse, surface, coverage, carriesDepth = false }) {
  const uncovered = (value, c) => (coverage ? select(c.greaterThan(0), value.div(c), vec2(0)) : value);
  const surfaceAt = (texel) => {
    const s = textureLoad(surface, texel).xy;
    return coverage ? uncovered(s, textureLoad(diffuse, texel).a) : s;
  };
  /** A light texel's colour (`rgb`) at a pixel of coverage `cover`: 0 where not finite, the coverage divided out. */
  const colourOf = (rgb, cover) => {
    const colour = select(finite3(rgb), rgb, vec3(0));
    return (coverage ? select(cover.greaterThan(0), colour.div(cover), colour) : colour).toVar();
  };
  /**
   * The pixel a surface pass shades: { colour, coverage, surface() } (see SssCentre), and its
   * texel's `rgb` as read; `surface()` reads the surface where it is called (on the mask only: a
   * pixel off it needs none).
   */
  const centreAt = (pixel) => {
    const light = textureLoad(diffuse, pixel).toVar();
    // A carried depth (carriedDepth.glsl) marks the mask by being non-zero; the coverage is 1 there.
    const cover = (carriesDepth ? select(light.a.notEqual(0), float(1), float(0)) : select(light.a.greaterThan(0), light.a, float(0))).toVar();
    return { colour: colourOf(light.rgb, cover), coverage: cover, surface: () => uncovered(textureLoad(surface, pixel).xy, cover).toVar(), rgb: light.rgb };
  };
  /** A surface pass's output: premultiplied by the centre's coverage, as its input was. */
  const covered = (colour, c) => vec4(vec3(colour).mul(c), c);
  return { uncovered, surfaceAt, colourOf, centreAt, covered };
}

/**
 * surfaceSlope.glsl's sssFadeBelow: 1 up to limit / SLOPE_FADE, 0 from the limit, linear between
 * (a limit of 0: 1 at 0 only).
 */
export function fadeBelow(value, limit) {
  const band = limit.mul(1 - 1 / SLOPE_FADE);
  return select(band.greaterThan(0), clamp(limit.sub(value).div(band), 0, 1), select(value.greaterThan(0), float(0), float(1)));
}

/**
 * surfaceSlope.glsl: the surface's depth slope at a pixel along the axis, world units per pixel;
 * each of its limits fades over a band (fadeBelow).
 * @param {ReturnType<typeof surfaceSample>} sample
 * @param {{ resolution }} u
 * @param {0|1} axis
 */
export function surfaceSlope(sample, u, axis) {
  return (pixel, surface, pixelWorld) => {
    const at = along(pixel, axis);
    const beforeAt = max(at.sub(1), 0);
    const afterAt = min(at.add(1), int(along(u.resolution, axis)).sub(1));
    const surfaceBefore = sample.surfaceAt(withAlong(pixel, axis, beforeAt));
    const surfaceAfter = sample.surfaceAt(withAlong(pixel, axis, afterAt));
    const slopeBefore = surface.x.sub(surfaceBefore.x).toVar();
    const slopeAfter = surfaceAfter.x.sub(surface.x).toVar();
    const onBefore = select(surfaceBefore.y.greaterThan(0).and(beforeAt.notEqual(at)), float(1), float(0));
    const onAfter = select(surfaceAfter.y.greaterThan(0).and(afterAt.notEqual(at)), float(1), float(0));
    const steeper = max(abs(slopeBefore), abs(slopeAfter)).toVar();
    const plane = onBefore.mul(onAfter)
      .mul(fadeBelow(abs(slopeAfter.sub(slopeBefore)), steeper.mul(PLANE_SLOPE_AGREEMENT)))
      .mul(fadeBelow(steeper, pixelWorld.mul(MAX_PLANE_SLOPE)));
    const weightBefore = onBefore.mul(fadeBelow(abs(slopeBefore), pixelWorld.mul(MAX_SLOPE))).toVar();
    const weightAfter = onAfter.mul(fadeBelow(abs(slopeAfter), pixelWorld.mul(MAX_SLOPE))).toVar();
    // Their mean where both count; below a sum of 1 their weighted sum, which fades to 0 with them.
    const oneSided = weightBefore.mul(slopeBefore).add(weightAfter.mul(slopeAfter)).div(max(weightBefore.add(weightAfter), 1));
    return mix(oneSided, slopeBefore.add(slopeAfter).mul(0.5), plane);
  };
}

/**
 * surfaceTap.glsl: the rule every tap follows. Returns { weight, colours } for a texel whose depth
 * the centre's plane predicts to be `expectedDepth`: the rule's weight, and the colour of each of
 * `lights` there ('lerp': each moved towards its own centre, `centres[k]`). One light is the
 * one-kernel blur; several are the isotropic blur's groups (kernelGroups.js), whose texels share
 * the coverage in their alphas, so the rule is taken once for all of them.
 * @param {ReturnType<typeof surfaceSample>} sample
 * @param {{ depthFalloff }} u
 * @param {{ lights: object[], surface, followSurface: 'off'|'drop'|'lerp', coverage: boolean }} inputs
 *   lights: texture nodes of the light to blur (a: the mask, the same in each)
 */
export function surfaceTap(sample, u, { lights, surface, followSurface, coverage, carriesDepth = false }) {
  return (texel, expectedDepth, centres) => {
    const texels = lights.map((light) => textureLoad(light, texel).toVar());
    const alpha = texels[0].a;
    const kept = (carriesDepth ? alpha.notEqual(0) : alpha.greaterThan(0)).and(finite3(texels.slice(1).reduce((sum, t) => sum.add(t.rgb), texels[0].rgb)));
    let weight = coverage ? alpha : float(1);
    let farness = null;
    if (followSurface !== 'off') {
      // The light carrying the depth in its alpha: one fetch a texel, not two (carriedDepth.glsl).
      const depth = carriesDepth ? alpha : sample.uncovered(textureLoad(surface, texel).xy, alpha).x;
      farness = clamp(abs(depth.sub(expectedDepth)).mul(u.depthFalloff), 0, 1);
      if (followSurface === 'drop') weight = weight.mul(farness.oneMinus());
    }
    // Off the mask or not finite: weight 0 and colour 0 (0 × NaN would still be NaN).
    const colours = texels.map((t, k) => {
      let colour = coverage ? t.rgb.div(alpha) : t.rgb;
      if (followSurface === 'lerp') colour = mix(colour, centres[k], farness);
      return select(kept, colour, vec3(0));
    });
    return { weight: select(kept, weight, float(0)), colours };
  };
}

/**
 * profileLookup.glsl's sssReadProfile: a ProfileLookup row at x mm, square-root spaced, linear
 * between texels (32-bit float filtering is an extension), held past the range.
 * @param {import('three/tsl').ShaderNodeObject} table texture node of ProfileLookup.texture
 * @param {number} size its texels per row
 */
export function readProfile(table, size) {
  return (row, xMm, rangeMm) => {
    const position = sqrt(clamp(xMm.div(rangeMm), 0, 1)).mul(size - 1).toVar();
    const below = min(int(position), size - 2);
    const fraction = position.sub(float(below));
    const a = textureLoad(table, ivec2(below, row)).rgb;
    const b = textureLoad(table, ivec2(below.add(1), row)).rgb;
    return mix(a, b, fraction);
  };
}
