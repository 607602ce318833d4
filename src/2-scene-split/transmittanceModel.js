// Transmittance through thin parts (Jimenez et al. 2010), renderer-free: the settings and their
// checks, the uniforms' values (one writer for the WebGL chunk's uniform objects and the WebGPU
// node's TSL uniforms: both hold `.value`), the light's checks (isShining, lightFromBehind,
// lightReachesFromBehind) and the constants of the shading formula, which the GLSL
// (shaders/2-scene-split/material/transmittedLight.glsl, as defines) and its TSL port
// (src/webgpu/2-scene-split/transmittanceTsl.js) both take from here.
import { Matrix4, Vector3 } from 'three';
import { LightDepthView } from '../1-light-depth/LightDepthView.js';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { describe } from '../support/rendererSupport.js';
import { glslFloat } from '../support/glsl.js';
import { classNameOf } from '../support/className.js';
import { nearestViewDepth } from '../framePlan.js';
import { MATERIAL_DEFAULTS, MATERIAL_SCHEMA, PIPELINE_SCHEMA, checkOption } from '../options.js';

/**
 * The transmitted light's shading (transmittedLight.glsl): beside T and the entry cosine from the
 * light depth map (transmittance.glsl), wrap lighting on the back side,
 * saturate(WRAP_OFFSET + dot(−N, L)) (REFERENCE §5's 0.3), times smoothstep(0, FROM_BEHIND_RANGE,
 * −L.z): only light from behind the point as the camera sees it (view space, +z to the camera),
 * fading in over the first quarter of the half-space.
 */
export const TRANSMITTED_LIGHT = Object.freeze({ WRAP_OFFSET: 0.3, FROM_BEHIND_RANGE: 0.25 });

/** TRANSMITTED_LIGHT as GLSL defines (SSS_WRAP_OFFSET, SSS_FROM_BEHIND_RANGE), floats. */
export const TRANSMITTED_LIGHT_DEFINES = Object.freeze(Object.fromEntries(
  Object.entries(TRANSMITTED_LIGHT).map(([name, value]) => [`SSS_${name}`, value.toFixed(6)]),
));

/**
 * A sheet, a surface of no thickness (transmittance.glsl's sssTransmittanceAround): a texel on the
 * far side of a point records the point's own surface where its depth lies within TEXELS of a
 * texel's width of the plane of the point's triangle (exact on that triangle: the map holds each
 * texel centre's depth; the tolerance is for a curved sheet's next triangle, over the texel and a
 * half read: faces up to about 2° apart). A closed part thinner than that reads as a sheet.
 */
export const SHEET = Object.freeze({ TEXELS: 0.05 });

/** SHEET as GLSL define lines (SSS_SHEET_TEXELS, ...), for the chunk that reads them. */
export const SHEET_DEFINES = Object.entries(SHEET).map(([name, value]) => `#define SSS_SHEET_${name} ${glslFloat(value)}`).join('\n');

/** The kinds of light transmittance is shaded with (a uniform: its index). */
export const LIGHT_TYPES = Object.freeze(['directional', 'spot', 'point']);

/** A light's LIGHT_TYPES entry. */
const lightType = (light) => (light.isSpotLight ? 'spot' : light.isPointLight ? 'point' : 'directional');

/**
 * The uniform objects `transmittanceChunk` reads, with neutral values. A hooked material owns one
 * set for its whole life (three keeps the uniform objects of a program's first compile), filled
 * per draw from the drawing pipeline's settings.
 */
export function transmittanceUniformSlots() {
  return {
    sssLightDepthMap: { value: null },
    sssViewToLightView: { value: new Matrix4() },
    sssLightProjection: { value: new Matrix4() },
    sssShrinkWorld: { value: 0 },
    sssProfileLookup: { value: null },
    sssTransmittanceRangeMm: { value: 1 },
    sssThicknessToProfileMm: { value: 1 },
    sssLightCube: { value: false }, // the map is a point light's six faces (the WebGL material reads them)
  };
}


/**
 * Checked transmittance settings (see createTransmittanceUniforms' options), frozen.
 * @param {object} options
 * @param {Function} [Accepted] the light depth maps the caller's renderer can read: LightDepthTarget
 *   (WebGLRenderer) or LightDepthNodeTarget (WebGPURenderer); both are LightDepthViews
 * @returns {Readonly<{ lightDepth: LightDepthView, lookup: ProfileLookup, worldUnitInMm: number, widthMm: number, translucency: number, shrinkMm: number }>}
 */
