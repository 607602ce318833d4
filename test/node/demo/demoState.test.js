// The demo's URL state: every key parses back to what was written, invalid values are refused
// with a message naming the key and the accepted values, and figures set their toggles.
import { describe, it, expect } from 'vitest';
import { STATE_SCHEMA, PRESET_NAMES, defaultState, parseHash, formatHash } from '../../../demo/state.js';
import { FIGURES, PRESETS, figureState, presetState } from '../../../demo/figures.js';

describe('demo URL state', () => {
  it('round-trips a state through the hash', () => {
    const state = defaultState();
    Object.assign(state, {
      sss: false, profile: 'marble', method: 'reference', width: 2.5, samples: 25, strength: [0.5, 0.4, 0.3],
      followSurface: 'lerp', transmittance: false, lightAzimuth: 180, lightColor: '#ffcc88', view: 'depth',
      split: 0.5, camera: [1, 2, 3, 0, 1.3, 0], figure: 4,
    });
    const hash = formatHash(state);
    expect(hash).toContain('lightAzimuth=180');
    expect(hash).toContain('sss=0');
    const { values, problems } = parseHash(`#${hash}`);
    expect(problems).toEqual([]);
    expect({ ...defaultState(), ...values }).toEqual(state);
  });

  it('writes nothing for the defaults', () => {
    expect(formatHash(defaultState())).toBe('');
  });

  it('ignores invalid values with a message naming the key and the accepted values', () => {
    const { values, problems } = parseHash('#width=-3&profile=jelly&samples=16&sss=yes&figure=9&lightColor=red&bogus=1&lightAzimuth=180');
    expect(values).toEqual({ lightAzimuth: 180 });
    expect(problems).toHaveLength(7);
    expect(problems.join('\n')).toMatch(/width=-3: it must be a number in \[0\.05, 20\] mm/);
    expect(problems.join('\n')).toMatch(/profile=jelly: it must be one of skin, skinBurley, marble, milk/);
    expect(problems.join('\n')).toMatch(/samples=16: it must be 'auto' or an odd integer in 3\.\.63/);
    expect(problems.join('\n')).toMatch(/"bogus": not a setting/);
  });

  it('has the keys the page promises, and five figures that differ in one setting', () => {
    for (const key of ['sss', 'transmittance', 'followSurface', 'width', 'samples', 'profile', 'view', 'figure', 'lightAzimuth']) {
      expect(STATE_SCHEMA).toHaveProperty(key);
    }
    expect(FIGURES.map((f) => f.id)).toEqual([1, 2, 3, 4, 5]);
    for (const f of FIGURES) {
      const before = figureState(f.id, 'before');
      const after = figureState(f.id, 'after');
      expect(before[f.toggle]).not.toEqual(after[f.toggle]);
      const differing = Object.keys(after).filter((k) => JSON.stringify(after[k]) !== JSON.stringify(before[k]));
      expect(differing).toEqual([f.toggle]);
      // Every value a figure sets is itself valid for the hash.
      const { problems } = parseHash(`#${formatHash({ ...defaultState(), ...after })}`);
      expect(problems).toEqual([]);
    }
  });

  it('has a state for each preset name, valid for the hash and read back from it', () => {
    expect(Object.keys(PRESETS)).toEqual(PRESET_NAMES);
    for (const name of PRESET_NAMES) {
      const state = { ...defaultState(), ...presetState(name) };
      const { values, problems } = parseHash(`#${formatHash(state)}`);
      expect(problems).toEqual([]);
      expect({ ...defaultState(), ...values }).toEqual(state);
    }
    expect(presetState('earLight')).toMatchObject({ pointLight: true, preset: 'earLight' });
    expect(presetState('foliage')).toMatchObject({ foliage: true, preset: 'foliage' });
    expect(parseHash('#preset=nose').problems).toEqual(['Ignored preset=nose: it must be one of earLight, foliage.']);
  });
});
