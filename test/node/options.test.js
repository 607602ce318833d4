// The options' one source (src/options.js's schema) and what derives from it: the defaults, the
// checks, the typedefs the TypeScript declarations come from, the README's options table, and the
// README's API section against the main entry and the stages subpath, one for one.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Scene, PerspectiveCamera, HalfFloatType } from 'three';
import {
  PIPELINE_SCHEMA, MATERIAL_SCHEMA, PIPELINE_DEFAULTS, MATERIAL_DEFAULTS, checkPipelineOptions, checkMaterialOptions,
} from '../../src/options.js';
import * as mainEntry from '../../src/index.js';
import * as stages from '../../src/stages.js';
import { getProfile } from '../../src/profiles/presets.js';
import { expectedFiles } from '../../scripts/optionsDoc.js';

const root = fileURLToPath(new URL('../..', import.meta.url));

describe('the options schema', () => {
  it('gives every option a check, a type and a doc; the defaults are its defaults', () => {
    for (const [name, spec] of [...Object.entries(PIPELINE_SCHEMA), ...Object.entries(MATERIAL_SCHEMA)]) {
      expect(typeof spec.check, name).toBe('function');
      expect(spec.type.length, name).toBeGreaterThan(0);
      expect(spec.doc.length, name).toBeGreaterThan(10);
      // A default passes its own check (undefined: the option has none); a profile's name is kept as the profile.
      if (spec.default !== undefined) expect(spec.check(spec.default, name), name).toEqual(name === 'profile' ? getProfile(spec.default) : spec.default);
    }
    expect(PIPELINE_DEFAULTS).toMatchObject({ worldUnitInMm: 1000, method: 'footprint', samples: 'auto', type: HalfFloatType });
    expect(MATERIAL_DEFAULTS).toEqual({ widthMm: 1, widthScale: 1, transmittance: true, translucency: 0, shrinkMm: 0.6 });
  });

  it('has one bound per quantity: worldUnitInMm is refused alike by the pipeline, the material hook and transmittance', async () => {
    const { makeSubsurface, createTransmittanceUniforms } = stages;
    const { MeshStandardMaterial } = await import('three');
    const scene = new Scene();
    const camera = new PerspectiveCamera();
    const message = /worldUnitInMm must be in \[0\.000001, 1000000\] mm, got 1000000000/;
    expect(() => checkPipelineOptions({ scene, camera, worldUnitInMm: 1e9 })).toThrow(message);
    expect(() => makeSubsurface(new MeshStandardMaterial(), { worldUnitInMm: 1e9 })).toThrow(message);
    expect(() => createTransmittanceUniforms({ lightDepth: null, lookup: null, worldUnitInMm: 1e9 })).toThrow(/lightDepth must be a LightDepthTarget/);
  });

  it('checks a whole options object once: unknown keys named, explicit undefined refused where there is a default', () => {
    const scene = new Scene();
    const camera = new PerspectiveCamera();
    expect(() => checkPipelineOptions({ scene, camera, samles: 9 })).toThrow(/unknown option "samles"/);
    expect(() => checkPipelineOptions({ scene, camera, light: undefined })).toThrow(/light must be .* or null, got undefined/);
    expect(checkPipelineOptions({ scene, camera, strength: undefined }).strength).toBeUndefined();
    expect(checkPipelineOptions({ scene, camera }).lightDepthSize).toBe(1024);
    expect(() => checkMaterialOptions({ strength: 0.5 })).toThrow(/unknown option "strength" \(accepted: widthMm, widthScale, /);
    expect(checkPipelineOptions({ scene, camera }).profile).toBe(getProfile('skin')); // a default is kept as its check keeps it
  });
});

describe('what derives from the schema', () => {
  it('the typedefs and the README options table are as scripts/optionsDoc.js writes them (npm run options-doc)', () => {
    for (const { file, current, expected } of expectedFiles()) expect(current, `${file} is out of date: run npm run options-doc`).toBe(expected);
  });

  it("the README's export table names every export of the main entry, and nothing else", () => {
    const readme = readFileSync(`${root}README.md`, 'utf8');
    const section = readme.slice(readme.indexOf('## API'), readme.indexOf('\nTypes: ', readme.indexOf('## API')));
    expect(section.length).toBeGreaterThan(200);
    const firstColumns = [...section.matchAll(/^\| ([^|]+) \|/gm)].map((m) => m[1]).filter((c) => c !== 'export' && !c.startsWith('---'));
    const named = firstColumns.flatMap((cell) => [...cell.matchAll(/`(\w+)`/g)].map((m) => m[1]));
    expect(new Set(named).size).toBe(named.length);
    expect(named.sort()).toEqual(Object.keys(mainEntry).sort());
  });

  it("the README's stages paragraph names every export of three-separable-sss/stages (src/stages.js), and nothing else", async () => {
    const readme = readFileSync(`${root}README.md`, 'utf8');
    const from = readme.indexOf('`three-separable-sss/stages`');
    expect(from).toBeGreaterThan(0);
    const named = [...readme.slice(from, readme.indexOf('\n\n', from)).matchAll(/`(\w+)`/g)].map((m) => m[1]);
    const stages = await import('../../src/stages.js');
    expect(new Set(named).size).toBe(named.length);
    expect(named.sort()).toEqual(Object.keys(stages).sort());
  });
});

describe('one settings layer for both renderers', () => {
  it('the WebGL pipeline and the WebGPU node have every setting they share as a property, with the same default, the same check and the same words', async () => {
    const { pass } = await import('three/tsl');
    const { SubsurfaceScattering } = mainEntry;
    const { subsurfaceScattering } = await import('../../src/webgpu/index.js');
    const { NODE_SCHEMA, propertiesOf } = await import('../../src/options.js');
    const scene = new Scene();
    const camera = new PerspectiveCamera();
    const sss = new SubsurfaceScattering({ scene, camera });
    const node = subsurfaceScattering(pass(scene, camera));
    const shared = propertiesOf(NODE_SCHEMA);
    expect(shared.map(({ name }) => name)).toContain('debugDepthRange');
    const refusal = (object, name, value) => {
      try {
        object[name] = value;
      } catch (error) {
        return `${error.constructor.name}: ${error.message}`;
      }
      return null;
    };
    for (const { name, assignable } of shared) {
      expect(node[name], name).toEqual(sss[name]);
      // A value no setting takes: both refuse it with the same error, naming the property as written.
      const bad = Symbol('bad');
      const message = refusal(sss, name, bad);
      expect(message, name).toMatch(assignable ? new RegExp(`^\\w+Error: ${name} must be`) : /is read-only/);
      if (assignable) expect(refusal(node, name, bad), name).toBe(message);
      expect(node[name], name).toEqual(sss[name]); // nothing changed
    }
    // A value taken on both reads back alike, as the schema's check keeps it.
    Object.assign(sss, { profile: 'marble', samples: 25, debugDepthRange: 3 });
    Object.assign(node, { profile: 'marble', samples: 25, debugDepthRange: 3 });
    for (const { name } of shared) expect(node[name], name).toEqual(sss[name]);
    expect(sss.profile.name).toBe('marble');
    node.dispose();
    sss.dispose();
  });
});
