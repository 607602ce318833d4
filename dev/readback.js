// Reads a render target back as 32-bit floats, always 4 per pixel (RGBA; missing channels 0, alpha
// 1), converting half floats, for the demo's test API, the test pages and the bench. Never used
// in the render loop.
import { DataUtils, FloatType, HalfFloatType, RedFormat, RGFormat, RGBAFormat } from 'three';

const CHANNELS = new Map([[RedFormat, 1], [RGFormat, 2], [RGBAFormat, 4]]);

/**
 * @param {import('three').WebGLRenderer} renderer
 * @param {import('three').WebGLRenderTarget} target
 * @param {number} [textureIndex=0] which attachment of a multi-target
 * @returns {Promise<Float32Array>} RGBA per pixel, rows bottom-up (GL order)
 */
export async function readRenderTargetFloats(renderer, target, textureIndex = 0) {
  const { width, height } = target;
  const texture = target.textures[textureIndex];
  const channels = CHANNELS.get(texture.format);
  if (!channels) throw new TypeError(`readRenderTargetFloats: texture ${textureIndex} must be RGBA, RG or Red`);
  let values;
  if (texture.type === FloatType) {
    values = new Float32Array(width * height * channels);
    await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height, values, undefined, textureIndex);
  } else if (texture.type === HalfFloatType) {
    const half = new Uint16Array(width * height * channels);
    await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height, half, undefined, textureIndex);
    values = Float32Array.from(half, DataUtils.fromHalfFloat);
  } else {
    throw new TypeError(`readRenderTargetFloats: texture ${textureIndex} must be FloatType or HalfFloatType`);
  }
  if (channels === 4) return values;
  const rgba = new Float32Array(width * height * 4);
  for (let i = 0; i < width * height; i++) {
    for (let c = 0; c < channels; c++) rgba[i * 4 + c] = values[i * channels + c];
    rgba[i * 4 + 3] = 1;
  }
  return rgba;
}
