// Stage 1 → 2: transmittance through thin parts (Jimenez et al. 2010) from a LightDepthTarget
// and a ProfileLookup, the WebGL half. The GLSL (shaders/2-scene-split/transmittance.glsl) and its
// uniforms work in any ShaderMaterial; the material hook uses the same chunk, plus the light's
// colour and attenuation (lightUniformSlots, updateLightUniforms) to shade with it. The
// renderer-free half (settings, uniform values, the light's checks) is ./transmittanceModel.js,
// which the WebGPU node shares.
import transmittanceGlsl from '../../shaders/2-scene-split/transmittance.glsl?raw';
import profileLookupGlsl from '../../shaders/common/profileLookup.glsl?raw';
import { assembleGlsl } from '../support/glsl.js';
import { SHEET_DEFINES, transmittanceSettings, transmittanceUniformSlots, writeTransmittanceUniforms } from './transmittanceModel.js';
import { LightDepthTarget } from '../1-light-depth/LightDepthTarget.js';

export {
  TRANSMITTED_LIGHT, TRANSMITTED_LIGHT_DEFINES, LIGHT_TYPES, transmittanceUniformSlots, transmittanceSettings, writeTransmittanceUniforms,
  isShining, lightFromBehind, lightReachesFromBehind, lightUniformSlots, updateLightUniforms, writeTransmittedLight,
} from './transmittanceModel.js';

/** The chunks shaders/2-scene-split/transmittance.glsl includes, by path (with the sheet's constants before it). */
export const TRANSMITTANCE_CHUNKS = Object.freeze({
  '2-scene-split/transmittance.glsl': `${SHEET_DEFINES}\n${transmittanceGlsl}`,
  'common/profileLookup.glsl': profileLookupGlsl,
});

/**
 * The GLSL computing transmittance from a LightDepthTarget and a ProfileLookup
 * (shaders/2-scene-split/transmittance.glsl with the profile table's reader); its uniforms come
 * from createTransmittanceUniforms.
 */
export const transmittanceChunk = assembleGlsl('transmittanceChunk', '#include "2-scene-split/transmittance.glsl"', TRANSMITTANCE_CHUNKS);

/**
 * Creates the uniforms of `transmittanceChunk` and a function that refreshes them for a camera.
 * Use it for a custom ShaderMaterial that includes the chunk.
 * @param {object} options
 * @param {import('../1-light-depth/LightDepthTarget.js').LightDepthTarget} options.lightDepth
 * @param {import('../profiles/ProfileLookup.js').ProfileLookup} options.lookup the profile's tables (row 0: T(d))
 * @param {number} options.worldUnitInMm millimetres per world unit (> 0)
 * @param {number} [options.widthMm=1] profile scale: millimetres of material per profile millimetre
 * @param {number} [options.translucency=0] 0..<1, shortens the thickness by (1 - translucency)
 * @param {number} [options.shrinkMm=0.6] inward shrink along the vertex normal, mm (against acne)
 * @param {object} [uniforms] existing uniform objects to fill (see transmittanceUniformSlots); new ones by default
 * @returns {{ uniforms: object, update(camera: import('three').Camera): void, set(options: object): void }}
 */
export function createTransmittanceUniforms(options, uniforms = transmittanceUniformSlots()) {
  let settings = transmittanceSettings(options, LightDepthTarget);
  writeTransmittanceUniforms(uniforms, settings);
  return {
    uniforms,
    set(next) {
      settings = transmittanceSettings({ ...settings, ...Object.fromEntries(Object.entries(next).filter(([, v]) => v !== undefined)) }, LightDepthTarget);
      writeTransmittanceUniforms(uniforms, settings);
    },
    update(camera) {
      writeTransmittanceUniforms(uniforms, settings, camera);
    },
  };
}
