// The bench's error metrics on images whose answers are known in closed form.
import { describe, it, expect } from 'vitest';
import { radianceErrors, maskedSsim } from '../../../dev/metrics.js';

/** An RGBA image of width × height from f(x, y) → [r, g, b]. */
function image(width, height, f) {
  const out = new Float64Array(width * height * 4);
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) out.set([...f(x, y), 1], (y * width + x) * 4);
  return out;
}

const mask = (width, height, f) => Float64Array.from({ length: width * height }, (_, i) => (f(i % width, Math.floor(i / width)) ? 1 : 0));

describe('radianceErrors (linear radiance, masked pixels)', () => {
  it('a uniform 10 % excess: relative RMSE 0.1, maximum error 0.1, PSNR 20 dB; unmasked pixels ignored', () => {
    const reference = image(8, 4, () => [1, 1, 1]);
    const test = image(8, 4, (x) => (x < 6 ? [1.1, 1.1, 1.1] : [50, -3, 7]));
    const e = radianceErrors(test, reference, mask(8, 4, (x) => x < 6));
    expect(e.pixels).toBe(24);
    expect(e.rmse).toBeCloseTo(0.1, 12);
    expect(e.maxError).toBeCloseTo(0.1, 12);
    expect(e.psnr).toBeCloseTo(20, 10);
  });

  it('one channel of one pixel off by 0.6 over a level of 2 (4 pixels): MSE 0.03', () => {
    const reference = image(2, 2, () => [2, 2, 2]);
    const test = image(2, 2, (x, y) => (x === 1 && y === 1 ? [2, 2.6, 2] : [2, 2, 2]));
    const e = radianceErrors(test, reference, mask(2, 2, () => true));
    // MSE = 0.36 / 12; mean r² = 4; peak 2.
    expect(e.rmse).toBeCloseTo(Math.sqrt(0.03 / 4), 12);
    expect(e.maxError).toBeCloseTo(0.6, 12);
    expect(e.psnr).toBeCloseTo(10 * Math.log10(4 / 0.03), 10);
  });

  it('identical images: zero error, infinite PSNR; an empty mask is refused', () => {
    const a = image(3, 3, (x, y) => [x, y, 1]);
    const e = radianceErrors(a, a, mask(3, 3, () => true));
    expect(e.rmse).toBe(0);
    expect(e.maxError).toBe(0);
    expect(e.psnr).toBe(Infinity);
    expect(() => radianceErrors(a, a, mask(3, 3, () => false))).toThrow(RangeError);
  });
});

describe('maskedSsim (8-bit tone-mapped, ssim.js)', () => {
  const C1 = (0.01 * 255) ** 2;

  it('two flat images of grey 100 and 120: the luminance term (2·100·120 + C1) / (100² + 120² + C1)', () => {
    const a = image(32, 24, () => [100, 100, 100]);
    const b = image(32, 24, () => [120, 120, 120]);
    const expected = (2 * 100 * 120 + C1) / (100 ** 2 + 120 ** 2 + C1);
    expect(maskedSsim(b, a, mask(32, 24, () => true), 32, 24)).toBeCloseTo(expected, 6);
  });

  it('identical textures score 1 on the mask however much they differ away from it', () => {
    const texture = (x, y) => { const v = (x * 37 + y * 91) % 256; return [v, 255 - v, (v * 3) % 256]; };
    const a = image(48, 32, texture);
    const b = image(48, 32, (x, y) => (x < 30 ? texture(x, y) : [0, 0, 0]));
    // Windows centred at x ≤ 24 reach x ≤ 29 only: all identical.
    expect(maskedSsim(b, a, mask(48, 32, (x) => x <= 24), 48, 32)).toBeCloseTo(1, 12);
    // Over the whole image the differing half lowers it.
    expect(maskedSsim(b, a, mask(48, 32, () => true), 48, 32)).toBeLessThan(0.9);
  });
});
