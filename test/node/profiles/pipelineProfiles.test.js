// Several profiles in one pipeline, as the pipeline keeps them (no GPU): which slot each material
// writes, which tables its transmittance reads, what the blur is compiled for and how many
// channels the surface attachment has, as materials come and go and the pipeline's profile changes.
import { describe, it, expect, afterEach } from 'vitest';
import * as THREE from 'three';
import * as SSS from '../../harness/sss.js';
import { createFixture } from '../../reliability/fixture.js';

let t;
afterEach(() => t?.dispose());

/** What the frame holds: { count: PROFILE_COUNT of both blur passes, channels: the surface's, slots and transmittance profiles by material }. */
function frameOf(sss, materials) {
  const counts = new Set([sss._blur.horizontalPass, sss._blur.verticalPass].map((pass) => pass.material.defines.PROFILE_COUNT));
  expect(counts.size).toBe(1);
  return {
    count: [...counts][0],
    channels: sss._scenePass.surfaceTexture.format === THREE.RGBAFormat ? 4 : 2,
    slots: materials.map((m) => sss.materials.get(m).hook.profileSlot),
    transmits: materials.map((m) => sss.materials.get(m).hook.transmittance[0].lookup.profile.name),
  };
}

describe('a pipeline with materials of several profiles', () => {
  it('gives each material its slot and its own transmittance table, and grows the surface only while several are used', () => {
    t = createFixture(THREE, SSS);
    const { sss, material: skin } = t;
    const marble = new THREE.MeshStandardMaterial();
    expect(frameOf(sss, [skin])).toEqual({ count: 1, channels: 2, slots: [0], transmits: ['skin'] });
    sss.makeSubsurface(marble, { profile: 'marble' });
    expect(frameOf(sss, [skin, marble])).toEqual({ count: 2, channels: 4, slots: [0, 1], transmits: ['skin', 'marble'] });
    sss.removeSubsurface(marble);
    expect(frameOf(sss, [skin])).toEqual({ count: 1, channels: 2, slots: [0], transmits: ['skin'] });
  });

  it("follows the pipeline's profile in the materials that name none, and keeps the others'", () => {
    t = createFixture(THREE, SSS);
    const { sss, material: plain } = t;
    const named = new THREE.MeshStandardMaterial();
    sss.makeSubsurface(named, { profile: 'skin' });
    expect(frameOf(sss, [plain, named])).toMatchObject({ count: 1, slots: [0, 0] });
    sss.profile = 'marble'; // the plain material follows, the named one stays skin
    expect(sss.profile.name).toBe('marble');
    expect(frameOf(sss, [plain, named])).toEqual({ count: 2, channels: 4, slots: [0, 1], transmits: ['marble', 'skin'] });
    sss.makeSubsurface(named, { profile: 'marble' }); // one profile again, not the pipeline's first
    expect(frameOf(sss, [plain, named])).toEqual({ count: 1, channels: 2, slots: [0, 0], transmits: ['marble', 'marble'] });
  });

  it('refuses what the dense reference cannot blur and leaves the pipeline as it was', () => {
    t = createFixture(THREE, SSS);
    const { sss, material: plain } = t;
    const named = new THREE.MeshStandardMaterial();
    sss.makeSubsurface(named, { profile: 'skin' });
    SSS.useDenseReference(sss);
    expect(() => { sss.profile = 'marble'; }).toThrow(/the dense reference blurs 1 profile per frame and the materials use 2/);
    expect(sss.profile.name).toBe('skin');
    expect(() => sss.makeSubsurface(named, { profile: 'milk' })).toThrow(RangeError);
    expect(frameOf(sss, [plain, named])).toEqual({ count: 1, channels: 2, slots: [0, 0], transmits: ['skin', 'skin'] });
    expect(sss.materials.get(named).options.profile).toBe('skin');
  });

  it('takes a material back to the pipeline\'s profile with profile: null, and drops the tables no material uses', () => {
    t = createFixture(THREE, SSS);
    const { sss, material: plain } = t;
    const named = new THREE.MeshStandardMaterial();
    sss.makeSubsurface(named, { profile: 'marble' });
    expect(frameOf(sss, [plain, named])).toMatchObject({ count: 2, slots: [0, 1] });
    sss.makeSubsurface(named, { profile: undefined, widthMm: 2 }); // left out: kept
    expect(frameOf(sss, [plain, named])).toMatchObject({ count: 2, transmits: ['skin', 'marble'] });
    sss.makeSubsurface(named, { profile: null });
    expect(frameOf(sss, [plain, named])).toEqual({ count: 1, channels: 2, slots: [0, 0], transmits: ['skin', 'skin'] });
    // Twenty fresh profile objects bound in turn leave one table, not twenty.
    for (let i = 0; i < 20; i++) sss.makeSubsurface(named, { profile: SSS.burleyProfile({ name: `b${i}`, scatterDistanceMm: [1, 0.5, 0.25 + i / 100] }) });
    expect(sss._otherLookups.size).toBe(1);
  });

  it('names the call that would make a ninth profile, and a refused setting changes nothing', () => {
    t = createFixture(THREE, SSS);
    const { sss } = t;
    expect(() => { sss.method = 'bogus'; }).toThrow(/method/);
    expect(() => { sss.profile = 'jelly'; }).toThrow(/profile/);
    expect([sss.profile.name, sss.method]).toEqual(['skin', 'footprint']);
    sss.makeSubsurface(new THREE.MeshStandardMaterial(), { profile: 'marble' });
    expect(() => SSS.useDenseReference(sss)).toThrow(/the dense reference blurs 1 profile per frame and the materials use 2/);
    expect([sss.profile.name, sss.method, sss.plan?.passes ?? 'separable']).toEqual(['skin', 'footprint', 'separable']);
    for (const name of ['skin', 'milk', 'skinBurley']) sss.makeSubsurface(new THREE.MeshStandardMaterial(), { profile: name });
    for (let i = 0; i < 4; i++) sss.makeSubsurface(new THREE.MeshStandardMaterial(), { profile: SSS.burleyProfile({ name: `b${i}`, scatterDistanceMm: [1, 0.5, 0.3 + i / 10] }) });
    // Eight now (the fixture's material follows the pipeline's skin): a ninth by the pipeline's profile, or by a material.
    expect(() => { sss.profile = SSS.burleyProfile({ name: 'ninth', scatterDistanceMm: [2, 1, 0.5] }); }).toThrow(/^SubsurfaceScattering\.profile: profile: at most 8 profiles/);
    expect(() => sss.makeSubsurface(new THREE.MeshStandardMaterial(), { profile: SSS.burleyProfile({ name: 'ninth', scatterDistanceMm: [2, 1, 0.5] }) })).toThrow(/^makeSubsurface: profile: at most 8/);
  });
});
