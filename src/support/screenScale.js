// How large a profile millimetre is on screen: the one formula the orchestrator's frame plan, the
// bench and (as shaders/common/screenScale.glsl) the blur and the dense reference use.
//
// A world length L at view depth z spans L · P / z in normalised device coordinates, P being the
// projection's scale on that axis (projectionMatrix.elements[0] for x, [5] for y), and NDC's 2 span
// `resolution` pixels. So one profile millimetre, `widthWorld` world units long, spans
//   widthWorld · P / (2 · z) · resolution   pixels,
// with z = 1 for an orthographic camera (its P already maps world units to NDC). Taking x and y
// scales apart fixes the reference's aspect bug (REFERENCE §4): one scale for both axes made its
// horizontal blur `aspect` times wider in world space.

/**
 * True when `camera` projects perspectively (the step shrinks with depth); false for orthographic.
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
