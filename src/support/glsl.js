// How GLSL is put together and how enums reach it.

const LOCAL_INCLUDE = /^[ \t]*#include[ \t]+"([^"]+)"[ \t]*$/gm;

/**
 * Pulls in the shader's own chunks (`#include "common/finite.glsl"`, a path under shaders/), each
 * once; three's `#include <chunk>` is left to three. A missing or unused chunk throws, so a renamed
 * one fails when the pass is built, not as a silently different shader.
 * @param {string} name who the shader belongs to, for messages (e.g. 'SubsurfaceBlurPass')
 * @param {string} source GLSL with `#include "path.glsl"` lines
 * @param {Record<string, string>} chunks every chunk this shader includes, by its path under shaders/
 * @returns {string} the source with every local include replaced by its chunk
 * @throws {Error} on an include without a chunk, an include cycle, or a chunk never included
 */
export function assembleGlsl(name, source, chunks = {}) {
  const used = new Set();
  const expand = (text, stack) => text.replace(LOCAL_INCLUDE, (line, path) => {
    if (!Object.hasOwn(chunks, path)) {
      throw new Error(`${name}: the shader includes "${path}", which was not given (given: ${Object.keys(chunks).join(', ') || 'none'})`);
    }
    if (stack.includes(path)) throw new Error(`${name}: "${path}" includes itself (${[...stack, path].join(' → ')})`);
    if (used.has(path)) return `// "${path}" is included above`;
    used.add(path);
    return `// ---- ${path}\n${expand(chunks[path], [...stack, path]).trimEnd()}\n// ---- end of ${path}`;
  });
  const out = expand(source, []);
  const unused = Object.keys(chunks).filter((path) => !used.has(path));
  if (unused.length > 0) throw new Error(`${name}: chunk${unused.length > 1 ? 's' : ''} ${unused.map((p) => `"${p}"`).join(', ')} given but never included`);
  return out;
}

/** 'followSurface' → 'FOLLOW_SURFACE', 'skinBurley' → 'SKIN_BURLEY'. */
export function constantCase(text) {
  return String(text).replace(/([a-z0-9])([A-Z])/g, '$1_$2').replace(/[^A-Za-z0-9]+/g, '_').toUpperCase();
}

/**
 * Named defines for an enumerated option, so shaders compare names (`#if DEBUG_VIEW ==
 * DEBUG_VIEW_MASK`), never an array position.
 * @param {string} prefix e.g. 'DEBUG_VIEW'
 * @param {ReadonlyArray<string>} values the accepted values, e.g. DEBUG_VIEWS
 * @param {string} current one of `values`
 * @returns {Record<string, number|string>}
 */
export function enumDefines(prefix, values, current) {
  if (!values.includes(current)) throw new RangeError(`${prefix}: ${JSON.stringify(current)} is not one of ${values.join(', ')}`);
  const defines = { [prefix]: `${prefix}_${constantCase(current)}` };
  values.forEach((value, i) => { defines[`${prefix}_${constantCase(value)}`] = i; });
  return defines;
}

/**
 * Sets defines on a material, flagging a recompile only when one changes.
 * @param {import('three').Material} material
 * @param {Record<string, number|string>} defines
 */
export function setDefines(material, defines) {
  for (const [key, value] of Object.entries(defines)) {
    if (material.defines[key] !== value) {
      material.defines[key] = value;
      material.needsUpdate = true;
    }
  }
}

/** 4 → '4.0': constants shared with the float64 oracle. */
export function glslFloat(value) {
  if (!Number.isFinite(value)) throw new RangeError(`glslFloat: ${value} is not finite`);
  const text = String(value);
  return /[.e]/.test(text) ? text : `${text}.0`;
}
