// Several lights in the material's GLSL (issue 36): one call of sssTransmittedFrom per light, as
// many as MAX_LIGHTS (a sampler array is indexed by constants only, so the calls are written out),
// and each call reading its own map.
import { describe, it, expect } from 'vitest';
import { MAX_LIGHTS } from '../../../src/options.js';
import transmittedLight from '../../../shaders/2-scene-split/material/transmittedLight.glsl?raw';

describe('the material reads every light', () => {
  it(`calls sssTransmittedFrom once per light, 0 to ${MAX_LIGHTS - 1}, each with its own map`, () => {
    const calls = [...transmittedLight.matchAll(/sssTransmittedFrom\( (\d+), sssLightDepthMaps\[ (\d+) \]/g)].map(([, i, map]) => [Number(i), Number(map)]);
    expect(calls).toEqual(Array.from({ length: MAX_LIGHTS }, (_, i) => [i, i]));
  });
});

describe('the light and transmittance settings, in any order', () => {
  it("a light arriving keeps transmittance off where it was set off (Object.assign's order does not matter), and on by default", async () => {
    const THREE = await import('three');
    const SSS = await import('../../harness/sss.js');
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera();
    const light = new THREE.SpotLight();
    scene.add(light);
    const make = () => new SSS.SubsurfaceScattering({ scene, camera });
    const a = Object.assign(make(), { transmittance: false, light });
    const b = Object.assign(make(), { light, transmittance: false });
    expect([a.transmittance, b.transmittance]).toEqual([false, false]);
    a.light = null;
    a.light = [light];
    expect(a.transmittance).toBe(false); // still off: the user's setting, not the light's arrival
    const c = Object.assign(make(), { light });
    expect(c.transmittance).toBe(true); // the default, on where there is a light
    c.light = null;
    expect(c.transmittance).toBe(false);
    c.light = light;
    expect(c.transmittance).toBe(true);
    for (const sss of [a, b, c]) sss.dispose();
  });
});

describe('a setting without a default', () => {
  it('strength and falloff take undefined back (the method\'s own), on the pipeline and in its blur', async () => {
    const THREE = await import('three');
    const SSS = await import('../../harness/sss.js');
    const sss = new SSS.SubsurfaceScattering({ scene: new THREE.Scene(), camera: new THREE.PerspectiveCamera(), method: 'reference' });
    sss.strength = [0.2, 0.3, 0.4];
    expect(sss._blur.kernelOptions.strength).toEqual([0.2, 0.3, 0.4]);
    sss.strength = undefined;
    expect(sss.strength).toBeUndefined();
    expect(sss._blur.kernelOptions.strength).toBeUndefined();
    expect(() => { sss.strength = null; }).toThrow(/^strength must be an array of 3 finite numbers/); // null is no RGB
    sss.dispose();
  });
});
