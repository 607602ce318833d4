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

describe('the settings a light needs, set at once in any key order (issue 40)', () => {
  /** Every order of `keys`. */
  const permutations = (keys) => (keys.length <= 1 ? [keys] : keys.flatMap((k, i) => permutations([...keys.slice(0, i), ...keys.slice(i + 1)]).map((rest) => [k, ...rest])));

  /** What a pipeline does with its settings: its lights' maps, the material's binding, the compose's view. */
  const pipelineState = (sss, skin) => {
    const { hook } = sss.materials.get(skin);
    return {
      maps: sss._lightDepths.map((d) => d.light.uuid),
      transmits: hook.transmittance?.map((t) => t.lightDepth.light.uuid) ?? null,
      output: hook.debugOutput,
      view: sss._composePass.material.defines.DEBUG_VIEW,
    };
  };
  /** The same of the WebGPU node: its light stage's light, whether the light's views show, the compose's view. */
  const nodeState = (node) => ({
    lights: node.lightDepths.map((d) => d.light.uuid),
    shown: node._uniforms.lightShown.value,
    view: node._uniforms.debugView.value,
  });

  // [label, the entry's options when made, the settings assigned at once]
  const cases = (light) => [
    ['transmittance and a light, made without one', {}, { transmittance: true, light }],
    ['transmittance off and a light', {}, { transmittance: false, light }],
    ["the thickness view and a light", {}, { debugView: 'thickness', light }],
    ["the transmittance view, transmittance and a light", { transmittance: false }, { debugView: 'transmittance', transmittance: true, light }],
    ['no light and the thickness view, made with a light', { light }, { light: null, debugView: 'thickness' }],
    ['no light and transmittance, made with a light', { light }, { light: null, transmittance: true }],
  ];

  it('the WebGL pipeline: every order is taken, reads back as set and leaves the same state', async () => {
    const THREE = await import('three');
    const SSS = await import('../../harness/sss.js');
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera();
    const light = new THREE.SpotLight();
    scene.add(light);
    const skin = new THREE.MeshStandardMaterial();
    for (const [label, made, settings] of cases(light)) {
      const states = permutations(Object.keys(settings)).map((order) => {
        const sss = new SSS.SubsurfaceScattering({ scene, camera, ...made });
        sss.makeSubsurface(skin);
        for (const key of order) sss[key] = settings[key];
        for (const [key, value] of Object.entries(settings)) expect(sss[key], `${label}, ${order}: ${key}`).toBe(value);
        const state = pipelineState(sss, skin);
        sss.dispose();
        return state;
      });
      for (const state of states) expect(state, label).toEqual(states[0]);
    }
    // Object.assign, as the issue wrote it: the light's transmittance reaches the material.
    const sss = Object.assign(new SSS.SubsurfaceScattering({ scene, camera }), { transmittance: true, light });
    sss.makeSubsurface(skin);
    expect(pipelineState(sss, skin)).toMatchObject({ maps: [light.uuid], transmits: [light.uuid] });
    sss.light = null;
    expect(sss.transmittance).toBe(true); // kept as set: it acts again with the next light
    expect(pipelineState(sss, skin)).toMatchObject({ maps: [], transmits: null });
    sss.light = light;
    expect(pipelineState(sss, skin)).toMatchObject({ maps: [light.uuid], transmits: [light.uuid] });
    sss.dispose();
    skin.dispose();
  });

  it('the WebGPU node: every order is taken, reads back as set and leaves the same state', async () => {
    const THREE = await import('three');
    const { pass } = await import('three/tsl');
    const NODE = await import('../../../src/webgpu/index.js');
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera();
    const light = new THREE.SpotLight();
    scene.add(light);
    for (const [label, made, settings] of cases(light)) {
      const states = permutations(Object.keys(settings)).map((order) => {
        const node = NODE.subsurfaceScattering(pass(scene, camera), made);
        for (const key of order) node[key] = settings[key];
        for (const [key, value] of Object.entries(settings)) expect(node[key], `${label}, ${order}: ${key}`).toBe(value);
        const state = nodeState(node);
        node.dispose();
        return state;
      });
      for (const state of states) expect(state, label).toEqual(states[0]);
    }
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
