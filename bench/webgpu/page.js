// The WebGPURenderer bench's browser side (bench/webgpu/run.js): the demo's head through eight
// set-ups, each with its own renderer, timed frame by frame in interleaved rounds:
//   composer     WebGLRenderer, EffectComposer with SubsurfaceScattering and OutputPass
//   webgpuPlain  WebGPURenderer (WebGPU), RenderPipeline over pass(scene, camera)
//   webgpuNode   the same with subsurfaceMRT() and the node
//   webglPlain   WebGPURenderer's WebGL 2 backend (forceWebGL), plain
//   webglNode    the same with the node
//   …Isotropic   composer, webgpuNode and webglNode with kernelGroups 'auto' (the isotropic blur)
// A frame's time is the wall time of render() and a 1-pixel read-back of its output (which waits
// for the GPU), so every row pays the same read-back. SwiftShader's times are CPU times: compare
// rows of one run, not runs.
import * as THREE from 'three/webgpu';
import { WebGLRenderer } from 'three';
import { pass } from 'three/tsl';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { subsurfaceMaterial, subsurfaceMRT, subsurfaceScattering } from 'three-separable-sss/webgpu';
import { buildScene } from '../scenes.js';

async function composerRow(width, height, { kernelGroups = 1 } = {}) {
  const built = await buildScene('head', { aspect: width / height });
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
  composer.renderToScreen = false;
  const sss = new SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: built.worldUnitInMm, light: null, kernelGroups });
  for (const m of built.subsurface) sss.makeSubsurface(m, { widthMm: built.widthMm });
  composer.addPass(sss);
  composer.addPass(new OutputPass());
  const pixel = new Uint16Array(4);
  return {
    async frame() {
      composer.render();
      await renderer.readRenderTargetPixelsAsync(composer.readBuffer, 0, 0, 1, 1, pixel); // as the other rows: an asynchronous read-back
    },
    dispose() { sss.dispose(); composer.dispose(); renderer.dispose(); renderer.forceContextLoss(); },
  };
}

async function webgpuRow(width, height, { backend, node, kernelGroups = 1 }) {
  const built = await buildScene('head', { aspect: width / height });
  const renderer = new THREE.WebGPURenderer({ antialias: false, forceWebGL: backend === 'webgl' });
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  await renderer.init();
  const scenePass = pass(built.scene, built.camera);
  const pipeline = new THREE.RenderPipeline(renderer);
  let sss = null;
  if (node) {
    built.scene.traverse((o) => { if (o.isMesh && built.subsurface.includes(o.material)) o.material = subsurfaceMaterial(o.material, { widthMm: built.widthMm }); });
    scenePass.setMRT(subsurfaceMRT());
    sss = subsurfaceScattering(scenePass, { worldUnitInMm: built.worldUnitInMm, kernelGroups });
    pipeline.outputNode = sss;
  } else {
    pipeline.outputNode = scenePass;
  }
  const target = new THREE.RenderTarget(width, height, { type: THREE.HalfFloatType });
  return {
    async frame() {
      renderer.setRenderTarget(target);
      pipeline.render();
      renderer.setRenderTarget(null);
      await renderer.readRenderTargetPixelsAsync(target, 0, 0, 1, 1);
    },
    dispose() { sss?.dispose(); pipeline.dispose(); scenePass.dispose(); target.dispose(); renderer.dispose(); },
  };
}

const ROWS = {
  composer: (w, h) => composerRow(w, h),
  webgpuPlain: (w, h) => webgpuRow(w, h, { backend: 'webgpu', node: false }),
  webgpuNode: (w, h) => webgpuRow(w, h, { backend: 'webgpu', node: true }),
  webglPlain: (w, h) => webgpuRow(w, h, { backend: 'webgl', node: false }),
  webglNode: (w, h) => webgpuRow(w, h, { backend: 'webgl', node: true }),
  composerIsotropic: (w, h) => composerRow(w, h, { kernelGroups: 'auto' }),
  webgpuNodeIsotropic: (w, h) => webgpuRow(w, h, { backend: 'webgpu', node: true, kernelGroups: 'auto' }),
  webglNodeIsotropic: (w, h) => webgpuRow(w, h, { backend: 'webgl', node: true, kernelGroups: 'auto' }),
};

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

/** Every row in each of `rounds` rounds, `frames` timed frames each after two warm-up frames; medians in ms. */
async function run({ width = 640, height = 360, rounds = 5, frames = 5 } = {}) {
  const rows = {};
  for (const [name, make] of Object.entries(ROWS)) {
    rows[name] = await make(width, height);
    await rows[name].frame(); // compiles
    await rows[name].frame();
  }
  const times = Object.fromEntries(Object.keys(rows).map((name) => [name, []]));
  for (let round = 0; round < rounds; round++) {
    for (const [name, row] of Object.entries(rows)) {
      for (let i = 0; i < frames; i++) {
        const start = performance.now();
        await row.frame();
        times[name].push(performance.now() - start);
      }
    }
  }
  for (const row of Object.values(rows)) row.dispose();
  return { width, height, rounds, frames, medianMs: Object.fromEntries(Object.entries(times).map(([k, v]) => [k, median(v)])), times };
}

window.bench = { run };
window.testReady = true;
