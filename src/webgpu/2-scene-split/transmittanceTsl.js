// Transmittance for the WebGPU node's materials, in TSL: a port of
// shaders/2-scene-split/transmittance.glsl (sssProfileTransmittance, sssLitSideFade,
// sssFaceNormal, sssTangentPlane, sssPlaneDepth, sssTransmittance, sssThicknessWorld) and of shaders/2-scene-split/material/transmittedLight.glsl, function by
// function under the same names, so a change to one GLSL function has one place to follow here.
// The uniforms have the WebGL chunk's names and are written by the same functions
// (src/2-scene-split/transmittanceModel.js's writeTransmittedLight: a TSL uniform holds `.value`
// as three's uniform objects do); the shading's constants come from its TRANSMITTED_LIGHT.
// Lengths in world units unless named Mm; positions and normals in the camera's view space.
import {
  BRDF_Lambert, Fn, If, abs, clamp, dFdx, dFdy, dot, float, floor, getDistanceAttenuation, ivec2, saturate, select, smoothstep,
  texture, textureLoad, textureSize, uniform, vec2, vec3, vec4,
} from 'three/tsl';
import {
  LIGHT_TYPES, SHEET, TRANSMITTED_LIGHT, lightUniformSlots, transmittanceUniformSlots,
} from '../../2-scene-split/transmittanceModel.js';
import { MATERIAL_OUTPUTS } from '../../4-compose/debugViews.js';
import { finite3, readProfile } from '../common/surfaceTsl.js';

/**
 * The TSL uniforms of one material's transmittance: the WebGL chunk's slots (lightUniformSlots,
 * transmittanceUniformSlots) as uniform nodes with the same names and first values, the two
 * tables as texture nodes, and the per-draw switches (sssTransmits 0/1, sssLightType: a
 * LIGHT_TYPES position, sssDebugOutput: a MATERIAL_OUTPUTS position).
 * @param {{ lightDepthMap: import('three').Texture, profileLookup: import('three').Texture }} textures
 */
export function transmittanceUniformNodes({ lightDepthMap, profileLookup }) {
  const slots = { ...lightUniformSlots(), ...transmittanceUniformSlots() };
  const nodes = Object.fromEntries(Object.entries(slots).filter(([, slot]) => slot.value !== null).map(([name, slot]) => [name, uniform(slot.value)]));
  return {
    ...nodes,
    sssLightDepthMap: texture(lightDepthMap),
    sssProfileLookup: texture(profileLookup),
    sssTransmits: uniform(0), // a float: WGSL uniforms hold no bool (written true/false, stored 1/0)
    sssLightType: uniform(0, 'int'),
    sssDebugOutput: uniform(0, 'int'),
    profileSize: profileLookup.image.width, // texels per row, fixed by ProfileLookup
  };
}

/**
 * transmittance.glsl's functions over `u` (transmittanceUniformNodes).
 * @param {ReturnType<typeof transmittanceUniformNodes>} u
 */
