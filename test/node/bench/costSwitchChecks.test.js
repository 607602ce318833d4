// Issue 19's switches (documented-internal flags the bench flips) take booleans only: a TypeError
// naming the switch otherwise, never a silent truthy value.
import { describe, it, expect } from 'vitest';
import { PerspectiveCamera, Scene } from 'three';
import { SubsurfaceScattering } from '../../../src/SubsurfaceScattering.js';

describe('issue 19 switches', () => {
  const sss = new SubsurfaceScattering({ scene: new Scene(), camera: new PerspectiveCamera() });
  const switches = [
    [sss, 'skipsUnreadLightDepth', true],
    [sss._scenePass, 'depthPrepass', false],
    [sss._blur, 'confineToSubsurface', true],
    [sss._composePass, 'writesDepth', true],
    [sss._composePass, 'fetchesEverywhere', false],
    [sss._blur, 'skipsEmptyTexels', true],
    [sss._blur, 'lightCarriesDepth', true],
    [sss._blur, 'groupsCarryDepth', true],
  ];

  it.each(switches.map(([owner, field, value]) => [field, owner, value]))('%s: defaults to the saving, takes booleans only', (field, owner, value) => {
    expect(owner[field]).toBe(value);
    expect(() => { owner[field] = 'no'; }).toThrow(TypeError);
    expect(() => { owner[field] = 1; }).toThrow(new RegExp(field));
    owner[field] = !value;
    expect(owner[field]).toBe(!value);
    owner[field] = value;
  });

  it('the groups\' carried depth reaches both blur passes', () => {
    sss._blur.groupsCarryDepth = false;
    expect([sss._blur.horizontalPass, sss._blur.verticalPass].map((p) => p.material.defines.SSS_GROUPS_CARRY_DEPTH)).toEqual([0, 0]);
    sss._blur.groupsCarryDepth = true;
    expect([sss._blur.horizontalPass, sss._blur.verticalPass].map((p) => p.material.defines.SSS_GROUPS_CARRY_DEPTH)).toEqual([1, 1]);
  });

  it('the compose\'s switches reach its material', () => {
    sss._composePass.fetchesEverywhere = true;
    expect(sss._composePass.material.defines.FETCH_EVERYWHERE).toBe(1);
    sss._composePass.fetchesEverywhere = false;
    sss._composePass.writesDepth = false;
    sss._composePass.setClear(true);
    expect(sss._composePass.material.depthWrite).toBe(false);
    sss._composePass.writesDepth = true;
    expect(sss._composePass.material.depthWrite).toBe(true);
  });
});
