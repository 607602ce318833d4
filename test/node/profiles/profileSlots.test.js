// Several profiles in one pipeline, the pure part (src/profiles/profileSlots.js, blurPlan.js's
// checkProfileCount): the slots a frame holds and which methods blur how many.
import { describe, it, expect } from 'vitest';
import { MAX_PROFILES, profileSlots } from '../../../src/profiles/profileSlots.js';
import { checkProfileCount } from '../../../src/3-blur/blurPlan.js';
import { METHODS } from '../../../src/options.js';

const skin = { name: 'skin' };
const marble = { name: 'marble' };
const milk = { name: 'milk' };

describe('profileSlots', () => {
  it('gives one slot per distinct profile, in binding order, and each material its slot', () => {
    expect(profileSlots([marble, skin, marble, milk, skin], skin)).toEqual({ profiles: [marble, skin, milk], slots: [0, 1, 0, 2, 1] });
  });

  it('keeps one slot when every material has one profile, whatever the pipeline\'s is', () => {
    expect(profileSlots([marble, marble], skin)).toEqual({ profiles: [marble], slots: [0, 0] });
  });

  it('holds the pipeline\'s profile when no material is bound', () => {
    expect(profileSlots([], skin)).toEqual({ profiles: [skin], slots: [] });
  });

  it(`accepts ${MAX_PROFILES} profiles and refuses one more, naming profile and the limit`, () => {
    const many = Array.from({ length: MAX_PROFILES + 1 }, (_, i) => ({ name: `p${i}` }));
    expect(profileSlots(many.slice(0, MAX_PROFILES), skin).profiles).toHaveLength(MAX_PROFILES);
    expect(() => profileSlots(many, skin)).toThrow(RangeError);
    expect(() => profileSlots(many, skin)).toThrow(/profile: at most 8 profiles per pipeline, got 9 \('p0', .*'p8'\)/);
  });
});

describe('checkProfileCount', () => {
  it("lets 'footprint', 'marginal' and 'reference' blur several profiles and the dense reference one", () => {
    const several = METHODS.filter((method) => { try { checkProfileCount(method, 2); return true; } catch { return false; } });
    expect(several).toEqual(['footprint', 'marginal', 'reference']);
    for (const method of METHODS) expect(() => checkProfileCount(method, 1, true)).not.toThrow();
    for (const method of METHODS) expect(() => checkProfileCount(method, 2, true)).toThrow(RangeError);
    expect(() => checkProfileCount('footprint', MAX_PROFILES + 1)).toThrow(RangeError);
  });

  it('names the dense reference and the materials\' profile', () => {
    expect(() => checkProfileCount('footprint', 3, true)).toThrow(/the dense reference blurs 1 profile per frame and the materials use 3 \(their `profile`\); use one profile/);
  });
});
