/**
 * Float64 CPU oracle of the transmittance stage (REFERENCE §5), independent of the GPU path.
 * @module test/oracle/transmittance
 */

import { vec3, vec4 } from 'gl-matrix';
import { checkNumber } from '../../src/support/parameterChecks.js';
import { getProfile } from '../../src/profiles/presets.js';
import { SHEET } from '../../src/2-scene-split/transmittanceModel.js';

/**
 * Transmitted fraction through a slab: the profile's exact transmittance T(d) (energy outside radius d)
 * at the scaled distance d = thickness · (1 − translucency) / widthMm (REFERENCE §5's scale with the
 * exact profile integral instead of the reference's exp(−s²/v) form).
 * @param {object} args
 * @param {number} args.thicknessMm thickness in mm (≥ 0, Infinity allowed: nothing behind)
 * @param {string|object} [args.profile='skin']
 * @param {number} [args.widthMm=1] kernel width scale: 1 kernel-mm per widthMm mm
 * @param {number} [args.translucency=0] in [0, 1]; 1 makes everything fully translucent
 * @returns {number[]} [r, g, b]
 */
export function transmittanceOracle({ thicknessMm, profile = 'skin', widthMm = 1, translucency = 0 }) {
  if (thicknessMm !== Infinity) checkNumber('thicknessMm', thicknessMm, { min: 0, unit: 'mm' });
  checkNumber('widthMm', widthMm, { min: 0, minExclusive: true, unit: 'mm' });
  checkNumber('translucency', translucency, { min: 0, max: 1 });
  const p = getProfile(profile);
  if (thicknessMm === Infinity) return translucency === 1 ? [1, 1, 1] : [0, 0, 0];
  return p.transmittance((thicknessMm * (1 - translucency)) / widthMm);
}

/**
 * The depth the point's own tangent plane has along the light's ray through `readView` (a light
 * view position: the map is read there): the depth a map of a flat sheet holds there.
 * @param {Float64Array} pointView the point, light view space
 * @param {Float64Array} normalView its normal, light view space
 * @param {Float64Array} readView
 * @param {boolean} orthographic rays along −z (a directional light), else from the origin
 */
function tangentPlaneDepth(pointView, normalView, readView, orthographic) {
  if (orthographic) {
    const z = pointView[2] - (normalView[0] * (readView[0] - pointView[0]) + normalView[1] * (readView[1] - pointView[1])) / normalView[2];
    return -z;
  }
  return (-vec3.dot(normalView, pointView) / vec3.dot(normalView, readView)) * readView[2];
}

/**
 * Thickness seen by the light, from a linear light depth map (REFERENCE §5, with the shrink only
 * moving where the map is read):
 *   shrunk = point − normalize(normal) · shrinkWorld        (pushed inward along the vertex normal)
 *   the map is read at the shrunk point's projection; the point's own light depth −(lightView · point).z
 *   thickness = lightDepth(point) − mapDepth(at the shrunk point's projection).
 * `mapDepth` is called with the shrunk light-view position (vec3) and, when `lightProjectionMatrix` is
 * given, the map coordinates uv ∈ [0, 1]² of the projection; a stored 0 means "nothing rendered there"
 * and gives Infinity, as does a projection outside the map. A point not behind the stored surface
 * (thickness ≤ 0) is that surface, lit directly, and gives Infinity (nothing comes through). On the
 * far side of its surface (with `toLightWorld`: the normal facing away from the light) a stored
 * depth within SHEET.TEXELS of a texel's width (`texelWorld`) of the point's own plane along the
 * same ray (the plane of its triangle: `normalWorld` here, a flat surface) is the point's own
 * surface, a sheet, and gives 0.
 * @param {object} args
 * @param {ArrayLike<number>} args.lightViewMatrix mat4, world → light view (column-major, gl-matrix/three.js)
 * @param {ArrayLike<number>} [args.lightProjectionMatrix] mat4, light view → clip
 * @param {ArrayLike<number>} args.pointWorld vec3
 * @param {ArrayLike<number>} args.normalWorld vec3, the vertex (not bump-mapped) normal, on the side the camera sees
 * @param {number} [args.shrinkWorld=0] inward push in world units (reference: 0.005 at 1 unit = 1/8 m)
 * @param {ArrayLike<number>} [args.toLightWorld] vec3, the direction from the point to the light (the sheet's test)
 * @param {number} [args.texelWorld=0] a map texel's width at the point's light depth (the sheet's tolerance)
 * @param {boolean} [args.orthographic] the light's rays are parallel (directional); default: without
 *   a projection, or with an orthographic one
 * @param {(lightViewPosition: Float64Array, uv: Float64Array|null) => number} args.mapDepth linear depth stored in the map
 * @returns {number} thickness in world units (Infinity when nothing comes through)
 */
