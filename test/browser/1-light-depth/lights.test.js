// The lights a user has (issue 36), on the WebGL pipeline: `sss.light` assigned at any time (another
// light, of either kind, or none) gives what a pipeline made with that light gives; a light nearer
// than its shadow camera's near (0.5 by default) still shines through, its map fitted to the
// meshes, against the float64 oracle; what cannot be fitted is said in `sss.problems`.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { evaluateFloats, openPage, closeCheckedPage } from '../../harness/page.js';
import { transmittedFractionOracle } from '../../oracle/transmittance.js';
import { middle } from '../../harness/images.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(() => closeCheckedPage(page));

/**
 * In the page: a white slab `thicknessMm` thick (metres, 0.2 m wide) seen from the front, the
 * lights given by `lights(THREE)` (name → light, added to the scene, none shining from the front),
 * a pipeline made with the light named `made` (or none), and `steps(sss, lights)` (default: one
 * frame, 'made'): an array of [label, action] run in turn, each followed by a frame whose
 * diffuse attachment (float) is returned under its label, with `sss.light` and
 * `sss.transmittance` as they read then and the frame's problems.
 */
function slabFrames(options) {
  return evaluateFloats(page, async ({ thicknessMm, size, made, lightsSource, stepsSource }) => {
    const { THREE, SSS, createRenderer, createComposer, read } = window.lab;
    // eslint-disable-next-line no-new-func
    const lights = new Function('THREE', `return (${lightsSource})(THREE)`)(THREE);
    // eslint-disable-next-line no-new-func
    const steps = new Function(`return (${stepsSource})`)();
    const renderer = createRenderer(size, size);
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 10);
    camera.position.set(0, 0, 0.3);
    const skin = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0 });
    const slab = new THREE.Mesh(new THREE.BoxGeometry(0.2, 0.2, thicknessMm / 1000), skin);
    slab.name = 'slab';
    scene.add(slab);
    for (const light of Object.values(lights)) {
      scene.add(light, ...(light.target ? [light.target] : []));
      // A directional light's shadow box left at three's default (±5) is set to the slab's.
      if (light.isDirectionalLight && light.shadow.camera.left === -5) Object.assign(light.shadow.camera, { left: -0.15, right: 0.15, bottom: -0.15, top: 0.15 });
    }
    const sss = new SSS.SubsurfaceScattering({ scene, camera, light: made ? lights[made] : null, worldUnitInMm: 1000, type: THREE.FloatType });
    sss.makeSubsurface(skin);
    const composer = createComposer(renderer, { type: THREE.FloatType });
    composer.addPass(sss);
    const out = {};
    for (const [label, action] of steps(sss, lights, { THREE, SSS, scene, camera, skin, slab })) {
      action();
      composer.render();
      const name = Object.entries(lights).find(([, l]) => l === sss.light)?.[0] ?? (sss.light === null || typeof sss.light === 'string' ? sss.light : 'another');
      out[label] = { diffuse: await read(renderer, sss._scenePass.renderTarget, 1), light: name, transmittance: sss.transmittance, problems: [...sss.problems] };
    }
    sss.dispose();
    composer.dispose();
    renderer.dispose();
    return out;
  }, { ...options, lightsSource: options.lights.toString(), stepsSource: (options.steps ?? (() => [['made', () => {}]])).toString() });
}

const worst = (a, b) => a.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, Math.abs(v - b[i]))), 0);