function transmittanceFunctions(u) {
  const readTable = readProfile(u.sssProfileLookup, u.profileSize);
  /** sssProfileTransmittance: T at the thickness in profile mm. */
  const profileTransmittance = (thicknessWorld) => readTable(0, thicknessWorld.mul(u.sssThicknessToProfileMm), u.sssTransmittanceRangeMm);
  /** sssLitSideFade: the lit side's fade-in over the first shrink. */
  const litSideFade = (thicknessWorld) => select(u.sssShrinkWorld.greaterThan(0), smoothstep(0, u.sssShrinkWorld, thicknessWorld), float(1));
  /**
   * sssTangentPlane: the point's own triangle as the map records it, in the light's view, from the
   * face normal (sssFaceNormal): { depthAt(ndc), facing, depth, texelWorld } (facing < 0: the far
   * side; texelWorld: a map texel's width at the point's light depth `depth`).
   */
  const tangentPlane = (viewPosition, viewFaceNormal, size) => {
    const point = u.sssViewToLightView.mul(vec4(viewPosition, 1)).xyz.toVar();
    const n = u.sssViewToLightView.mul(vec4(viewFaceNormal, 0)).xyz.normalize().toVar();
    const projection = u.sssLightProjection;
    const orthographic = projection.element(2).w.greaterThan(-0.5); // three's perspective matrices hold −1 there
    const scale = vec2(projection.element(0).x, projection.element(1).y).toVar();
    // Orthographic: rays along −z from ndc / scale off where ndc 0 is; perspective: from the light through ((ndc + offset) / scale, −1).
    const origin = vec2(projection.element(3).x, projection.element(3).y).negate().div(scale);
    const offset = vec2(projection.element(2).x, projection.element(2).y);
    const num = select(orthographic, vec3(point.z.negate().mul(n.z).add(dot(n.xy, origin.sub(point.xy))), n.xy.div(scale)), vec3(dot(n, point), 0, 0)).toVar();
    const den = select(orthographic, vec3(n.z, 0, 0), vec3(dot(n.xy, offset.div(scale)).sub(n.z), n.xy.div(scale))).toVar();
    const facing = select(orthographic, n.z, dot(n, point.negate().normalize())).toVar();
    const depth = point.z.negate().toVar();
    const texelWorld = select(orthographic, float(1), depth).mul(2).div(scale.x.mul(float(size.x)));
    /** sssPlaneDepth */
    const depthAt = (ndc) => dot(num, vec3(1, ndc)).div(dot(den, vec3(1, ndc)));
    return { depthAt, facing, depth, texelWorld };
  };
  /** Where the shrunk point falls in the map: { inside, texel } (texel: continuous, texel centres at .5 off). */
  const mapPosition = (viewPosition, viewVertexNormal, size) => {
    const shrunk = viewPosition.sub(viewVertexNormal.mul(u.sssShrinkWorld));
    const clip = u.sssLightProjection.mul(u.sssViewToLightView).mul(vec4(shrunk, 1)).toVar();
    const ndc = clip.xy.div(clip.w).toVar();
    const inside = clip.w.greaterThan(0).and(abs(ndc.x).lessThanEqual(1)).and(abs(ndc.y).lessThanEqual(1));
    // TSL's textures are top-down on both backends (three flips texelFetch on WebGL 2): row 0 is the light's NDC y = +1.
    const uv = vec2(ndc.x.mul(0.5).add(0.5), ndc.y.mul(-0.5).add(0.5));
    return { inside, texel: uv.mul(vec2(size)) };
  };
  /** A texel's centre as the light's NDC (TSL's textures are top-down: row 0 at NDC y = +1, as mapPosition reads them). */
  const ndcOf = (at, size) => vec2(at).add(0.5).div(vec2(size)).mul(vec2(2, -2)).add(vec2(-1, 1));
  /**
   * sssTransmittance: T through the point times the share of the light that entered, averaged over
   * the four map texels around it with their bilinear weights (sssTransmittanceAround: a texel on
   * the far side recording the point's own tangent plane is a sheet, of no thickness).
   */
  const transmittance = (viewPosition, viewVertexNormal, viewFaceNormal) => {
    const size = ivec2(textureSize(u.sssLightDepthMap, 0)).toVar();
    const { inside, texel } = mapPosition(viewPosition, viewVertexNormal, size);
    const plane = tangentPlane(viewPosition, viewFaceNormal, size);
    const farSide = plane.facing.lessThan(0);
    const tolerance = plane.texelWorld.mul(SHEET.TEXELS).toVar();
    const corner = texel.sub(0.5).toVar();
    const base = ivec2(floor(corner)).toVar();
    const f = corner.sub(vec2(base)).toVar();
    const light = vec3(0).toVar();
    for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]]) {
      const weight = (dx === 1 ? f.x : f.x.oneMinus()).mul(dy === 1 ? f.y : f.y.oneMinus());
      const at = clamp(base.add(ivec2(dx, dy)), ivec2(0), size.sub(1)).toVar();
      const recorded = textureLoad(u.sssLightDepthMap, at).rg.toVar(); // depth, entry cosine
      const thickness = plane.depth.sub(recorded.x).toVar();
      const sheet = farSide.and(abs(recorded.x.sub(plane.depthAt(ndcOf(at, size)))).lessThanEqual(tolerance)).toVar();
      // The share of the light that entered and comes through (the GLSL's `share`).
      const share = select(recorded.x.greaterThan(0).and(sheet), recorded.y.min(plane.facing.negate()),
        select(recorded.x.greaterThan(0).and(thickness.greaterThan(0)), recorded.y.mul(select(farSide, float(1), litSideFade(thickness))), float(0)));
      light.addAssign(profileTransmittance(select(sheet, float(0), thickness.max(0))).mul(weight.mul(share)));
    }
    return select(inside, light, vec3(0));
  };
  /** sssThicknessWorld: the thickness at the map's nearest texel, 0 on a sheet, −1 where nothing comes through (the debug view). */
  const thicknessWorld = (viewPosition, viewVertexNormal, viewFaceNormal) => {
    const size = ivec2(textureSize(u.sssLightDepthMap, 0)).toVar();
    const { inside, texel } = mapPosition(viewPosition, viewVertexNormal, size);
    const plane = tangentPlane(viewPosition, viewFaceNormal, size);
    const at = clamp(ivec2(floor(texel)), ivec2(0), size.sub(1)).toVar();
    const nearest = textureLoad(u.sssLightDepthMap, at).r.toVar();
    const thickness = plane.depth.sub(nearest).toVar();
    const sheet = plane.facing.lessThan(0).and(abs(nearest.sub(plane.depthAt(ndcOf(at, size)))).lessThanEqual(plane.texelWorld.mul(SHEET.TEXELS)));
    return select(inside.and(nearest.greaterThan(0)), select(sheet, float(0), select(thickness.greaterThan(0), thickness, float(-1))), float(-1));
  };
  return { transmittance, thicknessWorld };
}

