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