export function thicknessFromLightDepth({
  lightViewMatrix,
  lightProjectionMatrix,
  pointWorld,
  normalWorld,
  shrinkWorld = 0,
  toLightWorld,
  texelWorld = 0,
  orthographic = !lightProjectionMatrix || lightProjectionMatrix[11] !== -1,
  mapDepth,
}) {
  checkNumber('shrinkWorld', shrinkWorld, { min: 0 });
  if (typeof mapDepth !== 'function') throw new TypeError('mapDepth must be a function');
  const normal = vec3.normalize(new Float64Array(3), normalWorld);
  const shrunk = vec3.scaleAndAdd(new Float64Array(3), pointWorld, normal, -shrinkWorld);
  const shrunkView = vec3.transformMat4(new Float64Array(3), shrunk, lightViewMatrix);
  const lightDepth = -vec3.transformMat4(new Float64Array(3), pointWorld, lightViewMatrix)[2];
  let uv = null;
  if (lightProjectionMatrix) {
    const clip = vec4.transformMat4(new Float64Array(4), [shrunkView[0], shrunkView[1], shrunkView[2], 1], lightProjectionMatrix);
    uv = new Float64Array([0.5 * (clip[0] / clip[3]) + 0.5, 0.5 * (clip[1] / clip[3]) + 0.5]);
    if (!(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1)) return Infinity;
  }
  const stored = mapDepth(shrunkView, uv);
  if (stored === 0) return Infinity;
  const facing = toLightWorld ? vec3.dot(normal, vec3.normalize(new Float64Array(3), toLightWorld)) : 0;
  if (facing < 0) {
    const pointView = vec3.transformMat4(new Float64Array(3), pointWorld, lightViewMatrix);
    const origin = vec3.transformMat4(new Float64Array(3), [0, 0, 0], lightViewMatrix);
    const normalView = vec3.sub(new Float64Array(3), vec3.transformMat4(new Float64Array(3), normal, lightViewMatrix), origin);
    const plane = tangentPlaneDepth(pointView, normalView, shrunkView, orthographic);
    if (Math.abs(stored - plane) <= SHEET.TEXELS * texelWorld + 1e-12 * Math.abs(lightDepth)) return 0; // float64 rounding
  }
  const thickness = lightDepth - stored;
  return thickness > 0 ? thickness : Infinity;
}

/**
 * The fraction of the light that arrives through `thicknessMm` of material: T(d) (transmittanceOracle),
 * on the side the light reaches faded in over the first `shrinkMm` (a smoothstep: below the recorded
 * surface by less than the shrink, a point reads as that surface, lit directly), not on the far side
 * (`farSide`: the camera-side normal faces away from the light), times the view factor: only light
 * from behind the point as the camera sees it, smoothstep(0, 0.25, −z) of the unit vector to the
 * light in view space. A sheet's far side is `thicknessMm` 0 and `farSide`: T(0) = 1.
 * @param {object} args transmittanceOracle's, and
 * @param {number} [args.shrinkMm=0]
 * @param {boolean} [args.farSide=false]
 * @param {number} [args.towardLightViewZ=-1] z of the unit vector from the point to the light, view space (+z: to the camera)
 * @returns {number[]} [r, g, b]
 */
export function transmittedFractionOracle({ shrinkMm = 0, farSide = false, towardLightViewZ = -1, ...args }) {
  const smoothstep = (e0, e1, x) => { const t = Math.min(Math.max((x - e0) / (e1 - e0), 0), 1); return t * t * (3 - 2 * t); };
  const fade = shrinkMm > 0 && !farSide ? smoothstep(0, shrinkMm, args.thicknessMm) : 1;
  const view = smoothstep(0, 0.25, -towardLightViewZ);
  return transmittanceOracle(args).map((t) => t * fade * view);
}
