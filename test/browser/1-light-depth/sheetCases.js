// What the lab's back-lit sheet (test/pages/lab.js `backlit` with `sheet`: a DoubleSide plane of no
// thickness, white, its front face to a directional light of intensity π turned `azimuthDeg` about
// y from straight behind, seen from the front at 10 mm per unit) shows in its diffuse light, from
// the float64 oracle: the thickness the map gives at its far side (0: the sheet itself), T of it
// (T(0) = 1 for every profile, unfaded on the far side), times the sheet's entry cosine cos a and
// the wrap at the exit, saturate(0.3 + cos a) (REFERENCE §5). Both light depth targets and both
// materials are held to it (the WebGL path's and the WebGPU node's).
import { mat4, vec3 } from 'gl-matrix';
import { thicknessFromLightDepth, transmittedFractionOracle } from '../../oracle/transmittance.js';

export const SHEET_WORLD_UNIT_IN_MM = 10; // the lab's
/** The lab's light depth map: 1024 texels over the directional light's shadow camera, 2 × 20 units across. */
const TEXEL_WORLD = 40 / 1024;

/**
 * @param {number} azimuthDeg the light's turn from straight behind the sheet
 * @param {{ shrinkMm?: number, profile?: string }} [options]
 * @returns {number[]} [r, g, b] of the diffuse light on the sheet's far side
 */
export function expectedSheet(azimuthDeg, { shrinkMm = 0.6, profile = 'skin' } = {}) {
  const a = (azimuthDeg * Math.PI) / 180;
  const toLight = [Math.sin(a), 0, -Math.cos(a)];
  const lightView = mat4.lookAt(new Float64Array(16), toLight.map((v) => 10 * v), [0, 0, 0], [0, 1, 0]);
  const fromLightView = mat4.invert(new Float64Array(16), lightView);
  const point = [0.3, -0.2, 0];
  const thicknessWorld = thicknessFromLightDepth({
    lightViewMatrix: lightView, pointWorld: point, normalWorld: [0, 0, 1], shrinkWorld: shrinkMm / SHEET_WORLD_UNIT_IN_MM,
    toLightWorld: toLight, texelWorld: TEXEL_WORLD,
    // The sheet z = 0 where the light's ray through the read position meets it.
    mapDepth: (position) => {
      const world = vec3.transformMat4(new Float64Array(3), position, fromLightView);
      const onSheet = vec3.scaleAndAdd(new Float64Array(3), world, toLight, -world[2] / toLight[2]);
      return -vec3.transformMat4(new Float64Array(3), onSheet, lightView)[2];
    },
  });
  if (thicknessWorld === Infinity) return [0, 0, 0];
  const through = transmittedFractionOracle({
    thicknessMm: thicknessWorld * SHEET_WORLD_UNIT_IN_MM, profile, shrinkMm, farSide: true, towardLightViewZ: toLight[2],
  });
  return through.map((t) => t * Math.cos(a) * Math.min(1, 0.3 + Math.cos(a)));
}
