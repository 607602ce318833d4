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
  if (channels !== 4 || textureIndex !== 0) return readAsRgbaFloats(renderer, target, textureIndex);
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
  return values;
}

/**
 * RG and Red attachments, and attachments after the first, read as RGBA floats by WebGL2 itself
 * (always allowed for float colour buffers; missing channels 0, alpha 1): three r180 and older
 * refuse formats other than RGBA in readRenderTargetPixelsAsync, and before r180 it reads the
 * first attachment only, so the version matrix needs this path.
 */
function readAsRgbaFloats(renderer, target, textureIndex) {
  const gl = renderer.getContext();
  const { width, height } = target;
  const rgba = new Float32Array(width * height * 4);
  // The textures' framebuffer, as three's own read-backs bind it: with MSAA it holds the resolved
  // attachments (setRenderTarget would bind the multisampled one, which cannot be read).
  const framebuffer = renderer.properties.get(target).__webglFramebuffer;
  if (!framebuffer) throw new Error('readRenderTargetFloats: the target has not been rendered yet');
  const current = renderer.getRenderTarget();
  renderer.state.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  try {
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + textureIndex);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, rgba);
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
  } finally {
    renderer.state.bindFramebuffer(gl.FRAMEBUFFER, current ? renderer.properties.get(current).__webglFramebuffer : null);
  }
  return rgba;
}
