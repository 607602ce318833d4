// The views a camera draws, as three draws them: a camera draws the whole target; an ArrayCamera
// draws each of its cameras into that camera's `viewport` (WebGLRenderer.render: renderScene with
// camera.viewport, device pixels of the target, no pixel ratio), later views over earlier ones.
// Each view is planned and blurred at its own camera's scale, inside its own rectangle
// (src/3-blur/BlurStage.js renderViews), as the same view drawn alone with that camera would be.

/**
 * A view: its camera, its viewport as three sets it (the screen scale's size: NDC spans it) and
 * the part of it inside the target (the pixels it can draw; its edges are the view's screen edges).
 * @typedef {object} CameraView
 * @property {import('three').Camera} camera
 * @property {{ x: number, y: number, width: number, height: number }} viewport device pixels
 * @property {{ x: number, y: number, width: number, height: number }} rect the viewport within the target
 * @property {boolean} whole whether the view is the whole target (a camera that is not an ArrayCamera)
 */

/**
 * The views `camera` draws into a target of `width` × `height` device pixels (an ArrayCamera's
 * views without a pixel inside it left out).
 * @param {import('three').Camera} camera
 * @param {number} width
 * @param {number} height
 * @returns {CameraView[]}
 */
export function cameraViews(camera, width, height) {
  const whole = { x: 0, y: 0, width, height };
  if (camera.isArrayCamera !== true) return [{ camera, viewport: whole, rect: whole, whole: true }];
  const views = [];
  for (const view of camera.cameras) {
    // gl.viewport takes integers (WebIDL truncates); a camera without a viewport draws into the whole target.
    const v = view.viewport;
    const viewport = v ? { x: Math.trunc(v.x), y: Math.trunc(v.y), width: Math.trunc(v.z), height: Math.trunc(v.w) } : whole;
    const x0 = Math.max(0, viewport.x);
    const y0 = Math.max(0, viewport.y);
    const x1 = Math.min(width, viewport.x + viewport.width);
    const y1 = Math.min(height, viewport.y + viewport.height);
    if (x1 > x0 && y1 > y0) views.push({ camera: view, viewport, rect: { x: x0, y: y0, width: x1 - x0, height: y1 - y0 }, whole: false });
  }
  return views;
}

/**
 * A box of pixels found in a view's own frame (origin at its viewport's corner, as a camera alone
 * would see it) in the target's pixels, within the view's rectangle; null (the whole view) stays
 * the view's rectangle.
 * @param {CameraView} view
 * @param {{ x: number, y: number, width: number, height: number }|null} box
 * @returns {{ x: number, y: number, width: number, height: number }}
 */
export function boxInTarget(view, box) {
  const { viewport, rect } = view;
  if (!box) return rect;
  const x0 = Math.max(rect.x, viewport.x + box.x);
  const y0 = Math.max(rect.y, viewport.y + box.y);
  const x1 = Math.min(rect.x + rect.width, viewport.x + box.x + box.width);
  const y1 = Math.min(rect.y + rect.height, viewport.y + box.y + box.height);
  return x1 > x0 && y1 > y0 ? { x: x0, y: y0, width: x1 - x0, height: y1 - y0 } : { x: rect.x, y: rect.y, width: 0, height: 0 };
}

/**
 * The smallest box holding `boxes` (device pixels; empty ones left out), or null where one of them
 * is null (the whole target).
 * @param {Array<{ x: number, y: number, width: number, height: number }|null>} boxes
 * @returns {{ x: number, y: number, width: number, height: number }|null}
 */
export function unionBox(boxes) {
  if (boxes.includes(null)) return null;
  const shown = boxes.filter((box) => box.width > 0 && box.height > 0);
  if (shown.length === 0) return { x: 0, y: 0, width: 0, height: 0 };
  const x0 = Math.min(...shown.map((b) => b.x));
  const y0 = Math.min(...shown.map((b) => b.y));
  const x1 = Math.max(...shown.map((b) => b.x + b.width));
  const y1 = Math.max(...shown.map((b) => b.y + b.height));
  return { x: x0, y: y0, width: x1 - x0, height: y1 - y0 };
}