export function transmittanceSettings(options, Accepted = LightDepthView) {
  if (options === null || typeof options !== 'object') throw new TypeError(`transmittance options must be an object { lightDepth, lookup, worldUnitInMm, ... }, got ${describe(options)}`);
  const {
    lightDepth, lookup, worldUnitInMm, widthMm = MATERIAL_DEFAULTS.widthMm, translucency = MATERIAL_DEFAULTS.translucency, shrinkMm = MATERIAL_DEFAULTS.shrinkMm,
  } = options;
  if (!(lightDepth instanceof Accepted)) throw new TypeError(`transmittance: lightDepth must be a ${classNameOf(Accepted)}, got ${describe(lightDepth)}`);
  if (!(lookup instanceof ProfileLookup)) throw new TypeError(`transmittance: lookup must be a ProfileLookup, got ${describe(lookup)}`);
  checkOption(PIPELINE_SCHEMA, 'worldUnitInMm', worldUnitInMm);
  for (const [name, value] of Object.entries({ widthMm, translucency, shrinkMm })) checkOption(MATERIAL_SCHEMA, name, value);
  return Object.freeze({ lightDepth, lookup, worldUnitInMm, widthMm, translucency, shrinkMm });
}

/**
 * Writes transmittanceUniformSlots' uniforms for `settings`, and with a camera the view-dependent
 * ones too (the light camera as LightDepthTarget last placed it).
 * @param {object} uniforms
 * @param {ReturnType<typeof transmittanceSettings>} settings
 * @param {import('three').Camera} [camera]
 */
export function writeTransmittanceUniforms(uniforms, settings, camera) {
  const { lightDepth, lookup, worldUnitInMm, widthMm, translucency, shrinkMm } = settings;
  uniforms.sssLightDepthMap.value = lightDepth.texture;
  uniforms.sssProfileLookup.value = lookup.texture;
  uniforms.sssShrinkWorld.value = shrinkMm / worldUnitInMm;
  uniforms.sssThicknessToProfileMm.value = (worldUnitInMm * (1 - translucency)) / widthMm;
  uniforms.sssTransmittanceRangeMm.value = lookup.transmittanceRangeMm;
  if (!camera) return;
  uniforms.sssViewToLightView.value.multiplyMatrices(lightDepth.viewMatrix, camera.matrixWorld);
  uniforms.sssLightCube.value = lightDepth.isCube;
  uniforms.sssLightProjection.value.copy(lightDepth.camera.projectionMatrix);
}

const _position = new Vector3();
const _direction = new Vector3();

/**
 * Whether `light` lights `scene` as three would light it from `camera`: visible with all its
 * ancestors, in the scene's graph, on a layer the camera sees, with a non-zero intensity. A light
 * removed from the scene, never added, or hidden sends no transmittance (and its depth pass is
 * skipped).
 * @param {import('three').Light} light
 * @param {import('three').Scene} scene
 * @param {import('three').Camera} camera
 */
export function isShining(light, scene, camera) {
  if (!(light.intensity > 0) || !light.layers.test(camera.layers)) return false;
  let node = light;
  while (node.visible && node.parent) node = node.parent;
  return node.visible && node === scene;
}

/**
 * Whether `light` can send transmitted light to any point of a mesh whose nearest point lies
 * `nearestDepth` in front of `camera` (nearestViewDepth). The material transmits only light that
 * comes from behind the point as the camera sees it (shaders/2-scene-split/material/
 * transmittedLight.glsl: TRANSMITTED_LIGHT's FROM_BEHIND_RANGE, in view space), so none reaches a mesh
 * while a spot light is no farther along the view axis than its nearest point, or while a
 * directional light shines from the camera's side. Then its light depth pass can be skipped.
 * @param {import('three').SpotLight|import('three').DirectionalLight} light (world matrices up to date)
 * @param {import('three').Camera} camera (matrixWorldInverse up to date)
 * @param {number} nearestDepth world units
 */
