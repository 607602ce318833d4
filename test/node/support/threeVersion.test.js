// The supported three range in one place: package.json's peer range is src/support/threeVersion.js's,
// the devDependency is its newest release, and the material hook's error on a shader it cannot
// patch names the loaded three release and the range.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { MeshStandardMaterial, REVISION, ShaderLib } from 'three';
import { makeSubsurface } from '../../../src/stages.js';
import { SUPPORTED_THREE, SUPPORTED_THREE_RANGE, isSupportedThree } from '../../../src/support/threeVersion.js';

const pkg = JSON.parse(readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));

describe('supported three releases', () => {
  it('package.json peers on the range the version matrix tests; the devDependency is the newest', () => {
    expect(pkg.peerDependencies.three).toBe(SUPPORTED_THREE_RANGE);
    expect(SUPPORTED_THREE_RANGE).toBe('>=0.168.0 <0.188.0');
    expect(Number(REVISION)).toBe(SUPPORTED_THREE.newest);
    expect(isSupportedThree('168')).toBe(true);
    expect(isSupportedThree('167')).toBe(false);
    expect(isSupportedThree('188')).toBe(false);
  });

  it("the material hook's error on a shader without its injection points names three's release and the range", () => {
    const material = new MeshStandardMaterial();
    const binding = makeSubsurface(material);
    // The r153 shader still called the chunk output_fragment: what an unsupported three looks like.
    const oldShader = {
      uniforms: {}, defines: {}, vertexShader: ShaderLib.physical.vertexShader,
      fragmentShader: ShaderLib.physical.fragmentShader.replace('#include <opaque_fragment>', '#include <output_fragment>'),
    };
    expect(() => material.onBeforeCompile(oldShader, null)).toThrow(
      `"#include <opaque_fragment>" not found in the material's shader: three r${REVISION} is not supported (supported: three >=0.168.0 <0.188.0, r168 to r187)`);
    // The shader three ships passes.
    const shader = { uniforms: {}, defines: {}, vertexShader: ShaderLib.physical.vertexShader, fragmentShader: ShaderLib.physical.fragmentShader };
    expect(() => material.onBeforeCompile(shader, null)).not.toThrow();
    expect(shader.fragmentShader).toContain('sssDiffuseOutput');
    binding.dispose();
  });
});