describe('sss.light, assigned', () => {
  it('a light after none, another of the other kind, then none: each frame is the frame of a pipeline made with that light', async () => {
    const lights = (THREE) => {
      const sun = new THREE.DirectionalLight(0xffffff, Math.PI);
      sun.position.set(0, 0, -2); // straight behind
      Object.assign(sun.shadow.camera, { left: -0.15, right: 0.15, bottom: -0.15, top: 0.15, near: 0.5, far: 5 });
      const spot = new THREE.SpotLight(0xffffff, 4 * Math.PI, 0, Math.PI / 8, 0, 2);
      spot.position.set(0.1, 0.05, -1.5);
      Object.assign(spot.shadow.camera, { near: 0.5, far: 5 });
      return { sun, spot };
    };
    const r = await slabFrames({
      thicknessMm: 1, size: 64, lights,
      steps: (sss, { sun, spot }, { SSS, scene, camera, skin }) => {
        const made = (light) => () => { // a pipeline made with `light`, drawn once, for comparison
          const own = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 1000 });
          own.makeSubsurface(skin);
          own.dispose();
        };
        return [
          ['none', () => {}],
          ['sun', () => { sss.light = sun; }],
          ['spot', () => { sss.light = spot; }],
          ['spot again', made(spot)], // the binding of a pipeline made and disposed leaves ours as it was
          ['null', () => { sss.light = null; }],
          ['sun again', () => { sss.light = sun; }],
        ];
      },
    });
    expect(r.none.light).toBe(null);
    expect(r.none.transmittance).toBe(true); // the default, kept: it acts through the light there is
    expect(Math.max(...r.none.diffuse.filter((_, i) => i % 4 !== 3))).toBe(0); // nothing lights the front
    expect(r.sun).toMatchObject({ light: 'sun', transmittance: true, problems: [] });
    expect(middle(r.sun.diffuse, 64)[0]).toBeGreaterThan(0.3); // 1 mm of skin: red through
    expect(r.spot).toMatchObject({ light: 'spot', transmittance: true, problems: [] });
    expect(worst(r.spot.diffuse, r.sun.diffuse)).toBeGreaterThan(0.05); // the spot's picture, not the sun's
    expect(worst(r['spot again'].diffuse, r.spot.diffuse)).toBe(0);
    expect(r.null).toMatchObject({ light: null, transmittance: true, problems: [] }); // the default asks for nothing: no word
    expect(worst(r.null.diffuse, r.none.diffuse)).toBe(0);
    expect(worst(r['sun again'].diffuse, r.sun.diffuse)).toBe(0);
  });

  it('equals a pipeline made with the light, to the bit, after a swap from the other kind', async () => {
    const lights = (THREE) => {
      const sun = new THREE.DirectionalLight(0xffffff, Math.PI);
      sun.position.set(0.05, 0, -2);
      const spot = new THREE.SpotLight(0xffffff, 4 * Math.PI, 0, Math.PI / 8, 0.2, 2);
      spot.position.set(0.1, 0.05, -1.5);
      return { sun, spot };
    };
    const swapped = await slabFrames({
      thicknessMm: 1, size: 48, lights,
      steps: (sss, { sun, spot }) => [['spot', () => { sss.light = spot; }], ['sun', () => { sss.light = sun; }]],
    });
    const made = await slabFrames({ thicknessMm: 1, size: 48, lights, steps: (sss, { sun }) => [['sun', () => { sss.light = sun; }]] });
    expect(middle(made.sun.diffuse, 48)[0]).toBeGreaterThan(0.3);
    expect(worst(swapped.sun.diffuse, made.sun.diffuse)).toBe(0);
  });
});

