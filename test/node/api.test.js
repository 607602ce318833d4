// The public API in plain Node: every bad argument gets a TypeError or RangeError that names the
// parameter and its accepted range; nothing renders, so no GPU is involved.
import { describe, it, expect } from 'vitest';
import { Scene, PerspectiveCamera, MeshStandardMaterial, MeshBasicMaterial, SpotLight, HemisphereLight } from 'three';
import {
  SubsurfaceScattering, makeSubsurface, computeKernel, LightDepthTarget, SubsurfaceBlurPass, ProfileLookup,
} from '../harness/sss.js';

const scene = new Scene();
const camera = new PerspectiveCamera();

describe('bad input is refused with a message naming the parameter and its range', () => {
  const cases = [
    ['no scene', () => new SubsurfaceScattering({ camera }), TypeError, /scene must be a THREE\.Scene/],
    ['no camera', () => new SubsurfaceScattering({ scene }), TypeError, /camera must be a THREE\.Camera/],
    ['a hemisphere light', () => new SubsurfaceScattering({ scene, camera, light: new HemisphereLight() }), TypeError, /light must be a THREE\.SpotLight, THREE\.DirectionalLight, THREE\.PointLight, a list of them, 'castShadow' or null/],
    ['NaN scale', () => new SubsurfaceScattering({ scene, camera, worldUnitInMm: NaN }), TypeError, /worldUnitInMm must be a finite number, got NaN/],
    ['negative scale', () => new SubsurfaceScattering({ scene, camera, worldUnitInMm: -1 }), RangeError, /worldUnitInMm must be in \[0\.000001, 1000000\] mm, got -1/],
    ['even samples', () => new SubsurfaceScattering({ scene, camera, samples: 16 }), RangeError, /samples must be an odd integer in 3\.\.63, got 16/],
    ['too many samples', () => new SubsurfaceScattering({ scene, camera, samples: 65 }), RangeError, /samples .*3\.\.63/],
    ['string samples', () => computeKernel({ samples: '17', profile: 'skin' }), TypeError, /samples .*3\.\.63/],
    ['unknown method', () => new SubsurfaceScattering({ scene, camera, method: 'fast' }), RangeError, /method must be one of/],
    ['unknown follow mode', () => new SubsurfaceScattering({ scene, camera, followSurface: 'maybe' }), RangeError, /followSurface must be one of/],
    ['negative depth threshold', () => new SubsurfaceScattering({ scene, camera, depthThresholdMm: -2 }), RangeError, /depthThresholdMm must be in \(0, /],
    ['unknown profile', () => new SubsurfaceScattering({ scene, camera, profile: 'jelly' }), TypeError, /skin/],
    ['not a standard material', () => makeSubsurface(new MeshBasicMaterial()), TypeError, /MeshStandardMaterial or MeshPhysicalMaterial/],
    ['NaN width', () => makeSubsurface(new MeshStandardMaterial(), { widthMm: NaN }), TypeError, /widthMm must be a finite number, got NaN/],
    ['negative width', () => makeSubsurface(new MeshStandardMaterial(), { widthMm: -1 }), RangeError, /widthMm must be in \(0, 1000\] mm, got -1/],
    ['huge width', () => makeSubsurface(new MeshStandardMaterial(), { widthMm: 5000 }), RangeError, /widthMm must be in \(0, 1000\] mm/],
    ['widthScale above 1', () => makeSubsurface(new MeshStandardMaterial(), { widthScale: 2 }), RangeError, /widthScale must be in \[0, 1\]/],
    ["strength, widthScale's old name", () => makeSubsurface(new MeshStandardMaterial(), { strength: 0.5 }), TypeError, /unknown option "strength"/],
    ['no light for the depth target', () => new LightDepthTarget(null), TypeError, /light must be a THREE\.SpotLight, THREE\.DirectionalLight or THREE\.PointLight/],
    ['light depth size', () => new LightDepthTarget(new SpotLight(), { size: 10.5 }), RangeError, /size must be an integer in 16\.\.8192/],
    ['translucency 1', () => new SubsurfaceScattering({ scene, camera, light: new SpotLight() }).makeSubsurface(new MeshStandardMaterial(), { translucency: 1 }), RangeError, /translucency must be in \[0, 1\)/],
    ['footprint blur without a table', () => new SubsurfaceBlurPass({ direction: 'horizontal', kernel: computeKernel({ samples: 9, profile: 'skin' }), camera, surfaceTexture: new ProfileLookup().texture, mode: 'footprint' }), TypeError, /needs a ProfileLookup/],
    ['blur direction', () => new SubsurfaceBlurPass({ direction: 'diagonal' }), RangeError, /direction must be one of/],
  ];
  for (const [what, make, type, message] of cases) {
    it(what, () => {
      expect(make).toThrow(type);
      expect(make).toThrow(message);
    });
  }
});

describe('the material hook', () => {
  it('is idempotent, keys the program cache, and undoes itself on dispose', () => {
    const material = new MeshStandardMaterial();
    const before = material.customProgramCacheKey();
    const hook = makeSubsurface(material, { widthMm: 2, worldUnitInMm: 50 });
    expect(makeSubsurface(material, { widthMm: 3 })).toBe(hook);
    expect(hook.uniforms.sssWidthWorld.value).toBeCloseTo(3 / 50, 12);
    expect(material.customProgramCacheKey()).not.toBe(before);
    expect(material.customProgramCacheKey()).toContain('subsurface');
    hook.dispose();
    expect(material.customProgramCacheKey()).toBe(before);
  });
});
