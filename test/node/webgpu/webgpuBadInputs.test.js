// The bad-input table (test/reliability/badInputs.js) on the WebGPURenderer node's API, in plain
// Node: every line of the table that names an option or a call the node has runs against the node
// (the fixture's `make` builds subsurfaceScattering(pass(scene, camera), options), its `sss` is a
// node, `sss.makeSubsurface` is subsurfaceMaterial), and must give the same error with the same
// message as on the WebGL pipeline. Then the node's own cases.
import { describe, it, expect } from 'vitest';
import * as THREE from 'three';
import { pass } from 'three/tsl';
import * as SSS from '../../harness/sss.js';
import * as NODE from '../../../src/webgpu/index.js';
import { CALL_CASES } from '../../reliability/badInputs.js';
import { createFixture, expectRead } from '../../reliability/fixture.js';
import { expectOutcome } from '../../reliability/expectError.js';

/** The table's lines about what the node has too: construction options, kernel, depth rule, width. */
const NODE_LINES = [
  /^worldUnitInMm: /, /^profile/, /^method: /, /^samples: /, /^strength: /, /^followSurface: /, /^depthThresholdMm: /,
  /^foreshortening: /, /^sss\.worldUnitInMm = /, /^samples = /, /^method = /, /^profile = /, /^strength = /, /^followSurface = /,
  /^depthThresholdMm = /, /^foreshortening = /, /^debugView = /, /^debugDepthRange = /, /^widthMm: /,
  /^light: /, /^lightDepthSize: /, /^transmittance = /, /^transmittance: /, /^translucency: /, /^shrinkMm: /, /^debugThicknessRangeMm = /,
  /^debugView: /, /^Object\.assign\(sss, /, /^sss\.scattering = /, /^sss\.transmittance = /, /^sss\.light = /, /^kernelGroups: (\d+|'\w+')$/, /with transmission\)$/,
];
const NODE_OPTIONS = Object.keys(NODE.NODE_DEFAULTS);

/** The WebGL fixture's scene with the node in place of the pipeline. */
function nodeFixture() {
  const t = createFixture(THREE, SSS);
  const made = [];
  const make = (options = {}) => {
    const kept = Object.fromEntries(Object.entries({ worldUnitInMm: 100, ...options }).filter(([key]) => NODE_OPTIONS.includes(key)));
    const node = NODE.subsurfaceScattering(pass(t.scene, t.camera), kept);
    node.makeSubsurface = (material, materialOptions) => NODE.subsurfaceMaterial(material, materialOptions);
    made.push(node);
    return node;
  };
  let node = null;
  const { THREE: three, scene, camera, material, mesh, light, nanProfile, changedProfile } = t; // not its getters (they make a WebGL pipeline)
  return {
    THREE: three, SSS, scene, camera, material, mesh, light, nanProfile, changedProfile, expectRead,
    NODE,
    make,
    get sss() {
      node ??= make();
      return node;
    },
    dispose() {
      for (const n of made) n.dispose();
      t.dispose();
    },
  };
}

/** Runs `run(t)` and checks the error it throws. */
function expectError(run, expected, fragment) {
  const t = nodeFixture();
  try {
    expectOutcome(run, t, expected, fragment);
  } finally {
    t.dispose();
  }
}

const lines = CALL_CASES.filter(([input]) => NODE_LINES.some((line) => line.test(input)));

describe("the bad-input table on the node's API, in Node", () => {
  it('covers every kind of line it names (none of the patterns matches nothing)', () => {
    for (const line of NODE_LINES) expect(lines.some(([input]) => line.test(input)), String(line)).toBe(true);
    expect(lines.length).toBeGreaterThan(40);
  });

  for (const [input, run, expected, fragment] of lines) {
    it(`${input}: ${expected} ${fragment}`, () => expectError(run, expected, fragment));
  }
});