describe('the settings a light needs, set at once (issue 40)', () => {
  const lights = (THREE) => {
    const sun = new THREE.DirectionalLight(0xffffff, Math.PI);
    sun.position.set(0, 0, -2); // straight behind
    return { sun };
  };
  const rgbMax = (rgba) => rgba.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, v)), 0);

  it('in either key order, on a pipeline made without a light: the frame of a pipeline made with it, to the bit; without one, the light\'s view is black and the frame says why', async () => {
    // The steps run in the page (their source is sent): one list per key order.
    const frames = (steps) => slabFrames({ thicknessMm: 1, size: 32, lights, steps });
    const forward = await frames((sss, { sun }) => [
      ['transmittance and the light', () => Object.assign(sss, { transmittance: true, light: sun })],
      ['no light and the thickness view', () => Object.assign(sss, { light: null, debugView: 'thickness' })],
      ['the light again', () => Object.assign(sss, { light: sun })],
    ]);
    const backward = await frames((sss, { sun }) => [
      ['transmittance and the light', () => Object.assign(sss, { light: sun, transmittance: true })],
      ['no light and the thickness view', () => Object.assign(sss, { debugView: 'thickness', light: null })],
      ['the light again', () => Object.assign(sss, { light: sun })],
    ]);
    const made = (await slabFrames({ thicknessMm: 1, size: 32, lights, made: 'sun' })).made;
    expect(rgbMax(made.diffuse)).toBeGreaterThan(0.3); // 1 mm of skin, back-lit: red through
    for (const label of Object.keys(forward)) {
      expect(worst(backward[label].diffuse, forward[label].diffuse), label).toBe(0);
      expect(backward[label].problems, label).toEqual(forward[label].problems);
      expect(backward[label].transmittance, label).toBe(true);
    }
    expect(worst(forward['transmittance and the light'].diffuse, made.diffuse)).toBe(0);
    expect(forward['transmittance and the light'].problems).toEqual([]);
    // No light: nothing transmitted, the thickness view black, both said.
    expect(rgbMax(forward['no light and the thickness view'].diffuse)).toBe(0);
    expect(forward['no light and the thickness view'].problems).toEqual([
      expect.stringMatching(/^transmittance is true but there is no light/),
      expect.stringMatching(/^debugView 'thickness' shows what the light gives, and there is no light/),
    ]);
    // The light back: the slab's 1 mm in the thickness view (profile mm), no word.
    const thickness = middle(forward['the light again'].diffuse, 32)[0];
    expect(thickness).toBeGreaterThan(0.8);
    expect(thickness).toBeLessThan(1.2);
    expect(forward['the light again'].problems).toEqual([]);
  });
});

