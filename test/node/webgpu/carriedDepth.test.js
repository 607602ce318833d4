// The WebGPU blur carries the depth in its light's alpha by the GLSL's rule: its constant is
// shaders/common/carriedDepth.glsl's, one value in two languages.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { DEPTH_ZERO } from '../../../src/webgpu/common/surfaceTsl.js';

describe('the carried depth', () => {
  it("marks a depth of 0 with carriedDepth.glsl's SSS_DEPTH_ZERO, a normal float", () => {
    const glsl = readFileSync(new URL('../../../shaders/common/carriedDepth.glsl', import.meta.url), 'utf8');
    const [, value] = glsl.match(/#define SSS_DEPTH_ZERO (\S+)/);
    expect(DEPTH_ZERO).toBe(Number(value));
    expect(Math.fround(DEPTH_ZERO)).toBeGreaterThan(1.2e-38); // not flushed to zero in 32 bits
  });
});
