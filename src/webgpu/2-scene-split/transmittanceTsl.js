// Transmittance for the WebGPU node's materials, in TSL: a port of
// shaders/2-scene-split/transmittance.glsl (sssProfileTransmittance, sssLitSideFade,
// sssFaceNormal, sssTangentPlane, sssPlaneDepth, sssTransmittanceAround, sssTransmittanceOfFace,
// sssPointTransmittanceFrom, sssThicknessWorldFrom) and of
// shaders/2-scene-split/material/pars.glsl's sssTransmittedFrom and transmittedLight.glsl,
// function by function under the same names, so a change to one GLSL function has one place to
// follow here. The uniforms have the WebGL chunk's names, one set per light (each light's map,
// matrices and shading), and are written by the same functions
// (src/2-scene-split/transmittanceModel.js's writeTransmittedLight, once per light: a TSL uniform
// holds `.value` as three's uniform objects do); the shading's constants come from its
// TRANSMITTED_LIGHT and SHEET. Lengths in world units unless named Mm; positions and normals in
// the camera's view space.
import {
  BRDF_Lambert, Fn, If, abs, clamp, cross, dFdx, dFdy, dot, float, floor, getDistanceAttenuation, int, ivec2, mat4, normalize, saturate,
  select, smoothstep, textureLoad, textureSize, uniform, vec2, vec3, vec4,
} from 'three/tsl';
import {
  LIGHT_TYPES, SHEET, TRANSMITTED_LIGHT, lightUniformSlots, transmittanceUniformSlots,
} from '../../2-scene-split/transmittanceModel.js';
import { POINT_FACES } from '../../1-light-depth/LightDepthView.js';
import { MATERIAL_OUTPUTS } from '../../4-compose/debugViews.js';
import { finite3, readProfile, texelTexture } from '../common/surfaceTsl.js';

/** The slots' uniforms each light has of its own (the rest, the material's settings, all lights share). */
const PER_LIGHT = Object.freeze([
  ...Object.keys(lightUniformSlots()), 'sssLightDepthMap', 'sssViewToLightView', 'sssLightProjection', 'sssLightCube',
]);

/** The WebGL chunk's slots, fresh (their vectors and matrices become the uniform nodes' values). */
const freshSlots = () => ({ ...lightUniformSlots(), ...transmittanceUniformSlots(), sssLightCube: { value: 0 } }); // floats: WGSL uniforms hold no bool (written true/false, stored 1/0)

/** Fresh slots of `names` as TSL uniform nodes with their first values (the textures apart). */
function uniformsOf(names) {
  const slots = freshSlots();
  return Object.fromEntries(names.filter((name) => slots[name].value !== null).map((name) => [name, uniform(slots[name].value)]));
}

/**
 * The TSL uniforms of one material's transmittance from `lightDepthMaps.length` lights: the WebGL
 * chunk's slots (lightUniformSlots, transmittanceUniformSlots) as uniform nodes with the same
 * names and first values, the tables as texture nodes. `lights` holds one slot per light, each
 * the shared uniforms and its own (PER_LIGHT; sssTransmits 0/1 and sssLightType, a LIGHT_TYPES
 * position), which is what writeTransmittedLight writes for one light; the shared sssTransmits is
 * whether any light transmits, sssDebugOutput a MATERIAL_OUTPUTS position.
 * @param {{ lightDepthMaps: import('three').Texture[], profileLookup: import('three').Texture }} textures
 */
export function transmittanceUniformNodes({ lightDepthMaps, profileLookup }) {
  const shared = {
    ...uniformsOf(Object.keys(freshSlots()).filter((name) => !PER_LIGHT.includes(name))),
    sssProfileLookup: texelTexture(profileLookup),
    sssTransmits: uniform(0),
    sssDebugOutput: uniform(0, 'int'),
    profileSize: profileLookup.image.width, // texels per row, fixed by ProfileLookup
  };
  const lights = lightDepthMaps.map((map) => ({
    ...shared,
    ...uniformsOf(PER_LIGHT), // each light its own vectors and matrices
    sssLightDepthMap: texelTexture(map),
    sssTransmits: uniform(0),
    sssLightType: uniform(0, 'int'),
  }));
  return { ...shared, lights };
}

/**
 * transmittance.glsl's functions over one light's slot `u` (transmittanceUniformNodes' lights).
 * @param {ReturnType<typeof transmittanceUniformNodes>['lights'][number]} u
 */