export function lightFromBehind(light, camera, nearestDepth) {
  const view = camera.matrixWorldInverse;
  _position.setFromMatrixPosition(light.matrixWorld);
  if (!light.isDirectionalLight) return -_position.applyMatrix4(view).z > nearestDepth;
  _direction.setFromMatrixPosition(light.target.matrixWorld);
  return _direction.subVectors(_position, _direction).transformDirection(view).z < 0;
}

/**
 * Whether `light` can send transmitted light to any of `meshes` (the frame's subsurface meshes on
 * the screen: FrameMeshes.onScreen) that has a material for which `transmits(material)` holds
 * (lightFromBehind at the mesh's nearest point). False lets the light depth pass be skipped: its
 * map would go unread. The meshes' and the camera's world matrices must be up to date (the
 * light's are updated here).
 * @param {import('three').SpotLight|import('three').DirectionalLight|import('three').PointLight} light
 * @param {Iterable<import('three').Mesh>} meshes
 * @param {import('three').Camera} camera
 * @param {(material: import('three').Material) => boolean} transmits
 */
export function lightReachesFromBehind(light, meshes, camera, transmits) {
  light.updateMatrixWorld();
  light.target?.updateMatrixWorld();
  for (const mesh of meshes) {
    const materials = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
    if (materials.some((m) => m && transmits(m)) && lightFromBehind(light, camera, nearestViewDepth(mesh, camera))) return true;
  }
  return false;
}

/** The uniform objects of the light the hooked material shades transmittance with. */
export function lightUniformSlots() {
  return {
    sssLightColor: { value: new Vector3() },
    sssLightPositionView: { value: new Vector3() },
    sssLightDirectionView: { value: new Vector3() },
    sssLightCutoffDistance: { value: 0 },
    sssLightDecay: { value: 2 },
    sssSpotConeCos: { value: 0 },
    sssSpotPenumbraCos: { value: 1 },
  };
}

/**
 * Refreshes lightUniformSlots' uniforms for `light` seen from `camera` (view space, three's
 * conventions: the direction points from the target towards the light); a light that does not
 * shine in `scene` (isShining) gets colour 0.
 * @param {object} uniforms
 * @param {import('three').SpotLight|import('three').DirectionalLight} light
 * @param {import('three').Scene} scene
 * @param {import('three').Camera} camera
 */
export function updateLightUniforms(uniforms, light, scene, camera) {
  const view = camera.matrixWorldInverse;
  uniforms.sssLightColor.value.set(light.color.r, light.color.g, light.color.b)
    .multiplyScalar(isShining(light, scene, camera) ? light.intensity : 0);
  _position.setFromMatrixPosition(light.matrixWorld);
  if (light.target) {
    _direction.setFromMatrixPosition(light.target.matrixWorld);
    _direction.subVectors(_position, _direction).transformDirection(view);
  } else {
    _direction.set(0, 0, 0); // a point light: none
  }
  uniforms.sssLightDirectionView.value.copy(_direction);
  uniforms.sssLightPositionView.value.copy(_position.applyMatrix4(view));
  if (!light.isDirectionalLight) {
    uniforms.sssLightCutoffDistance.value = light.distance;
    uniforms.sssLightDecay.value = light.decay;
  }
  if (light.isSpotLight) {
    uniforms.sssSpotConeCos.value = Math.cos(light.angle);
    uniforms.sssSpotPenumbraCos.value = Math.cos(light.angle * (1 - light.penumbra));
  }
}

/**
 * Writes a subsurface material's transmittance uniforms for one draw: whether it transmits (a map
 * as last rendered and a light that shines), the light's type, colour and place
 * (updateLightUniforms), the map's and the profile's (writeTransmittanceUniforms). The WebGL
 * material hook and the WebGPU node's materials call it with their own uniform objects.
 * @param {object} uniforms lightUniformSlots and transmittanceUniformSlots, with sssTransmits and sssLightType
 * @param {ReturnType<typeof transmittanceSettings>} settings
 * @param {import('three').Scene} scene
 * @param {import('three').Camera} camera
 */
export function writeTransmittedLight(uniforms, settings, scene, camera) {
  const { light, valid } = settings.lightDepth;
  uniforms.sssTransmits.value = valid && isShining(light, scene, camera);
  uniforms.sssLightType.value = LIGHT_TYPES.indexOf(lightType(light));
  updateLightUniforms(uniforms, light, scene, camera);
  writeTransmittanceUniforms(uniforms, settings, camera);
}