describe('a light nearer than its shadow camera\'s near', () => {
  const SHRINK_MM = 0.6;
  // Straight behind, intensity π, wrap 1, entry cosine 1, white: the diffuse light is T(1 mm).
  const oracle = transmittedFractionOracle({ thicknessMm: 1, profile: 'skin', shrinkMm: SHRINK_MM, towardLightViewZ: -1 });

  it('a DirectionalLight 0.3 m behind a 1 mm slab (near 0.5 by default): the oracle\'s T(1 mm) within 2 % (before: 0)', async () => {
    const r = await slabFrames({
      thicknessMm: 1, size: 48,
      lights: (THREE) => {
        const sun = new THREE.DirectionalLight(0xffffff, Math.PI);
        sun.position.set(0, 0, -0.3);
        Object.assign(sun.shadow.camera, { left: -0.15, right: 0.15, bottom: -0.15, top: 0.15 }); // near 0.5, far 500: three's
        return { sun };
      },
      made: 'sun',
    });
    const mean = middle(r.made.diffuse, 48);
    expect(oracle[0]).toBeGreaterThan(0.3);
    for (let c = 0; c < 3; c++) {
      if (oracle[c] > 0.01) expect(Math.abs(mean[c] / oracle[c] - 1), `channel ${c}: GPU ${mean[c]}, oracle ${oracle[c]}`).toBeLessThan(0.02);
      else expect(Math.abs(mean[c] - oracle[c])).toBeLessThan(2e-4);
    }
    expect(r.made.problems).toEqual([]);
  });

  it("the README's first page with its spot light 0.45 m from the disc lights as many pixels through as at 0.56 m (before: 227 of 3809)", async () => {
    const lights = (THREE) => {
      const near = new THREE.SpotLight(0xffffff, 20, 0, Math.PI / 6, 0.3);
      near.position.set(0.2, 0.15, -0.5).setLength(0.45);
      const far = new THREE.SpotLight(0xffffff, 20, 0, Math.PI / 6, 0.3);
      far.position.set(0.2, 0.15, -0.5); // the README's, 0.56 m away
      return { near, far };
    };
    const disc = (sss, lights, { slab }) => { slab.rotation.y = 0.4; return [['made', () => {}]]; }; // the first page's disc, a square here
    const near = (await slabFrames({ thicknessMm: 4, size: 64, lights, made: 'near', steps: disc })).made;
    const far = (await slabFrames({ thicknessMm: 4, size: 64, lights, made: 'far', steps: disc })).made;
    const lit = (rgba) => rgba.filter((v, i) => i % 4 === 0 && v > 1e-3).length;
    expect(lit(far.diffuse)).toBeGreaterThan(1000);
    expect(lit(near.diffuse), `lit at 0.45 m: ${lit(near.diffuse)}, at 0.56 m: ${lit(far.diffuse)}`).toBeGreaterThan(0.9 * lit(far.diffuse));
    expect(near.problems).toEqual([]);
  });

  it('a spot light inside a transmitting mesh\'s bounds is said once in sss.problems, naming the mesh', async () => {
    const r = await slabFrames({
      thicknessMm: 1, size: 32,
      lights: (THREE) => {
        const inside = new THREE.SpotLight(0xffffff, 10, 0, Math.PI / 4);
        inside.position.set(0.05, 0, 0); // in the slab's box, pointing away from the camera
        inside.target.position.set(0.05, 0, -1);
        return { inside };
      },
      made: 'inside',
      steps: (sss, lights, { camera }) => [['inside', () => { camera.position.set(0, 0, -0.3); camera.lookAt(0, 0, 0); }], ['again', () => {}]],
    });
    expect(r.again.problems).toEqual([expect.stringMatching(/^the spot light is inside the bounds of mesh "slab", so its parts nearer than .* world units to the light are not in the light's depth map/)]);
  });
});

describe('several lights', () => {
  it('up to four, each with its own map: each alone, summed, equals all together (float read-backs), and the list reads back', async () => {
    const lights = (THREE) => {
      const behind = new THREE.DirectionalLight(0xffffff, Math.PI);
      behind.position.set(0, 0, -2);
      const oblique = new THREE.DirectionalLight(0xffccaa, 2);
      oblique.position.set(1.2, 0.3, -1.5);
      const spot = new THREE.SpotLight(0xaaccff, 6 * Math.PI, 0, Math.PI / 10, 0.3, 2);
      spot.position.set(-0.1, 0.05, -1.2);
      const low = new THREE.SpotLight(0xffffff, 3 * Math.PI, 0, Math.PI / 6, 0.5, 2);
      low.position.set(0.05, -0.4, -0.8);
      return { behind, oblique, spot, low };
    };
    const r = await slabFrames({
      thicknessMm: 1.5, size: 48, lights,
      steps: (sss, l) => [
        ['behind', () => { sss.light = l.behind; }], ['oblique', () => { sss.light = [l.oblique]; }],
        ['spot', () => { sss.light = l.spot; }], ['low', () => { sss.light = l.low; }],
        ['all', () => { sss.light = [l.behind, l.oblique, l.spot, l.low]; }],
        ['two', () => { sss.light = [l.spot, l.behind]; }],
      ],
    });
    const names = ['behind', 'oblique', 'spot', 'low'];
    for (const name of names) expect(Math.max(...r[name].diffuse.filter((_, i) => i % 4 === 0)), name).toBeGreaterThan(0.01); // each sends light
    const sum = (labels) => r.all.diffuse.map((_, i) => labels.reduce((s, label) => s + r[label].diffuse[i], 0));
    const relative = (a, b) => a.reduce((m, v, i) => (i % 4 === 3 ? m : Math.max(m, Math.abs(v - b[i]) / Math.max(1e-3, Math.abs(b[i])))), 0);
    expect(relative(r.all.diffuse, sum(names)), 'four together against the four alone, summed').toBeLessThan(1e-5);
    expect(relative(r.two.diffuse, sum(['spot', 'behind'])), 'two').toBeLessThan(1e-5);
    expect(r.all.light).toBe('another'); // a list (not one of the lights)
    expect(r.all.problems).toEqual([]);
  });

  it("'castShadow': the scene's shadow-casting lights, found each frame (the same floats as listing them), more than four said in problems", async () => {
    const lights = (THREE) => {
      const sun = new THREE.DirectionalLight(0xffffff, Math.PI);
      sun.position.set(0, 0, -2);
      const spot = new THREE.SpotLight(0xaaccff, 6 * Math.PI, 0, Math.PI / 10, 0.3, 2);
      spot.position.set(-0.1, 0.05, -1.2);
      const bulb = new THREE.PointLight(0xffccaa, 2, 0, 2);
      bulb.position.set(0.2, 0, -0.6);
      sun.castShadow = spot.castShadow = true; // the bulb casts none
      return { sun, spot, bulb };
    };
    const r = await slabFrames({
      thicknessMm: 1.5, size: 48, lights,
      steps: (sss, l, { THREE, scene }) => {
        const extra = Array.from({ length: 3 }, () => Object.assign(new THREE.SpotLight(0xffffff, 0), { castShadow: true }));
        return [
          ['listed', () => { sss.light = [l.sun, l.spot]; }],
          ['castShadow', () => { sss.light = 'castShadow'; }],
          ['one casts', () => { l.spot.castShadow = false; }],
          ['sun', () => { sss.light = l.sun; }],
          ['five cast', () => { l.spot.castShadow = true; scene.add(...extra); sss.light = 'castShadow'; }],
        ];
      },
    });
    expect(Math.max(...r.listed.diffuse.filter((_, i) => i % 4 === 0))).toBeGreaterThan(0.05);
    expect(worst(r.castShadow.diffuse, r.listed.diffuse)).toBe(0);
    expect(r.castShadow.light).toBe('castShadow');
    expect(worst(r['one casts'].diffuse, r.sun.diffuse)).toBe(0);
    expect(r['five cast'].problems).toEqual(['5 lights cast shadows: transmittance comes from the first 4 in the scene\'s order (list the ones you want in `light`)']);
  });

  it("each light's problem is its own, naming the light as the user named it", async () => {
    const r = await slabFrames({
      thicknessMm: 1, size: 16,
      lights: (THREE) => {
        const key = Object.assign(new THREE.DirectionalLight(0xffffff, 1), { name: 'key' });
        const rim = Object.assign(new THREE.SpotLight(0xffffff, 1), { name: 'rim' });
        key.position.set(0, 0, -2);
        rim.position.set(0.1, 0, -1);
        return { key, rim };
      },
      steps: (sss, { key, rim }, { scene }) => [['both', () => { sss.light = [key, rim]; key.intensity = NaN; scene.remove(rim); }]],
    });
    expect(r.both.problems).toEqual([
      'the light "key"\'s color (1, 1, 1) or intensity (NaN) is not finite: three lights the scene with NaN from it, drawn black here, and there is no transmittance until both are finite',
      'the light "rim" is not in the scene (removed, or never added): there is no transmittance until it is added (with its target), or set transmittance to false',
    ]);
  });

  it('a list is read back as given, frozen; more than four or a light twice are refused', async () => {
    const r = await page.evaluate(() => {
      const { THREE, SSS } = window.lab;
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera();
      const a = new THREE.SpotLight();
      const b = new THREE.DirectionalLight();
      const sss = new SSS.SubsurfaceScattering({ scene, camera, light: [a, b] });
      const errors = [];
      for (const bad of [[a, b, a], [a, b, new THREE.SpotLight(), new THREE.SpotLight(), new THREE.SpotLight()], [], [a, new THREE.AmbientLight()]]) {
        try { sss.light = bad; } catch (error) { errors.push(`${error.name}: ${error.message}`); }
      }
      const out = { same: sss.light[0] === a && sss.light[1] === b && sss.light.length === 2, frozen: Object.isFrozen(sss.light), transmittance: sss.transmittance, errors };
      sss.dispose();
      return out;
    });
    expect(r).toMatchObject({ same: true, frozen: true, transmittance: true });
    expect(r.errors).toEqual([
      'RangeError: light lists a light twice',
      'RangeError: light must list 1 to 4 lights, got 5',
      'RangeError: light must list 1 to 4 lights, got 0',
      'TypeError: light[1] must be a THREE.SpotLight, THREE.DirectionalLight or THREE.PointLight, got an AmbientLight',
    ]);
  });
});

describe('a PointLight', () => {
  const SHRINK_MM = 0.6;
  const oracle = transmittedFractionOracle({ thicknessMm: 1, profile: 'skin', shrinkMm: SHRINK_MM, towardLightViewZ: -1 });

  it("among transmitting meshes (its map: six faces), straight behind a 1 mm slab along +z, +x, −y and −z: the oracle's T(1 mm) within 2 %", async () => {
    const r = await slabFrames({
      thicknessMm: 1, size: 48, made: 'bulb',
      lights: (THREE) => ({ bulb: new THREE.PointLight(0xffffff, Math.PI * 4, 0, 2) }), // π at 2 m with decay 2: irradiance π
      steps: (sss, { bulb }, { THREE, scene, camera, skin, slab }) => {
        // A second transmitting mesh beyond the light: the meshes surround it, so it takes six faces.
        const beyond = new THREE.Mesh(new THREE.BoxGeometry(0.1, 0.1, 0.1), skin);
        scene.add(beyond);
        const facing = (n) => () => { // the slab's front towards n, the camera there, the light behind
          const normal = new THREE.Vector3(...n);
          slab.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
          camera.up.set(0, n[1] === 0 ? 1 : 0, n[1] === 0 ? 0 : 1);
          camera.position.copy(normal).multiplyScalar(0.3);
          camera.lookAt(0, 0, 0);
          bulb.position.copy(normal).multiplyScalar(-2);
          beyond.position.copy(normal).multiplyScalar(-4);
        };
        return [['+z', facing([0, 0, 1])], ['+x', facing([1, 0, 0])], ['-y', facing([0, -1, 0])], ['-z', facing([0, 0, -1])]];
      },
    });
    // At the middle's edge the light is 0.7° off the axis: T, the entry cosine and the falloff change by under 0.1 %.
    for (const face of ['+z', '+x', '-y', '-z']) {
      const mean = middle(r[face].diffuse, 48);
      for (let c = 0; c < 3; c++) {
        if (oracle[c] > 0.01) expect(Math.abs(mean[c] / oracle[c] - 1), `${face}, channel ${c}: GPU ${mean[c]}, oracle ${oracle[c]}`).toBeLessThan(0.02);
        else expect(Math.abs(mean[c] - oracle[c]), `${face}, channel ${c}`).toBeLessThan(2e-4);
      }
      expect(r[face].problems).toEqual([]);
    }
  });

  it('aimed at the meshes where they fit a cone of 120° (one map): what a spot light at its place gives, within 1e-4 of the lit level', async () => {
    const lights = (THREE) => {
      const bulb = new THREE.PointLight(0xffffff, 2, 0, 2);
      bulb.position.set(-0.5, 0, -0.5);
      const spot = new THREE.SpotLight(0xffffff, 2, 0, Math.PI / 4, 0, 2); // its cone edge outside the slab: no cone falloff on it
      spot.position.copy(bulb.position);
      return { bulb, spot };
    };
    // The slab turned to face the light (seen by the camera at 45°).
    const turned = (sss, l, { slab }) => { slab.rotation.y = Math.PI / 4; return [['made', () => {}]]; };
    const point = (await slabFrames({ thicknessMm: 1, size: 48, lights, made: 'bulb', steps: turned })).made.diffuse;
    const spot = (await slabFrames({ thicknessMm: 1, size: 48, lights, made: 'spot', steps: turned })).made.diffuse;
    const lit = Math.max(...spot.filter((_, i) => i % 4 === 0));
    expect(lit).toBeGreaterThan(0.05);
    expect(worst(point, spot) / lit).toBeLessThan(1e-4);
  });
});