function transmittanceFunctions(u) {
  const readTable = readProfile(u.sssProfileLookup, u.profileSize);
  const map = u.sssLightDepthMap;
  /** sssProfileTransmittance: T at the thickness in profile mm. */
  const profileTransmittance = (thicknessWorld) => readTable(0, thicknessWorld.mul(u.sssThicknessToProfileMm), u.sssTransmittanceRangeMm);
  /** sssLitSideFade: the lit side's fade-in over the first shrink. */
  const litSideFade = (thicknessWorld) => select(u.sssShrinkWorld.greaterThan(0), smoothstep(0, u.sssShrinkWorld, thicknessWorld), float(1));
  /**
   * sssTangentPlane: the point's own triangle as the map records it, for a point and face normal
   * in a light view (its axis −z) and that view's `projection` (a mat4 node), over a map (or face)
   * of `size` texels: { depthAt(ndc) (sssPlaneDepth), facing (< 0: the far side), depth (the
   * point's light depth), texelWorld (a texel's width at that depth) }.
   */
  const tangentPlane = (point, faceNormal, projection, size) => {
    const n = normalize(faceNormal).toVar();
    const orthographic = projection.element(2).w.greaterThan(-0.5); // three's perspective matrices hold −1 there
    const scale = vec2(projection.element(0).x, projection.element(1).y).toVar();
    // Orthographic: rays along −z from ndc / scale off where ndc 0 is; perspective: from the light through ((ndc + offset) / scale, −1).
    const origin = vec2(projection.element(3).x, projection.element(3).y).negate().div(scale);
    const offset = vec2(projection.element(2).x, projection.element(2).y);
    const num = select(orthographic, vec3(point.z.negate().mul(n.z).add(dot(n.xy, origin.sub(point.xy))), n.xy.div(scale)), vec3(dot(n, point), 0, 0)).toVar();
    const den = select(orthographic, vec3(n.z, 0, 0), vec3(dot(n.xy, offset.div(scale)).sub(n.z), n.xy.div(scale))).toVar();
    const facing = select(orthographic, n.z, dot(n, point.negate().normalize())).toVar();
    const depth = point.z.negate().toVar();
    const texelWorld = select(orthographic, float(1), depth).mul(2).div(scale.x.mul(float(size.x))).toVar();
    const depthAt = (ndc) => dot(num, vec3(1, ndc)).div(dot(den, vec3(1, ndc)));
    return { depthAt, facing, depth, texelWorld };
  };
  /** A texel's centre as the light's NDC (TSL's textures are top-down: row 0 at NDC y = +1, as the reads below take them). */
  const ndcOf = (at, size) => vec2(at).add(0.5).div(vec2(size)).mul(vec2(2, -2)).add(vec2(-1, 1));
  /**
   * sssTransmittanceAround: T times the share of the light that entered, over the four texels
   * around `texel` (continuous, texel centres at integers) of the map's part from `origin`, `size`
   * texels (a texel beyond its edge is its edge's), for a point on `plane` (tangentPlane): a texel
   * on the far side recording the point's own surface is a sheet, of no thickness.
   */
  const transmittanceAround = (texel, origin, size, plane) => {
    const base = ivec2(floor(texel)).toVar();
    const f = texel.sub(vec2(base)).toVar();
    const farSide = plane.facing.lessThan(0);
    const tolerance = plane.texelWorld.mul(SHEET.TEXELS).toVar();
    const light = vec3(0).toVar();
    for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]]) {
      const weight = (dx === 1 ? f.x : f.x.oneMinus()).mul(dy === 1 ? f.y : f.y.oneMinus());
      const at = clamp(base.add(ivec2(dx, dy)), ivec2(0), size.sub(1)).toVar();
      const recorded = textureLoad(map, origin.add(at)).rg.toVar(); // depth, entry cosine
      const thickness = plane.depth.sub(recorded.x).toVar();
      const sheet = farSide.and(abs(recorded.x.sub(plane.depthAt(ndcOf(at, size)))).lessThanEqual(tolerance)).toVar();
      // The share of the light that entered and comes through (the GLSL's `share`).
      const share = select(recorded.x.greaterThan(0).and(sheet), recorded.y.min(plane.facing.negate()),
        select(recorded.x.greaterThan(0).and(thickness.greaterThan(0)), recorded.y.mul(select(farSide, float(1), litSideFade(thickness))), float(0)));
      light.addAssign(profileTransmittance(select(sheet, float(0), thickness.max(0))).mul(weight.mul(share)));
    }
    return light;
  };
  /**
   * Where a map of `size` texels from the light's one view sees the point `shrunk` (view space):
   * { inside, uv }. TSL's textures are top-down on both backends (three flips texelFetch on
   * WebGL 2): row 0 is the light's NDC y = +1.
   */
  const mapPosition = (shrunk) => {
    const clip = u.sssLightProjection.mul(u.sssViewToLightView).mul(vec4(shrunk, 1)).toVar();
    const ndc = clip.xy.div(clip.w).toVar();
    const inside = clip.w.greaterThan(0).and(abs(ndc.x).lessThanEqual(1)).and(abs(ndc.y).lessThanEqual(1));
    return { inside, uv: vec2(ndc.x.mul(0.5).add(0.5), ndc.y.mul(-0.5).add(0.5)) };
  };
  const shrunkOf = (viewPosition, viewVertexNormal) => viewPosition.sub(viewVertexNormal.mul(u.sssShrinkWorld));
  /** The point and its face normal in the light's view. */
  const inLightView = (viewPosition, viewFaceNormal) => [
    u.sssViewToLightView.mul(vec4(viewPosition, 1)).xyz.toVar(), u.sssViewToLightView.mul(vec4(viewFaceNormal, 0)).xyz,
  ];
  /** sssTransmittanceOfFace: through the map of one view (a spot or directional light, an aimed point light). */
  const transmittanceFrom = (viewPosition, viewVertexNormal, viewFaceNormal) => {
    const size = ivec2(textureSize(map, 0)).toVar();
    const { inside, uv } = mapPosition(shrunkOf(viewPosition, viewVertexNormal));
    const plane = tangentPlane(...inLightView(viewPosition, viewFaceNormal), u.sssLightProjection, size);
    return select(inside, transmittanceAround(uv.mul(vec2(size)).sub(0.5), ivec2(0), size, plane), vec3(0));
  };
  /** A 90° face's projection (sssPointTransmittanceFrom's). */
  const FACE_PROJECTION = mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -1, 0);
  /**
   * sssPointTransmittanceFrom: through a point light's six faces (LightDepthView's POINT_FACES,
   * each drawn into its viewport, rows from the top here as the reads are): the face of the shrunk
   * point's largest axis, its depth the distance along that axis.
   */
  const pointTransmittanceFrom = (viewPosition, viewVertexNormal, viewFaceNormal) => {
    const shrunk = u.sssViewToLightView.mul(vec4(shrunkOf(viewPosition, viewVertexNormal), 1)).xyz.toVar();
    const a = abs(shrunk).toVar();
    const onX = a.x.greaterThanEqual(a.y).and(a.x.greaterThanEqual(a.z)).toVar();
    const onY = onX.not().and(a.y.greaterThanEqual(a.z)).toVar();
    const negative = select(onX, shrunk.x, select(onY, shrunk.y, shrunk.z)).lessThan(0).toVar();
    const s = select(negative, float(-1), float(1));
    const forward = select(onX, vec3(s, 0, 0), select(onY, vec3(0, s, 0), vec3(0, 0, s))).toVar();
    const up = select(onY, vec3(0, 0, 1), vec3(0, 1, 0));
    const x = normalize(cross(up, forward.negate())).toVar();
    const y = cross(forward.negate(), x).toVar();
    const ndc = vec2(dot(shrunk, x), dot(shrunk, y)).div(dot(shrunk, forward)).toVar();
    // The face's view space: x, y, and −forward as z (transpose(mat3(x, y, −forward)) as rows).
    const toFace = (v) => vec3(dot(v, x), dot(v, y), dot(v, forward.negate()));
    const [point, normal] = inLightView(viewPosition, viewFaceNormal);
    const face = select(onX, int(0), select(onY, int(2), int(4))).add(select(negative, int(1), int(0))).toVar();
    const size = ivec2(textureSize(map, 0)).div(ivec2(POINT_FACES.ACROSS, POINT_FACES.UP)).toVar();
    const plane = tangentPlane(toFace(point).toVar(), toFace(normal), FACE_PROJECTION, size);
    const uv = vec2(ndc.x.mul(0.5).add(0.5), ndc.y.mul(-0.5).add(0.5));
    return transmittanceAround(uv.mul(vec2(size)).sub(0.5), ivec2(face.mod(POINT_FACES.ACROSS), face.div(POINT_FACES.ACROSS)).mul(size), size, plane);
  };
  /** sssThicknessWorldFrom: the thickness at the map's nearest texel, 0 on a sheet, −1 where nothing comes through (the debug view). */
  const thicknessWorldFrom = (viewPosition, viewVertexNormal, viewFaceNormal) => {
    const size = ivec2(textureSize(map, 0)).toVar();
    const { inside, uv } = mapPosition(shrunkOf(viewPosition, viewVertexNormal));
    const plane = tangentPlane(...inLightView(viewPosition, viewFaceNormal), u.sssLightProjection, size);
    const at = clamp(ivec2(floor(uv.mul(vec2(size)))), ivec2(0), size.sub(1)).toVar();
    const nearest = textureLoad(map, at).r.toVar();
    const thickness = plane.depth.sub(nearest).toVar();
    const sheet = plane.facing.lessThan(0).and(abs(nearest.sub(plane.depthAt(ndcOf(at, size)))).lessThanEqual(plane.texelWorld.mul(SHEET.TEXELS)));
    return select(inside.and(nearest.greaterThan(0)), select(sheet, float(0), select(thickness.greaterThan(0), thickness, float(-1))), float(-1));
  };
  return { transmittanceFrom, pointTransmittanceFrom, thicknessWorldFrom };
}