/**
 * transmittedLight.glsl: the light arriving through the object from behind, to add to the direct
 * diffuse light before the blur, and the thickness in profile mm for the debug view. three's own
 * attenuation (getDistanceAttenuation, the spot cone's smoothstep) keeps it consistent with the
 * light's front-side contribution.
 * @param {ReturnType<typeof transmittanceUniformNodes>} u
 * @param {{ position, normal, albedo }} o view-space position and vertex (not bump-mapped)
 *   normal, the diffuse albedo
 * @returns {{ transmitted, thicknessMm }} vec3 and float nodes (0 where nothing is transmitted)
 */
export function transmittedLight(u, { position, normal, albedo }) {
  const { transmittance, thicknessWorld } = transmittanceFunctions(u);
  const result = Fn(() => {
    // sssFaceNormal: the triangle's normal turned to the camera, from the position's derivatives,
    // here in uniform control flow (WGSL refuses derivatives under a branch on a varying value).
    const faceDerivative = dFdx(position).cross(dFdy(position)).normalize().toVar();
    const face = select(dot(faceDerivative, position).greaterThan(0), faceDerivative.negate(), faceDerivative).toVar();
    const transmitted = vec3(0).toVar();
    const thicknessMm = float(0).toVar();
    If(u.sssTransmits.greaterThan(0.5), () => {
      const toLight = vec3(u.sssLightDirectionView).toVar();
      const attenuation = float(1).toVar();
      If(u.sssLightType.equal(LIGHT_TYPES.indexOf('spot')), () => {
        const lightVector = u.sssLightPositionView.sub(position).toVar();
        const lightDistance = lightVector.length().toVar();
        toLight.assign(lightVector.div(lightDistance));
        attenuation.assign(smoothstep(u.sssSpotConeCos, u.sssSpotPenumbraCos, dot(toLight, u.sssLightDirectionView))
          .mul(getDistanceAttenuation({ lightDistance, cutoffDistance: u.sssLightCutoffDistance, decayExponent: u.sssLightDecay })));
      });
      // Wrap lighting on the back side, where the light leaves (the entry cosine comes from the map), for light from behind the point as the camera sees it.
      const wrap = saturate(dot(normal.negate(), toLight).add(TRANSMITTED_LIGHT.WRAP_OFFSET))
        .mul(smoothstep(0, TRANSMITTED_LIGHT.FROM_BEHIND_RANGE, toLight.z.negate()));
      const weight = attenuation.mul(wrap).toVar();
      // Most of a front-lit surface gets none: the map and the profile are read only where some light comes through.
      If(weight.greaterThan(0), () => {
        const light = u.sssLightColor.mul(weight).mul(transmittance(position, normal, face)).mul(BRDF_Lambert({ diffuseColor: albedo })).toVar();
        // A degenerate light set-up must not turn the whole material NaN.
        transmitted.assign(select(finite3(light), light, vec3(0)));
      });
      If(u.sssDebugOutput.equal(MATERIAL_OUTPUTS.indexOf('thickness')), () => {
        thicknessMm.assign(thicknessWorld(position, normal, face).mul(u.sssThicknessToProfileMm));
      });
    });
    return vec4(transmitted, thicknessMm);
  })().toVar('sssTransmittedLight');
  return { transmitted: result.xyz, thicknessMm: result.w };
}
