// The user's shader hooks and ours on one material (issue 41), as three calls them: a material's
// onBeforeCompile, customProgramCacheKey and onBeforeRender, set before or after makeSubsurface, by
// hand or by a library. Version 0.3 replaced a hook set after makeSubsurface with the user's alone
// (the split gone, INVALID_OPERATION every frame), keyed every subsurface program alike (two hooks,
// one program) and restored the hook it found first.
import { describe, it, expect } from 'vitest';
import { Material, MeshStandardMaterial, ShaderChunk, ShaderLib } from 'three';
import { makeSubsurface } from '../../../src/stages.js';
import { uncomposedReason } from '../../../src/2-scene-split/subsurfaceMaterial.js';
import { userProgramKeyOf, userShaderHook } from '../../../src/support/userHooks.js';

/** three's shader for a MeshStandardMaterial, as onBeforeCompile receives it. */
const shaderOf = () => ({ uniforms: {}, defines: {}, vertexShader: ShaderLib.physical.vertexShader, fragmentShader: ShaderLib.physical.fragmentShader });

/** A wind sway as three.js users write it: a uniform and a move of `transformed`. */
const sway = (amplitude) => function swayHook(shader) {
  shader.uniforms.time = { value: 0 };
  shader.vertexShader = `uniform float time;\n${shader.vertexShader.replace('#include <begin_vertex>', `#include <begin_vertex>\n\ttransformed.x += ${amplitude.toFixed(3)} * sin( time + position.y );`)}`;
};

/** Compiles `material` as three does: its onBeforeCompile on a fresh shader, called as its method. */
function compile(material) {
  const shader = shaderOf();
  material.onBeforeCompile(shader, null);
  return shader;
}

