// The one GLSL mechanism (src/support/glsl.js): local includes resolved once each, loud on an
// unknown or an unused chunk; enums as named defines; the library's shaders all assemble.
import { describe, it, expect } from 'vitest';
import { assembleGlsl, enumDefines, glslFloat, constantCase } from '../../../src/support/glsl.js';
import { DEBUG_VIEWS } from '../../../src/4-compose/debugViews.js';

describe('assembleGlsl', () => {
  it('replaces each local include by its chunk, once, recursively, and leaves three\'s includes alone', () => {
    const out = assembleGlsl('test', '#include <common>\n#include "a.glsl"\n#include "b.glsl"\nvoid main() {}', {
      'a.glsl': 'float a() { return 1.0; }',
      'b.glsl': '#include "a.glsl"\nfloat b() { return a(); }',
    });
    expect(out).toContain('#include <common>');
    expect(out.match(/float a\(\)/g)).toHaveLength(1);
    expect(out.indexOf('float a()')).toBeLessThan(out.indexOf('float b()'));
    expect(out).not.toMatch(/#include "/);
  });

  it('throws on an include that was not given, naming the shader and the chunk', () => {
    expect(() => assembleGlsl('SubsurfaceBlurPass', '#include "common/missing.glsl"', {})).toThrow(/SubsurfaceBlurPass.*"common\/missing\.glsl"/);
  });

  it('throws on a chunk given but never included', () => {
    expect(() => assembleGlsl('test', 'void main() {}', { 'common/finite.glsl': '' })).toThrow(/"common\/finite\.glsl" given but never included/);
  });

  it('throws on an include cycle', () => {
    expect(() => assembleGlsl('test', '#include "a.glsl"', { 'a.glsl': '#include "b.glsl"', 'b.glsl': '#include "a.glsl"' })).toThrow(/includes itself/);
  });
});

describe('enumDefines', () => {
  it('names every value and the current one, so reordering the list cannot change what a shader compares', () => {
    const defines = enumDefines('DEBUG_VIEW', DEBUG_VIEWS, 'mask');
    expect(defines.DEBUG_VIEW).toBe('DEBUG_VIEW_MASK');
    expect(defines.DEBUG_VIEW_MASK).toBe(DEBUG_VIEWS.indexOf('mask'));
    const reordered = enumDefines('DEBUG_VIEW', [...DEBUG_VIEWS].reverse(), 'mask');
    expect(reordered[reordered.DEBUG_VIEW]).toBe(reordered.DEBUG_VIEW_MASK);
    expect(new Set(Object.values(defines).filter((v) => typeof v === 'number')).size).toBe(DEBUG_VIEWS.length);
    expect(() => enumDefines('DEBUG_VIEW', DEBUG_VIEWS, 'nope')).toThrow(RangeError);
  });

  it('writes values in constant case', () => {
    expect(constantCase('skinBurley')).toBe('SKIN_BURLEY');
    expect(constantCase('off')).toBe('OFF');
  });
});

describe('glslFloat', () => {
  it('writes GLSL float literals', () => {
    expect(glslFloat(4)).toBe('4.0');
    expect(glslFloat(0.5)).toBe('0.5');
    expect(glslFloat(1e-7)).toBe('1e-7');
    expect(() => glslFloat(NaN)).toThrow(RangeError);
  });
});

describe("the library's shaders", () => {
  it('all assemble on import (every include found, no chunk unused)', async () => {
    const m = await import('../../../src/stages.js');
    expect(m.transmittanceChunk).toContain('float sssThicknessWorld(');
    expect(m.transmittanceChunk).toContain('vec3 sssReadProfile(');
  });
});

describe('enumerated options in the GLSL sources', () => {
  it('are compared with named values only, never with a number', async () => {
    const { readdirSync, readFileSync } = await import('node:fs');
    const { join } = await import('node:path');
    const root = new URL('../../../shaders/', import.meta.url).pathname;
    const files = readdirSync(root, { recursive: true }).filter((f) => f.endsWith('.glsl'));
    expect(files.length).toBeGreaterThan(10);
    const numeric = /\b(DEBUG_VIEW|FOLLOW_SURFACE|KERNEL_MODE|SSS_LIGHT_TYPE|sssDebugOutput)\s*[!=]=\s*\d/;
    for (const file of files) expect(readFileSync(join(root, file), 'utf8')).not.toMatch(numeric);
  });
});