/**
 * pars.glsl's sssTransmittedFrom: light `u`'s light through the point, before the albedo: T and
 * the entry cosine from its map, its colour and attenuation (three's getDistanceAttenuation and
 * the spot cone's smoothstep, consistent with its front-side light), and wrap lighting on the
 * back side where the light leaves, for light from behind the point as the camera sees it. The
 * map is read only where some light comes through. `face`: sssFaceNormal's, found in uniform
 * control flow.
 */
function transmittedFrom(u, position, normal, face) {
  const { transmittanceFrom, pointTransmittanceFrom } = transmittanceFunctions(u);
  const light = vec3(0).toVar();
  If(u.sssTransmits.greaterThan(0.5), () => {
    const toLight = vec3(u.sssLightDirectionView).toVar();
    const attenuation = float(1).toVar();
    If(u.sssLightType.notEqual(LIGHT_TYPES.indexOf('directional')), () => {
      const lightVector = u.sssLightPositionView.sub(position).toVar();
      const lightDistance = lightVector.length().toVar();
      toLight.assign(lightVector.div(lightDistance));
      attenuation.assign(getDistanceAttenuation({ lightDistance, cutoffDistance: u.sssLightCutoffDistance, decayExponent: u.sssLightDecay }));
      If(u.sssLightType.equal(LIGHT_TYPES.indexOf('spot')), () => {
        attenuation.mulAssign(smoothstep(u.sssSpotConeCos, u.sssSpotPenumbraCos, dot(toLight, u.sssLightDirectionView)));
      });
    });
    const wrap = saturate(dot(normal.negate(), toLight).add(TRANSMITTED_LIGHT.WRAP_OFFSET))
      .mul(smoothstep(0, TRANSMITTED_LIGHT.FROM_BEHIND_RANGE, toLight.z.negate()));
    const weight = attenuation.mul(wrap).toVar();
    If(weight.greaterThan(0), () => {
      const through = vec3(0).toVar();
      If(u.sssLightCube.greaterThan(0.5), () => { through.assign(pointTransmittanceFrom(position, normal, face)); })
        .Else(() => { through.assign(transmittanceFrom(position, normal, face)); });
      light.assign(u.sssLightColor.mul(weight).mul(through));
    });
  });
  return light;
}

