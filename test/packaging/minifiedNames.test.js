// Messages in a production build (issue 40): a user's bundler minifies the library with the app, and
// `sss.enabled = 'yes'` read "u_.enabled must be a boolean". Here the library is built as Vite's
// library mode builds it, minified (Vite's own minifier, as its production build minifies), and imported in
// plain Node: the build must rename the classes (else this test proves nothing), and every message
// that names a class must name it as the user knows it.
import { describe, it, expect } from 'vitest';
import { build } from 'vite';
import { execFileSync } from 'node:child_process';
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));
// Inside the repository so that bare imports (three, postprocessing) resolve from its node_modules.
const outDir = `${root}node_modules/.cache/sss-minified-test`;

describe('the minified library build', () => {
  it("names its classes in messages as in development (before: 'u_.enabled must be a boolean')", async () => {
    rmSync(outDir, { recursive: true, force: true });
    await build({ root, configFile: `${root}vite.config.js`, mode: 'lib', logLevel: 'error', build: { outDir, emptyOutDir: true, minify: true, sourcemap: false } });
    const entry = (name) => JSON.stringify(`${outDir}/${name}.js`);
    const script = `
      const THREE = await import('three');
      const { SubsurfaceScattering } = await import(${entry('three-separable-sss')});
      const stages = await import(${entry('stages')});
      const { SubsurfaceScatteringPass } = await import(${entry('postprocessing')});
      const { LightDepthNodeTarget } = await import(${entry('webgpu')});
      const message = (run) => { try { run(); return null; } catch (error) { return error.message; } };
      const scene = new THREE.Scene();
      const camera = new THREE.PerspectiveCamera();
      const light = new THREE.SpotLight();
      const sss = new SubsurfaceScattering({ scene, camera });
      const pmndrs = new SubsurfaceScatteringPass({ scene, camera });
      const scenePass = new stages.SubsurfaceScenePass(scene, camera);
      console.log(JSON.stringify({
        classNames: [SubsurfaceScattering, SubsurfaceScatteringPass, stages.SubsurfaceScenePass, stages.LightDepthTarget].map((c) => c.name),
        messages: {
          enabled: message(() => { sss.enabled = 'yes'; }),
          clearDepth: message(() => { sss.clearDepth = 1; }),
          pmndrs: message(() => { pmndrs.needsDepthBlit = 'yes'; }),
          scenePass: message(() => { scenePass.renderToScreen = 'no'; }),
          blurPass: message(() => { sss._blur.horizontalPass.enabled = 'no'; }),
          composePass: message(() => { sss._composePass.needsSwap = 0; }),
          lightDepth: message(() => stages.createTransmittanceUniforms({ lightDepth: null })),
          otherRenderer: message(() => stages.createTransmittanceUniforms({ lightDepth: new LightDepthNodeTarget(light), lookup: null })),
          ours: message(() => new SubsurfaceScattering({ scene: sss, camera })),
        },
      }));`;
    const out = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '--no-deprecation', '-e', script], { encoding: 'utf8' }));
    rmSync(outDir, { recursive: true, force: true });
    // The build renamed them, as a user's production build does.
    expect(out.classNames).not.toContain('SubsurfaceScattering');
    expect(out.classNames).not.toContain('SubsurfaceScenePass');
    expect(out.messages).toEqual({
      enabled: 'SubsurfaceScattering.enabled must be a boolean (true or false), got "yes"',
      clearDepth: 'SubsurfaceScattering.clearDepth must be a boolean (true or false), got 1',
      pmndrs: 'SubsurfaceScatteringPass.needsDepthBlit must be a boolean (true or false), got "yes"',
      scenePass: 'SubsurfaceScenePass.renderToScreen must be a boolean (true or false), got "no"',
      blurPass: 'SubsurfaceBlurPass.enabled must be a boolean (true or false), got "no"',
      composePass: 'SubsurfaceComposePass.needsSwap must be a boolean (true or false), got 0',
      lightDepth: 'transmittance: lightDepth must be a LightDepthTarget, got null',
      otherRenderer: 'transmittance: lightDepth must be a LightDepthTarget, got a LightDepthNodeTarget',
      ours: 'scene must be a THREE.Scene, got a SubsurfaceScattering',
    });
  }, 240_000);
});
