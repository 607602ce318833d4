// What a WebGL 2 context holds in textures and renderbuffers, counted from the storage calls three
// makes (texStorage2D, texImage2D, renderbufferStorage, renderbufferStorageMultisample) and the
// deletions, for the memory measurement (bench/memory.js): the bytes a pipeline allocates, per
// format and sample count, as the GPU is asked for them. Not part of the library.

/** Bytes per texel of the sized internal formats three asks for (WebGL 2 enums). */
const BYTES = new Map([
  [0x8058, 4], // RGBA8
  [0x8c43, 4], // SRGB8_ALPHA8
  [0x881a, 8], // RGBA16F
  [0x8814, 16], // RGBA32F
  [0x822f, 4], // RG16F
  [0x8230, 8], // RG32F
  [0x822d, 2], // R16F
  [0x822e, 4], // R32F
  [0x8d70, 16], // RGBA32UI
  [0x8229, 1], // R8
  [0x822b, 2], // RG8
  [0x81a5, 2], // DEPTH_COMPONENT16
  [0x81a6, 4], // DEPTH_COMPONENT24 (stored in 32 bits)
  [0x8cac, 4], // DEPTH_COMPONENT32F
  [0x88f0, 4], // DEPTH24_STENCIL8
  [0x8cad, 8], // DEPTH32F_STENCIL8
]);

/** The bytes per texel of an unsized texImage2D (format, type): RGBA of UNSIGNED_BYTE, FLOAT, HALF_FLOAT. */
const UNSIZED = { 0x1401: 1, 0x1406: 4, 0x140b: 2, 0x8d61: 2, 0x1405: 4, 0x1403: 2 };
const CHANNELS = { 0x1908: 4, 0x8227: 2, 0x1903: 1, 0x1907: 3, 0x1902: 1, 0x84f9: 1, 0x8d99: 4, 0x8228: 2, 0x8d94: 1 };

/**
 * Wraps `gl`'s allocation calls. Returns the live allocations' list, each { kind: 'texture' |
 * 'renderbuffer', width, height, samples, internalFormat, bytes } (a multisampled renderbuffer
 * counts every sample).
 * @param {WebGL2RenderingContext} gl
 * @returns {{ live: () => Array<object> }}
 */
export function trackAllocations(gl) {
  const allocations = new Map(); // WebGLTexture | WebGLRenderbuffer → allocation
  const boundTextures = new Map(); // `${unit}/${target}` → texture
  let unit = gl.TEXTURE0;
  let renderbuffer = null;
  const wrap = (name, after) => {
    const original = gl[name].bind(gl);
    gl[name] = (...args) => {
      const result = original(...args);
      after(...args);
      return result;
    };
  };
  const texture = (target) => boundTextures.get(`${unit}/${target}`);
  const record = (object, allocation) => {
    if (!object) return;
    if (!BYTES.has(allocation.internalFormat) && allocation.bytesPerTexel === undefined) throw new Error(`trackAllocations: internal format 0x${allocation.internalFormat.toString(16)} has no size here`);
    const perTexel = allocation.bytesPerTexel ?? BYTES.get(allocation.internalFormat);
    allocations.set(object, { ...allocation, bytes: allocation.width * allocation.height * (allocation.depth ?? 1) * Math.max(allocation.samples, 1) * perTexel });
  };
  wrap('activeTexture', (u) => { unit = u; });
  wrap('bindTexture', (target, t) => boundTextures.set(`${unit}/${target}`, t));
  wrap('bindRenderbuffer', (_, r) => { renderbuffer = r; });
  wrap('texStorage2D', (target, levels, internalFormat, width, height) => record(texture(target), { kind: 'texture', width, height, samples: 0, internalFormat }));
  wrap('texStorage3D', (target, levels, internalFormat, width, height, depth) => record(texture(target), { kind: 'texture', width, height, depth, samples: 0, internalFormat }));
  wrap('texImage2D', (...args) => {
    const [target, level, internalFormat, width, height, , format, type] = args;
    if (level !== 0 || args.length < 9) return; // a level's mip, or an image source (the plain frame has the same)
    const sized = BYTES.has(internalFormat);
    record(texture(target), { kind: 'texture', width, height, samples: 0, internalFormat, bytesPerTexel: sized ? undefined : (CHANNELS[format] ?? 4) * (UNSIZED[type] ?? 1) });
  });
  wrap('renderbufferStorage', (_, internalFormat, width, height) => record(renderbuffer, { kind: 'renderbuffer', width, height, samples: 0, internalFormat }));
  wrap('renderbufferStorageMultisample', (_, samples, internalFormat, width, height) => record(renderbuffer, { kind: 'renderbuffer', width, height, samples, internalFormat }));
  wrap('deleteTexture', (t) => allocations.delete(t));
  wrap('deleteRenderbuffer', (r) => allocations.delete(r));
  return { live: () => [...allocations.values()] };
}
