// The regions the surface-truth bench reports separately (pure; page and Node alike): where
// screen-space scattering is known to go wrong (REFERENCE: silhouettes, creases) and the rest.
// Eyes, lips and ears are boxes in the head scan's coordinates (world units of 5 cm, Y up, facing
// +Z), read off the bench's view of the scan by ray casts at the eye slits' corners, the mouth's
// corners and lips, and the ears' top and bottom.

export const REGION_NAMES = Object.freeze(['silhouettes', 'creases', 'ears', 'eyes', 'lips', 'rest']);

/** Facing the camera less than this (cosine between normal and view direction): a silhouette. */
export const SILHOUETTE_COSINE = 0.3;
/** Pixels this close (pixels, Chebyshev) to a pixel without subsurface surface: a silhouette. */
export const SILHOUETTE_PIXELS = 2;

/**
 * A crease (eyelid slit, lip line, nostril, ear fold): a pixel farther from the camera than both
 * pixels CREASE_PIXELS away on either side, along x or y, by more than CREASE_MM: a valley in
 * the view's depth, whose walls the camera sees edge-on.
 */
export const CREASE_PIXELS = 2;
export const CREASE_MM = 0.5;

/** [min, max] world-unit boxes: the slits at x −1.16..−0.37 and 0.57..0.99, y 1.70-1.74. */
const BOXES = {
  eyes: [
    [[-1.3, 1.45, 1.3], [-0.25, 2.0, 2.3]],
    [[0.08, 1.45, 1.2], [1.12, 2.0, 2.3]],
  ],
  // Mouth corners at x −0.43 and 0.26, upper and lower lip at y 0.62 and 0.25.
  lips: [[[-0.6, 0.18, 1.8], [0.45, 0.72, 2.5]]],
  // The ears stand out of the skull's sides at x −1.69 and 1.51 (y 0.68-1.75).
  ears: [
    [[-2.2, 0.5, -0.8], [-1.45, 2.0, 0.9]],
    [[1.28, 0.5, -0.8], [2.0, 2.0, 0.9]],
  ],
};

const inside = ([lo, hi], x, y, z) => x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];

/**
 * The region of each pixel (index into REGION_NAMES; −1: no subsurface surface): next to a pixel
 * without subsurface surface, a silhouette; else in a valley of depth, a crease; else seen at a
 * grazing angle, a silhouette; else the box it lies in, or the rest.
 * @param {{ surface: Float32Array, mask: Float32Array, width: number, height: number, cameraPosition: number[], worldUnitInMm: number }} o
 *   surface: world xyz and facing cosine per pixel (RGBA); mask: alpha > 0 on subsurface pixels;
 *   cameraPosition: world units
 */
export function classifyPixels({ surface, mask, width, height, cameraPosition, worldUnitInMm }) {
  const regions = new Int8Array(width * height).fill(-1);
  const subsurface = (x, y) => x >= 0 && y >= 0 && x < width && y < height && mask[4 * (y * width + x) + 3] > 0;
  const distanceMm = (x, y) => {
    const i = 4 * (y * width + x);
    return Math.hypot(surface[i] - cameraPosition[0], surface[i + 1] - cameraPosition[1], surface[i + 2] - cameraPosition[2]) * worldUnitInMm;
  };
  const valley = (x, y, ax, ay) => {
    const k = CREASE_PIXELS;
    if (!subsurface(x - k * ax, y - k * ay) || !subsurface(x + k * ax, y + k * ay)) return false;
    const centre = distanceMm(x, y) - CREASE_MM;
    return centre > distanceMm(x - k * ax, y - k * ay) && centre > distanceMm(x + k * ax, y + k * ay);
  };
  const counts = Object.fromEntries(REGION_NAMES.map((name) => [name, 0]));
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) {
    const i = y * width + x;
    if (!subsurface(x, y)) continue;
    let edge = false;
    for (let dy = -SILHOUETTE_PIXELS; dy <= SILHOUETTE_PIXELS && !edge; dy++) {
      for (let dx = -SILHOUETTE_PIXELS; dx <= SILHOUETTE_PIXELS && !edge; dx++) edge = !subsurface(x + dx, y + dy);
    }
    const crease = !edge && (valley(x, y, 1, 0) || valley(x, y, 0, 1));
    const [px, py, pz] = [surface[4 * i], surface[4 * i + 1], surface[4 * i + 2]];
    const name = edge ? 'silhouettes' : crease ? 'creases' : surface[4 * i + 3] < SILHOUETTE_COSINE ? 'silhouettes'
      : ['ears', 'eyes', 'lips'].find((region) => BOXES[region].some((box) => inside(box, px, py, pz))) ?? 'rest';
    regions[i] = REGION_NAMES.indexOf(name);
    counts[name]++;
  }
  return { regions, counts };
}
