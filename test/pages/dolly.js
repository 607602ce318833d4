// The stability tests' dolly, shared by the WebGL page (stability.js) and the WebGPU one
// (webgpu.js): the camera on the demo's line of sight to the face, the distance for a plan's scale,
// and how far each frame pair's change of the scattering signal s (and of the unscattered image)
// departs from the dolly's steady change. Nothing here is part of the library.
import { FACE_CENTRE } from '/demo/headScene.js';

/** The camera's line of sight to the face (the demo's), to dolly along. */
export const dollyDirection = (camera) => camera.position.clone().sub(FACE_CENTRE).normalize();

/** The camera `distance` world units from the face centre along `direction`, looking at it. */
export function placeOnDolly(camera, direction, distance) {
  camera.position.copy(FACE_CENTRE).addScaledVector(direction, distance);
  camera.lookAt(FACE_CENTRE);
  camera.updateMatrixWorld();
}

/**
 * The distance at which `scaleAt(distance)` (the plan's pixels per profile mm, falling with the
 * distance) is `pixelsPerMm`: bisection.
 */
export function distanceForScale(scaleAt, pixelsPerMm, near = 1.5, far = 1500) {
  let [a, b] = [near, far];
  for (let i = 0; i < 80; i++) {
    const mid = Math.sqrt(a * b);
    if (scaleAt(mid) > pixelsPerMm) a = mid;
    else b = mid;
  }
  return Math.sqrt(a * b);
}

/**
 * The mean |value| over the values that are not 0, the largest tenth left out: a change of the
 * whole face counts, the pixels that pop on their own (a footprint edge snapping to the next
 * pixel, a slope estimate switching) do not.
 */
export function trimmedMean(values) {
  const magnitudes = Float32Array.from(values, Math.abs).filter((v) => v > 0).sort();
  const kept = magnitudes.subarray(0, Math.floor(magnitudes.length * 0.9));
  return kept.reduce((sum, v) => sum + v, 0) / Math.max(kept.length, 1);
}

/**
 * s (the output minus the unscattered light: the colour and diffuse attachments summed) and that
 * unscattered image, RGB, from three RGBA read-backs of one frame.
 */
export function scatteringSignal(output, colour, diffuse) {
  const pixels = output.length / 4;
  const s = new Float32Array(pixels * 3);
  const unscattered = new Float32Array(pixels * 3);
  for (let p = 0; p < pixels; p++) {
    for (let c = 0; c < 3; c++) {
      const u = colour[p * 4 + c] + diffuse[p * 4 + c];
      unscattered[p * 3 + c] = u;
      s[p * 3 + c] = output[p * 4 + c] - u;
    }
  }
  return { s, unscattered };
}

/**
 * How each pair's change departs from the dolly's steady change: r_k = Δ_k − (x_{k+2} − x_{k−1}) / 3
 * for the pairs with a frame either side (k = 1 .. n − 3), whose steady part (linear in the step)
 * cancels, as trimmed means (trimmedMean), with the frames' largest trimmed means of s and of the
 * unscattered image.
 * @param {Array<{ s: Float32Array, unscattered: Float32Array }>} frames
 */
export function dollyDepartures(frames) {
  const departure = (name, k) => {
    const x = frames.map((f) => f[name]);
    return trimmedMean(x[k].map((_, i) => x[k + 1][i] - x[k][i] - (x[k + 2][i] - x[k - 1][i]) / 3));
  };
  const pairs = [];
  for (let k = 1; k + 2 < frames.length; k++) pairs.push({ k, s: departure('s', k), unscattered: departure('unscattered', k) });
  return { pairs, s: Math.max(...frames.map((f) => trimmedMean(f.s))), unscattered: Math.max(...frames.map((f) => trimmedMean(f.unscattered))) };
}
