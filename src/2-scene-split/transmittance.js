// Stage 1 → 2: transmittance through thin parts (Jimenez et al. 2010) from a LightDepthTarget
// and a ProfileLookup. The GLSL (shaders/2-scene-split/transmittance.glsl) and its uniforms work in
// any ShaderMaterial; the material hook uses the same chunk, plus the light's colour and
// attenuation (lightUniformSlots, updateLightUniforms) to shade with it.
import { Matrix4, Vector3 } from 'three';
import transmittanceGlsl from '../../shaders/2-scene-split/transmittance.glsl?raw';
import profileLookupGlsl from '../../shaders/common/profileLookup.glsl?raw';
import { assembleGlsl } from '../support/glsl.js';
import { checkNumber } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { LightDepthTarget } from '../1-light-depth/LightDepthTarget.js';
import { ProfileLookup } from '../profiles/ProfileLookup.js';
import { MATERIAL_DEFAULTS } from '../options.js';

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
 * set for its whole life: three keeps the uniform objects of a program's first compile when it
 * switches back to that program, so they must never be replaced.
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
  const { widthMm, translucency, shrinkMm } = MATERIAL_DEFAULTS;
  const state = { widthMm, translucency, shrinkMm };
  function set(next) {
    Object.assign(state, Object.fromEntries(Object.entries(next).filter(([, v]) => v !== undefined)));
    if (!(state.lightDepth instanceof LightDepthTarget)) {
      throw new TypeError(`transmittance: lightDepth must be a LightDepthTarget, got ${describe(state.lightDepth)}`);
    }
    if (!(state.lookup instanceof ProfileLookup)) {
      throw new TypeError(`transmittance: lookup must be a ProfileLookup, got ${describe(state.lookup)}`);
    }
    checkNumber('worldUnitInMm', state.worldUnitInMm, { min: 0, minExclusive: true, max: 1e9, unit: 'mm' });
    checkNumber('widthMm', state.widthMm, { min: 0, minExclusive: true, max: 1000, unit: 'mm' });
    checkNumber('translucency', state.translucency, { min: 0, max: 1, maxExclusive: true });
    checkNumber('shrinkMm', state.shrinkMm, { min: 0, max: 1000, unit: 'mm' });
    uniforms.sssLightDepthMap.value = state.lightDepth.texture;
    uniforms.sssProfileLookup.value = state.lookup.texture;
    uniforms.sssShrinkWorld.value = state.shrinkMm / state.worldUnitInMm;
    uniforms.sssThicknessToProfileMm.value = (state.worldUnitInMm * (1 - state.translucency)) / state.widthMm;
  }
  set(options);
  return {
    uniforms,
    set,
    update(camera) {
      const { lightDepth, lookup } = state;
      uniforms.sssViewToLightView.value.multiplyMatrices(lightDepth.camera.matrixWorldInverse, camera.matrixWorld);
      uniforms.sssLightProjection.value.copy(lightDepth.camera.projectionMatrix);
      uniforms.sssTransmittanceRangeMm.value = lookup.transmittanceRangeMm;
    },
  };
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
 * conventions: the direction points from the target towards the light).
 * @param {object} uniforms
 * @param {import('three').SpotLight|import('three').DirectionalLight} light
 * @param {import('three').Camera} camera
 */
export function updateLightUniforms(uniforms, light, camera) {
  const view = camera.matrixWorldInverse;
  // Like three's own lights: a hidden light (or one under a hidden parent) sends nothing.
  let shining = true;
  light.traverseAncestors((a) => { if (!a.visible) shining = false; });
  uniforms.sssLightColor.value.set(light.color.r, light.color.g, light.color.b)
    .multiplyScalar(shining && light.visible ? light.intensity : 0);
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
