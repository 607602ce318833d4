// Out of range: the constructors check three's REVISION before building anything. Here three is the
// real devDependency with its REVISION faked (r160 is what a user forced onto an old three has:
// before the check the page died with "Cannot read properties of undefined (reading '0') at
// createSubsurfaceTarget").
import { describe, it, expect, vi, afterEach } from 'vitest';

const fake = vi.hoisted(() => ({ revision: '160' }));
vi.mock('three', async (importOriginal) => {
  const three = { ...(await importOriginal()) };
  Object.defineProperty(three, 'REVISION', { get: () => fake.revision, enumerable: true });
  return three;
});

const { MeshStandardMaterial, PerspectiveCamera, Scene, SpotLight } = await import('three');
const { SubsurfaceScattering, SubsurfaceScenePass, makeSubsurface } = await import('../../harness/sss.js');
const { SubsurfaceScatteringPass } = await import('../../../src/integrations/postprocessing.js');

const scene = new Scene();
const camera = new PerspectiveCamera();
const supported = '(supported: three >=0.168.0 <0.188.0, r168 to r187)';

afterEach(() => {
  vi.restoreAllMocks();
});

describe('three releases out of range', () => {
  it('r160 and r167: every entry point throws an Error naming the release and the supported range, first', () => {
    for (const revision of ['160', '167']) {
      fake.revision = revision;
      const named = (who) => `${who}: three r${revision} is not supported ${supported}`;
      expect(() => new SubsurfaceScattering({ scene, camera, light: new SpotLight() })).toThrow(named('SubsurfaceScattering'));
      // First: before the options are checked (bad options would otherwise be the message).
      expect(() => new SubsurfaceScattering(null)).toThrow(named('SubsurfaceScattering'));
      expect(() => new SubsurfaceScatteringPass({ scene, camera })).toThrow(named('SubsurfaceScattering'));
      expect(() => new SubsurfaceScenePass(scene, camera)).toThrow(named('SubsurfaceScenePass'));
      expect(() => makeSubsurface(new MeshStandardMaterial())).toThrow(named('makeSubsurface'));
    }
  });

  it('r168 and r187 build without a word; r188 (newer than tested) builds with one warning naming the range', () => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    for (const revision of ['168', '187']) {
      fake.revision = revision;
      new SubsurfaceScattering({ scene, camera }).dispose();
    }
    expect(warn).not.toHaveBeenCalled();
    fake.revision = '188';
    new SubsurfaceScattering({ scene, camera }).dispose();
    new SubsurfaceScattering({ scene, camera }).dispose();
    expect(warn).toHaveBeenCalledTimes(1);
    expect(warn.mock.calls[0][0]).toBe(`SubsurfaceScattering: three r188 is newer than the releases this version was tested with ${supported}`);
  });
});
