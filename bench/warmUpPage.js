// The browser side of bench/warmUp.js: on a page of a fresh browser (no program compiled yet, no
// shader cache), the demo's head with the pipeline's defaults and a transmitting light, its first
// frame timed after one warm-up:
//   pipeline  await sss.compileAsync(renderer, composer.readBuffer): every program the frames draw with
//   uploads   the same, then every texture of the scene's materials uploaded (renderer.initTexture)
//   three     await renderer.compileAsync(scene, camera): what a three.js user calls today
//   none      no warm-up: the first frame compiles everything
// then a second frame and steady frames; the programs the first frame compiled, by name. A frame's time is the wall time of composer.render() and a 1-pixel read-back
// (a fence). SwiftShader's times are CPU times: compare them as ratios.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { headRig } from '/test/pages/headRig.js';
import { median } from '/dev/gpuTimer.js';

/**
 * @param {{ warmUp: string, width: number, height: number, frames: number }} o
 * @returns {Promise<object>} the warm-up's time, the first frame's, the steady frames' median, and
 *   the programs the warm-up and the first frame compiled
 */
async function run({ warmUp, width, height, frames }) {
  const rig = await headRig(width / height);
  setLightDirection(rig, 175, 15); // from behind: the light's depth pass draws
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  const sss = new SubsurfaceScattering({ scene: rig.scene, camera: rig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: rig.light });
  sss.makeSubsurface(rig.head.material);
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  const pixel = new Uint16Array(4);
  const frame = () => {
    const start = performance.now();
    composer.render();
    renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel);
    return performance.now() - start;
  };
  const gl = renderer.getContext();
  const start = performance.now();
  const warmUps = {
    pipeline: () => sss.compileAsync(renderer, composer.readBuffer),
    three: () => renderer.compileAsync(rig.scene, rig.camera),
    none: () => undefined,
    // The pipeline's, then every texture the scene's materials hold uploaded (three's initTexture).
    uploads: async () => {
      await sss.compileAsync(renderer, composer.readBuffer);
      rig.scene.traverse((object) => {
        for (const material of [object.material ?? []].flat()) {
          for (const value of Object.values(material)) if (value?.isTexture) renderer.initTexture(value);
        }
      });
    },
  };
  await warmUps[warmUp]();
  const warmUpMs = performance.now() - start;
  const warmed = renderer.info.programs.length;
  const warmedKeys = renderer.info.programs.map((p) => p.cacheKey);
  const firstMs = frame();
  const afterFirst = renderer.info.programs.length;
  // By the material's name, else three's shader id (the cache key's first field: 'depth', 'physical', …).
  const firstPrograms = renderer.info.programs.filter((p) => !warmedKeys.includes(p.cacheKey)).map((p) => p.name || p.cacheKey.split(',')[0]);
  const secondMs = frame();
  const steady = Array.from({ length: frames }, frame);
  const result = {
    warmUp, width, height, frames, isStandIn: rig.isStandIn, warmUpMs, firstMs, secondMs, steadyMs: median(steady), steady, firstPrograms,
    programsWarmed: warmed, programsFirstFrame: afterFirst - warmed, lightMap: sss._lightDepth?.valid ?? false,
    parallelCompile: gl.getExtension('KHR_parallel_shader_compile') !== null, glError: gl.getError(),
  };
  sss.dispose();
  composer.dispose();
  renderer.dispose();
  return result;
}

window.bench = { run };
window.testReady = true;
