// Stage 1 → 2: transmittance through thin parts (Jimenez et al. 2010) from a LightDepthTarget
// and a ProfileLookup. The GLSL (shaders/2-scene-split/transmittance.glsl) and its uniforms work in
// any ShaderMaterial; the material hook uses the same chunk, plus the light's colour and
// attenuation (lightUniformSlots, updateLightUniforms) to shade with it.
import { Matrix4, Vector3 } from 'three';
import transmittanceGlsl from '../../shaders/2-scene-split/transmittance.glsl?raw';
import profileLookupGlsl from '../../shaders/common/profileLookup.glsl?raw';
import { assembleGlsl } from '../support/glsl.js';
import { describe } from '../support/rendererSupport.js';
import { LightDepthTarget } from '../1-light-depth/LightDepthTarget.js';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { MATERIAL_DEFAULTS, MATERIAL_SCHEMA, PIPELINE_SCHEMA, checkOption } from '../options.js';

/** The chunks shaders/2-scene-split/transmittance.glsl includes, by path. */
export const TRANSMITTANCE_CHUNKS = Object.freeze({
  '2-scene-split/transmittance.glsl': transmittanceGlsl,
  'common/profileLookup.glsl': profileLookupGlsl,
});

/**
 * The GLSL computing transmittance from a LightDepthTarget and a ProfileLookup
 * (shaders/2-scene-split/transmittance.glsl with the profile table's reader); its uniforms come
 * from createTransmittanceUniforms.
 */
export const transmittanceChunk = assembleGlsl('transmittanceChunk', '#include "2-scene-split/transmittance.glsl"', TRANSMITTANCE_CHUNKS);

const _position = new Vector3();
const _direction = new Vector3();

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
  };
}

/**
 * Checked transmittance settings (see createTransmittanceUniforms' options), frozen.
 * @returns {Readonly<{ lightDepth: LightDepthTarget, lookup: ProfileLookup, worldUnitInMm: number, widthMm: number, translucency: number, shrinkMm: number }>}
 */
export function transmittanceSettings(options) {
  if (options === null || typeof options !== 'object') throw new TypeError(`transmittance options must be an object { lightDepth, lookup, worldUnitInMm, ... }, got ${describe(options)}`);
  const {
    lightDepth, lookup, worldUnitInMm, widthMm = MATERIAL_DEFAULTS.widthMm, translucency = MATERIAL_DEFAULTS.translucency, shrinkMm = MATERIAL_DEFAULTS.shrinkMm,
  } = options;
  if (!(lightDepth instanceof LightDepthTarget)) throw new TypeError(`transmittance: lightDepth must be a LightDepthTarget, got ${describe(lightDepth)}`);
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
  uniforms.sssViewToLightView.value.multiplyMatrices(lightDepth.camera.matrixWorldInverse, camera.matrixWorld);
  uniforms.sssLightProjection.value.copy(lightDepth.camera.projectionMatrix);
}

/**
 * Creates the uniforms of `transmittanceChunk` and a function that refreshes them for a camera.
 * Use it for a custom ShaderMaterial that includes the chunk.
 * @param {object} options
 * @param {LightDepthTarget} options.lightDepth
 * @param {ProfileLookup} options.lookup the profile's tables (row 0: T(d))
 * @param {number} options.worldUnitInMm millimetres per world unit (> 0)
 * @param {number} [options.widthMm=1] profile scale: millimetres of material per profile millimetre
 * @param {number} [options.translucency=0] 0..<1, shortens the thickness by (1 - translucency)
 * @param {number} [options.shrinkMm=0.6] inward shrink along the vertex normal, mm (against acne)
 * @param {object} [uniforms] existing uniform objects to fill (see transmittanceUniformSlots); new ones by default
 * @returns {{ uniforms: object, update(camera: import('three').Camera): void, set(options: object): void }}
 */
export function createTransmittanceUniforms(options, uniforms = transmittanceUniformSlots()) {
  let settings = transmittanceSettings(options);
  writeTransmittanceUniforms(uniforms, settings);
  return {
    uniforms,
    set(next) {
      settings = transmittanceSettings({ ...settings, ...Object.fromEntries(Object.entries(next).filter(([, v]) => v !== undefined)) });
      writeTransmittanceUniforms(uniforms, settings);
    },
    update(camera) {
      writeTransmittanceUniforms(uniforms, settings, camera);
    },
  };
}

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
 * transmittedLight.glsl: smoothstep(0, 0.25, −toLight.z), in view space), so none reaches a mesh
 * while a spot light is no farther along the view axis than its nearest point, or while a
 * directional light shines from the camera's side. Then its light depth pass can be skipped.
 * @param {import('three').SpotLight|import('three').DirectionalLight} light (world matrices up to date)
 * @param {import('three').Camera} camera (matrixWorldInverse up to date)
 * @param {number} nearestDepth world units
 */
export function lightFromBehind(light, camera, nearestDepth) {
  const view = camera.matrixWorldInverse;
  _position.setFromMatrixPosition(light.matrixWorld);
  if (light.isSpotLight) return -_position.applyMatrix4(view).z > nearestDepth;
  _direction.setFromMatrixPosition(light.target.matrixWorld);
  return _direction.subVectors(_position, _direction).transformDirection(view).z < 0;
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
  _direction.setFromMatrixPosition(light.target.matrixWorld);
  _direction.subVectors(_position, _direction).transformDirection(view);
  uniforms.sssLightDirectionView.value.copy(_direction);
  uniforms.sssLightPositionView.value.copy(_position.applyMatrix4(view));
  if (light.isSpotLight) {
    uniforms.sssLightCutoffDistance.value = light.distance;
    uniforms.sssLightDecay.value = light.decay;
    uniforms.sssSpotConeCos.value = Math.cos(light.angle);
    uniforms.sssSpotPenumbraCos.value = Math.cos(light.angle * (1 - light.penumbra));
  }
}