describe("the user's hooks compose with ours, in any order", () => {
  it('a hook set before makeSubsurface runs, then ours', () => {
    const material = new MeshStandardMaterial();
    material.onBeforeCompile = sway(0.1);
    const binding = makeSubsurface(material);
    const shader = compile(material);
    expect(shader.vertexShader).toContain('transformed.x += 0.100');
    expect(shader.fragmentShader).toContain('sssDiffuseOutput');
    expect(shader.uniforms.time).toEqual({ value: 0 });
    binding.dispose();
  });

  it('a hook set after makeSubsurface runs, then ours; the program key holds it, as three keys a hook', () => {
    const [a, b, c] = [new MeshStandardMaterial(), new MeshStandardMaterial(), new MeshStandardMaterial()];
    const bindings = [a, b, c].map((m) => makeSubsurface(m));
    const plainKey = a.customProgramCacheKey();
    a.onBeforeCompile = sway(0.1);
    b.onBeforeCompile = sway(0.2); // same source text: three keys it alike (a closure's value is not in its text)
    c.onBeforeCompile = (shader) => { shader.vertexShader = shader.vertexShader.replace('#include <begin_vertex>', '#include <begin_vertex>\n\ttransformed.y += 0.3;'); };
    const shader = compile(a);
    expect(shader.vertexShader).toContain('transformed.x += 0.100');
    expect(shader.fragmentShader).toContain('sssDiffuseOutput');
    expect(shader.vertexShader).toContain('sssHidden');
    expect(a.customProgramCacheKey()).not.toBe(plainKey);
    expect(a.customProgramCacheKey()).toBe(`${sway(0.1)}|subsurface1`); // three's default key of the hook, then ours
    expect(c.customProgramCacheKey()).not.toBe(a.customProgramCacheKey());
    // A key of the user's own is theirs to make: b's tells its amplitude apart.
    b.customProgramCacheKey = () => 'sway 0.2';
    expect(b.customProgramCacheKey()).toBe('sway 0.2|subsurface1');
    bindings.forEach((binding) => binding.dispose());
  });

  it("the user's onBeforeRender runs before ours, set before or after", () => {
    const material = new MeshStandardMaterial();
    const calls = [];
    material.onBeforeRender = () => calls.push('before');
    const binding = makeSubsurface(material);
    const renderer = { getRenderTarget: () => null };
    material.onBeforeRender(renderer, null, null, null, null, null);
    material.onBeforeRender = function (r) { calls.push(this === material && r === renderer ? 'after' : 'wrong this'); };
    material.onBeforeRender(renderer, null, null, null, null, null);
    expect(calls).toEqual(['before', 'after']);
    binding.dispose();
  });

  it('removing the subsurface puts back exactly what the user holds now (0.3: the hook it found first)', () => {
    const material = new MeshStandardMaterial();
    const first = sway(0.1);
    material.onBeforeCompile = first;
    const binding = makeSubsurface(material);
    const now = (shader) => { shader.defines.MINE = 1; };
    material.onBeforeCompile = now;
    const key = () => 'mine';
    material.customProgramCacheKey = key;
    binding.dispose();
    expect(material.onBeforeCompile).toBe(now);
    expect(material.customProgramCacheKey).toBe(key);
    expect(Object.hasOwn(material, 'onBeforeRender')).toBe(false); // never set: three's own, from the prototype
    // Made subsurface again, the user's hook of now runs under ours.
    const again = makeSubsurface(material);
    const shader = compile(material);
    expect(shader.defines.MINE).toBe(1);
    expect(shader.fragmentShader).toContain('sssDiffuseOutput');
    again.dispose();
    expect(material.onBeforeCompile).toBe(now);
  });

  it("a library's hook that chains what it read from the material (ours) runs ours once", () => {
    const material = new MeshStandardMaterial();
    const binding = makeSubsurface(material);
    const previous = material.onBeforeCompile;
    material.onBeforeCompile = function (shader, renderer) {
      previous.call(this, shader, renderer);
      shader.fragmentShader = shader.fragmentShader.replace('#include <color_fragment>', '#include <color_fragment>\n\tdiffuseColor.rgb *= 0.5;');
    };
    const previousKey = material.customProgramCacheKey;
    material.customProgramCacheKey = function () { return `${previousKey.call(this)}|tinted`; };
    const shader = compile(material);
    expect(shader.fragmentShader.split('sssDiffuseOutput =').length - 1).toBe(1);
    expect(shader.fragmentShader).toContain('diffuseColor.rgb *= 0.5');
    expect(material.customProgramCacheKey()).toBe('|tinted|subsurface1');
    binding.dispose();
  });

  it("a library material's hooks from its class (three-custom-shader-material style) compose and stay the class's", () => {
    class TintedMaterial extends MeshStandardMaterial {
      onBeforeCompile(shader) { shader.fragmentShader = shader.fragmentShader.replace('#include <color_fragment>', '#include <color_fragment>\n\tdiffuseColor.rgb *= vec3( 0.2, 0.8, 0.3 );'); }

      customProgramCacheKey() { return 'tinted'; }
    }
    const material = new TintedMaterial();
    const binding = makeSubsurface(material);
    const shader = compile(material);
    expect(shader.fragmentShader).toContain('vec3( 0.2, 0.8, 0.3 )');
    expect(shader.fragmentShader).toContain('sssDiffuseOutput');
    expect(material.customProgramCacheKey()).toBe('tinted|subsurface1');
    binding.dispose();
    expect(Object.hasOwn(material, 'onBeforeCompile')).toBe(false);
    expect(material.onBeforeCompile).toBe(TintedMaterial.prototype.onBeforeCompile);
  });

  it("a hook that takes out a point the split goes in at: drawn as three draws it (its outputs declared, clipped in the split call), and the reason names the material", () => {
    const material = new MeshStandardMaterial({ name: 'Custom' });
    // It inlines a chunk, as three-custom-shader-material's expansion maps do.
    material.onBeforeCompile = (shader) => { shader.fragmentShader = shader.fragmentShader.replace('#include <lights_fragment_end>', ShaderChunk.lights_fragment_end); };
    const binding = makeSubsurface(material);
    expect(uncomposedReason(material)).toBe(null); // known when three compiles it
    const shader = compile(material);
    expect(uncomposedReason(material)).toBe('material "Custom": its onBeforeCompile takes "#include <lights_fragment_end>" out of three\'s fragment shader, where the subsurface split goes in, so it is drawn as three draws it, without scattering or transmittance');
    expect(shader.fragmentShader).toContain('out highp vec4 sssDiffuseOutput');
    expect(shader.fragmentShader).toMatch(/#define main sssMaterialMain[\s\S]*#undef main[\s\S]*sssDiffuseOutput = vec4\( 0.0 \);/);
    expect(shader.vertexShader).toMatch(/#define main sssMaterialMain[\s\S]*#undef main[\s\S]*sssMaterialMain\(\);/);
    binding.dispose();
  });

  it("the light's depth pass reads the user's hook and key, composed with ours or not; a frozen material is refused", () => {
    const plain = new MeshStandardMaterial();
    expect(userShaderHook(plain)).toBe(null);
    const hook = sway(0.1);
    plain.onBeforeCompile = hook;
    expect([userShaderHook(plain), userProgramKeyOf(plain)]).toEqual([hook, String(hook)]);
    const binding = makeSubsurface(plain);
    expect([userShaderHook(plain), userProgramKeyOf(plain)]).toEqual([hook, String(hook)]); // not ours
    binding.dispose();
    expect(Material.prototype.onBeforeCompile).not.toBe(hook);
    const frozen = Object.freeze(new MeshStandardMaterial());
    expect(() => makeSubsurface(frozen)).toThrow(new TypeError('makeSubsurface: material.onBeforeCompile cannot be redefined (the material is frozen or sealed), so its shader cannot be patched'));
  });
});
