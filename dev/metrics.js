/**
 * Image error metrics of the speed-accuracy bench, over subsurface pixels only (the mask), in Node
 * and in the browser alike.
 *
 * Images are RGBA arrays as read back from render targets (4 values per pixel; alpha ignored); the
 * mask is one value per pixel, > 0 on subsurface pixels.
 * - `radianceErrors`: on linear radiance (the HDR image before tone mapping), over the RGB values of
 *   the masked pixels: relative RMSE = √(mean (t − r)²) / √(mean r²); maximum error = max |t − r|
 *   (radiance units); PSNR = 10 log10(peak² / mean (t − r)²) dB with peak = the largest reference
 *   value there (HDR has no fixed peak).
 * - `maskedSsim`: SSIM (Wang et al. 2004: 11×11 Gaussian window, σ 1.5, K1 0.01, K2 0.03, 8-bit
 *   luma) of two tone-mapped 8-bit images through the `ssim.js` package, averaged over the windows
 *   centred on masked pixels.
 * @module dev/metrics
 */
import { ssim } from 'ssim.js';

/** ssim.js's window: its map has one value per window lying wholly inside the image. */
const WINDOW = 11;
const HALF = (WINDOW - 1) / 2;

function checkSizes(a, b, mask) {
  if (a.length !== b.length || a.length !== mask.length * 4) {
    throw new RangeError(`images must both hold 4 values per mask pixel: got ${a.length}, ${b.length} for ${mask.length} pixels`);
  }
}

/**
 * @param {ArrayLike<number>} test RGBA, linear radiance
 * @param {ArrayLike<number>} reference RGBA, linear radiance
 * @param {ArrayLike<number>} mask one value per pixel, > 0 where measured
 * @returns {{ rmse: number, maxError: number, psnr: number, pixels: number }} rmse relative,
 *   psnr in dB (Infinity when identical)
 */
export function radianceErrors(test, reference, mask) {
  checkSizes(test, reference, mask);
  let squared = 0;
  let energy = 0;
  let maxError = 0;
  let peak = 0;
  let pixels = 0;
  for (let i = 0; i < mask.length; i++) {
    if (!(mask[i] > 0)) continue;
    pixels++;
    for (let c = 0; c < 3; c++) {
      const r = reference[i * 4 + c];
      const d = test[i * 4 + c] - r;
      squared += d * d;
      energy += r * r;
      maxError = Math.max(maxError, Math.abs(d));
      peak = Math.max(peak, r);
    }
  }
  if (pixels === 0) throw new RangeError('radianceErrors: the mask selects no pixel');
  const mse = squared / (pixels * 3);
  return { rmse: Math.sqrt(squared / energy), maxError, psnr: 10 * Math.log10((peak * peak) / mse), pixels };
}

/**
 * @param {ArrayLike<number>} test RGBA, 8-bit tone-mapped values (0..255)
 * @param {ArrayLike<number>} reference RGBA, 8-bit tone-mapped values
 * @param {ArrayLike<number>} mask one value per pixel, > 0 where measured
 * @param {number} width
 * @param {number} height
 * @returns {number} mean SSIM over the windows centred on masked pixels (NaN if there are none)
 */
export function maskedSsim(test, reference, mask, width, height) {
  checkSizes(test, reference, mask);
  // Crop to the mask's bounding box plus half a window: the same windows, less work.
  let x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      if (!(mask[y * width + x] > 0)) continue;
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
  }
  x0 = Math.max(0, x0 - HALF); y0 = Math.max(0, y0 - HALF);
  x1 = Math.min(width - 1, x1 + HALF); y1 = Math.min(height - 1, y1 + HALF);
  const w = x1 - x0 + 1;
  const h = y1 - y0 + 1;
  if (!(w >= WINDOW && h >= WINDOW)) return NaN;
  const crop = (image) => {
    const data = new Uint8ClampedArray(w * h * 4);
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w * 4; x++) data[y * w * 4 + x] = Math.round(image[((y + y0) * width + x0) * 4 + x]);
    }
    return { data, width: w, height: h };
  };
  const { ssim_map: map } = ssim(crop(reference), crop(test), { ssim: 'fast', downsample: false, windowSize: WINDOW });
  let sum = 0;
  let windows = 0;
  for (let y = 0; y < map.height; y++) {
    for (let x = 0; x < map.width; x++) {
      if (!(mask[(y + y0 + HALF) * width + x + x0 + HALF] > 0)) continue;
      sum += map.data[y * map.width + x];
      windows++;
    }
  }
  return windows > 0 ? sum / windows : NaN;
}