/** The node's own lines: [input, run(t), expected, message fragment], as in the table. */
const NODE_CASES = [
  ['subsurfaceScattering()', (t) => t.NODE.subsurfaceScattering(), 'TypeError', /scenePass must be a PassNode \(pass\(scene, camera\)\), got undefined/],
  ['subsurfaceScattering(scene)', (t) => t.NODE.subsurfaceScattering(t.scene), 'TypeError', /scenePass must be a PassNode .*got a Scene/],
  ['options: null', (t) => t.NODE.subsurfaceScattering(pass(t.scene, t.camera), null), 'TypeError', /subsurfaceScattering options must be an object, got null/],
  ['a misspelt option', (t) => t.NODE.subsurfaceScattering(pass(t.scene, t.camera), { sampels: 17 }), 'TypeError', /^subsurfaceScattering options: unknown option "sampels" \(accepted: light, worldUnitInMm, profile, method, samples, /],
  ["a WebGL pipeline's option", (t) => t.NODE.subsurfaceScattering(pass(t.scene, t.camera), { multisampling: 4 }), 'TypeError', /unknown option "multisampling"/],
  ["method: 'marginal' (WebGL only)", (t) => t.make({ method: 'marginal' }), 'RangeError', /method 'marginal' is not available on the WebGPU node \(only 'footprint'/],
  ["method = 'reference'", (t) => { t.sss.method = 'reference'; }, 'RangeError', /^method 'reference' is not available on the WebGPU node/],
  // The WebGL pipeline's lights and refusals (test/browser/1-light-depth/lights.test.js asks the same of it).
  ['light: a PointLight: taken', (t) => t.make({ light: new t.THREE.PointLight() }), 'ok'],
  ['light = two lights: taken', (t) => { t.sss.light = [t.light, new t.THREE.PointLight()]; }, 'ok'],
  ["light: 'castShadow': taken", (t) => t.make({ light: 'castShadow' }), 'ok'],
  ['light = [one light]: taken', (t) => { t.sss.light = [t.light]; }, 'ok'],
  ['light = a light twice', (t) => { t.sss.light = [t.light, t.light]; }, 'RangeError', /^light lists a light twice$/],
  ['light = five lights', (t) => { t.sss.light = Array.from({ length: 5 }, () => new t.THREE.SpotLight()); }, 'RangeError', /^light must list 1 to 4 lights, got 5$/],
  ['light: []', (t) => t.make({ light: [] }), 'RangeError', /^light must list 1 to 4 lights, got 0$/],
  ['light = [a light, an AmbientLight]', (t) => { t.sss.light = [t.light, new t.THREE.AmbientLight()]; }, 'TypeError', /^light\[1\] must be a THREE\.SpotLight, THREE\.DirectionalLight or THREE\.PointLight, got an AmbientLight$/],
  ["debugView = 'thickness' with a light: taken", (t) => { t.make({ light: t.light }).debugView = 'thickness'; }, 'ok'],
  ['subsurfaceMaterial(null)', (t) => t.NODE.subsurfaceMaterial(null), 'TypeError', /subsurfaceMaterial: material must be a THREE\.MeshStandardMaterial or MeshPhysicalMaterial \(or its node version\), got null/],
  ['subsurfaceMaterial(a MeshBasicMaterial)', (t) => t.NODE.subsurfaceMaterial(new t.THREE.MeshBasicMaterial()), 'TypeError', /material must be .*got a MeshBasicMaterial/],
  ['subsurfaceMaterial(material, null)', (t) => t.NODE.subsurfaceMaterial(t.material, null), 'TypeError', /subsurfaceMaterial options must be an object, got null/],
  ['subsurfaceMaterial(material, { widthmm })', (t) => t.NODE.subsurfaceMaterial(t.material, { widthmm: 2 }), 'TypeError', /subsurfaceMaterial options: unknown option "widthmm" \(accepted: widthMm, transmittance, translucency, shrinkMm\)/],
  ["material.widthMm = 'wide'", (t) => { t.NODE.subsurfaceMaterial(t.material).widthMm = 'wide'; }, 'TypeError', /widthMm must be a finite number, got "wide"/],
  ['material.translucency = 1', (t) => { t.NODE.subsurfaceMaterial(t.material).translucency = 1; }, 'RangeError', /translucency must be in \[0, 1\), got 1/],
  ['material.shrinkMm = -1', (t) => { t.NODE.subsurfaceMaterial(t.material).shrinkMm = -1; }, 'RangeError', /shrinkMm must be in \[0, 1000\] mm, got -1/],
  ["material.transmittance = 'yes'", (t) => { t.NODE.subsurfaceMaterial(t.material).transmittance = 'yes'; }, 'TypeError', /transmittance must be a boolean \(true or false\), got "yes"/],
];

describe("the node's own bad inputs", () => {
  for (const [input, run, expected, fragment] of NODE_CASES) {
    it(`${input}: ${expected} ${fragment}`, () => expectError(run, expected, fragment));
  }

  it('takes what the table lets through: a good node and material, no error', () => {
    const t = nodeFixture();
    try {
      const node = t.make({ profile: 'skinBurley', samples: 17, strength: [1, 0.5, 0.25], followSurface: 'lerp', depthThresholdMm: 3, foreshortening: false });
      Object.assign(node, { samples: 'auto', profile: 'marble' });
      expect(node.profile.name).toBe('marble');
      const skin = t.NODE.subsurfaceMaterial(new t.THREE.MeshPhysicalMaterial({ clearcoat: 1 }), { widthMm: 2 });
      expect(skin.isSubsurfaceNodeMaterial && skin.isMeshPhysicalNodeMaterial).toBe(true);
      expect(skin.widthMm).toBe(2);
    } finally {
      t.dispose();
    }
  });

  it("a list of lights reads back as given, frozen, a map per light (a point light's of six faces where it is not aimed yet); 'castShadow' reads back, its maps found each frame", () => {
    const t = nodeFixture();
    try {
      const bulb = new t.THREE.PointLight();
      const node = t.make({ light: [t.light, bulb], lightDepthSize: 64 });
      expect(node.light).toEqual([t.light, bulb]);
      expect(Object.isFrozen(node.light)).toBe(true);
      expect(node.transmittance).toBe(true);
      expect(node.lightDepths.map((map) => [map.light, map.isCube, map.renderTarget.width, map.renderTarget.height])).toEqual([[t.light, false, 64, 64], [bulb, true, 96, 64]]);
      expect(node.lightDepth.light).toBe(t.light);
      node.light = 'castShadow';
      expect([node.light, node.lightDepths.length, node.lightDepth]).toEqual(['castShadow', 0, null]);
      node.light = bulb;
      expect(node.lightDepths.map((map) => map.light)).toEqual([bulb]);
    } finally {
      t.dispose();
    }
  });

  it('a clone of a subsurface node material has uniforms of its own: changing it leaves the original as it was', () => {
    const a = NODE.subsurfaceMaterial(new THREE.MeshStandardMaterial(), { widthMm: 2, translucency: 0.3 });
    const b = a.clone();
    expect([b.isSubsurfaceNodeMaterial, b.widthMm, b.translucency]).toEqual([true, 2, 0.3]);
    expect(b.subsurfaceWidth).not.toBe(a.subsurfaceWidth);
    expect(b.transmittanceNodes).toBeNull();
    Object.assign(b, { widthMm: 5, translucency: 0.6 });
    expect([a.widthMm, a.translucency]).toEqual([2, 0.3]);
  });
});

