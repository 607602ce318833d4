// The surface-truth bench's images (browser side): PNGs of images in GL rows, and heat maps of the
// per-pixel error, black (0) through red and yellow to white (≥ max); pixels without subsurface
// surface dark blue-grey.

/** A PNG blob as base64 (for page.evaluate to hand over). */
async function base64(blob) {
  const bytes = new Uint8Array(await blob.arrayBuffer());
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

/** Black → red → yellow → white for t in [0, 1]. */
function colour(t) {
  const u = Math.min(Math.max(t, 0), 1) * 3;
  return [Math.min(u, 1), Math.min(Math.max(u - 1, 0), 1), Math.min(Math.max(u - 2, 0), 1)].map((c) => Math.round(255 * c));
}

/**
 * @param {Float32Array} values per pixel, GL rows (bottom-up)
 * @param {number} width @param {number} height @param {number} max the value drawn white
 * @param {Int8Array} regions −1 where there is no subsurface surface
 * @returns {Promise<string>} the PNG, base64
 */
export function heatMap(values, width, height, max, regions) {
  return pngOf(width, height, (i) => (regions[i] < 0 ? [24, 26, 34] : colour(values[i] / max)));
}

/**
 * A PNG of an image in GL rows (bottom-up), as base64.
 * @param {number} width @param {number} height
 * @param {(i: number) => number[]} rgbAt pixel i (GL order) → [r, g, b], 0..255
 * @returns {Promise<string>}
 */
export async function pngOf(width, height, rgbAt) {
  const canvas = new OffscreenCanvas(width, height);
  const context = canvas.getContext('2d');
  const image = context.createImageData(width, height);
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) {
    image.data.set([...rgbAt((height - 1 - y) * width + x), 255], 4 * (y * width + x));
  }
  context.putImageData(image, 0, 0);
  return base64(await canvas.convertToBlob());
}
