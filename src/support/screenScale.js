// How large a profile millimetre is on screen (also shaders/common/screenScale.glsl): a length L at
// view depth z spans L · P / z in NDC, P the projection's scale on that axis, and NDC's 2 span
// `resolution` pixels (z = 1 orthographic). Taking x and y apart fixes the reference's aspect bug
// (REFERENCE §4): one scale for both made its horizontal blur `aspect` times wider.

/**
 * @param {import('three').Camera} camera
 */
export function isPerspective(camera) {
  return camera.isPerspectiveCamera === true || camera.projectionMatrix.elements[15] === 0;
}

/**
 * Pixels one profile millimetre spans along one screen axis.
 * @param {number} widthWorld world units per profile millimetre (widthMm / worldUnitInMm × widthScale)
 * @param {number} depth linear view depth, world units (ignored for an orthographic camera)
 * @param {number} projectionScale the projection's scale on the axis (elements[0] or [5])
 * @param {number} resolution pixels along the axis
 * @param {boolean} [perspective=true]
 */
export function pixelsPerMm(widthWorld, depth, projectionScale, resolution, perspective = true) {
  return ((widthWorld * projectionScale) / (2 * (perspective ? depth : 1))) * resolution;
}
