/**
 * Gives `texture` of `target` the data type `type`: three allocates at first use and keeps the
 * buffers, so the target is disposed for three to reallocate them.
 * @param {import('three').WebGLRenderTarget} target
 * @param {import('three').Texture} texture one of target.textures
 * @param {number} type a three.js data type (HalfFloatType, FloatType)
 * @returns {boolean} whether the type changed (and the target was disposed)
 */
export function setTextureType(target, texture, type) {
  if (texture.type === type) return false;
  texture.type = type;
  target.dispose();
  return true;
}