/**
 * transmittedLight.glsl: the light arriving through the object from behind, from each light, to
 * add to the direct diffuse light before the blur, and the thickness in profile mm for the debug
 * view (the first light's; none from a point light's six faces).
 * @param {ReturnType<typeof transmittanceUniformNodes>} u
 * @param {{ position, normal, albedo }} o view-space position and vertex (not bump-mapped)
 *   normal, the diffuse albedo
 * @returns {{ transmitted, thicknessMm }} vec3 and float nodes (0 where nothing is transmitted)
 */
export function transmittedLight(u, { position, normal, albedo }) {
  const result = Fn(() => {
    // sssFaceNormal: the triangle's normal turned to the camera, from the position's derivatives,
    // here in uniform control flow (WGSL refuses derivatives under a branch on a varying value).
    const faceDerivative = dFdx(position).cross(dFdy(position)).normalize().toVar();
    const face = select(dot(faceDerivative, position).greaterThan(0), faceDerivative.negate(), faceDerivative).toVar();
    const transmitted = vec3(0).toVar();
    const thicknessMm = float(0).toVar();
    If(u.sssTransmits.greaterThan(0.5), () => {
      // One call per light (the graph is built for the node's lights: their number rebuilds it).
      for (const light of u.lights) transmitted.addAssign(transmittedFrom(light, position, normal, face));
      const light = transmitted.mul(BRDF_Lambert({ diffuseColor: albedo })).toVar();
      // A degenerate light set-up must not turn the whole material NaN.
      transmitted.assign(select(finite3(light), light, vec3(0)));
      const [first] = u.lights;
      If(u.sssDebugOutput.equal(MATERIAL_OUTPUTS.indexOf('thickness')).and(first.sssLightCube.lessThan(0.5)), () => {
        thicknessMm.assign(transmittanceFunctions(first).thicknessWorldFrom(position, normal, face).mul(u.sssThicknessToProfileMm));
      });
    });
    return vec4(transmitted, thicknessMm);
  })().toVar('sssTransmittedLight');
  return { transmitted: result.xyz, thicknessMm: result.w };
}
