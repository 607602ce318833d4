// Changing a render target texture's data type after three has allocated it: three sizes its
// buffers at their first use and keeps them, so the target is disposed for three to reallocate
// them, in the new type, on its next use (its clears and scissors then start over).

/**
 * Gives `texture` of `target` the data type `type`.
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
