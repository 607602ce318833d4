// The WebGPURenderer bench's browser side (bench/webgpu/run.js): the demo's head through each
// renderer's plain frame and its subsurface frame, each set-up with its own renderer, timed frame
// by frame in interleaved rounds:
//   composerPlain   WebGLRenderer, EffectComposer with RenderPass and OutputPass
//   composer        the same with SubsurfaceScattering in place of RenderPass
//   composerNoBlur  the same with `scattering: false`
//   webgpuPlain     WebGPURenderer (WebGPU), RenderPipeline over pass(scene, camera)
//   webgpuSplit     the same pass with subsurfaceMRT() and the subsurface materials, showing its
//                   colour output: the scene split alone
//   webgpuNoBlur    the node with `scattering: false`: the split and the compose
//   webgpuNode      the node
//   webgpuPlainAway, webgpuNodeAway  plain and the node with the camera turned to the head's side:
//                   nothing subsurface on the screen
//   webgl…          the same six on WebGPURenderer's WebGL 2 backend (forceWebGL)
//   …Isotropic      composer, webgpuNode and webglNode with kernelGroups 'auto' (the isotropic blur)
//   …Base           composer, webgpuNode and webglNode with the base checkout's library
//                   (bench/webgpu/run.js --base): before and after in the same rounds
// Split over plain is the scene split's cost, no-blur over split the compose's (and the node's
// CPU side), node over no-blur the blur's. A frame's time is the wall time of render() and a
// 1-pixel read-back of its output (which waits for the GPU), so every row pays the same
// read-back. SwiftShader's times are CPU times: compare rows of one run, not runs.
import * as THREE from 'three/webgpu';
import { WebGLRenderer } from 'three';
import { pass } from 'three/tsl';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import * as LIBRARY from 'three-separable-sss';
import * as NODE from 'three-separable-sss/webgpu';
import * as BASE_LIBRARY from 'three-separable-sss-base';
import * as BASE_NODE from 'three-separable-sss-base/webgpu';
import { buildScene } from '../scenes.js';

/** This checkout's library and the base's (vite.config.js's SSS_BASE_DIR; without one, this checkout's again). */
const THIS = { ...LIBRARY, ...NODE };
const BASE = { ...BASE_LIBRARY, ...BASE_NODE };

async function composerRow(width, height, { sss = true, kernelGroups = 1, lib = THIS, scattering = true } = {}) {
  const built = await buildScene('head', { aspect: width / height });
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
  composer.renderToScreen = false;
  let pipeline = null;
  if (sss) {
    pipeline = new lib.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: built.worldUnitInMm, light: null, kernelGroups, scattering });
    for (const m of built.subsurface) pipeline.makeSubsurface(m, { widthMm: built.widthMm });
    composer.addPass(pipeline);
  } else {
    composer.addPass(new RenderPass(built.scene, built.camera));
  }
  composer.addPass(new OutputPass());
  const pixel = new Uint16Array(4);
  return {
    async frame() {
      composer.render();
      await renderer.readRenderTargetPixelsAsync(composer.readBuffer, 0, 0, 1, 1, pixel); // as the other rows: an asynchronous read-back
    },
    dispose() { pipeline?.dispose(); composer.dispose(); renderer.dispose(); renderer.forceContextLoss(); },
  };
}

/**
 * `stage`: 'plain', 'split' (the split's colour output), 'noBlur' (the node, scattering off) or
 * 'node'; `away`: the camera turned to the head's side (bench/sceneGraphPage.js's offScreen view),
 * nothing subsurface on the screen.
 */
async function webgpuRow(width, height, { backend, stage, kernelGroups = 1, lib = THIS, away = false }) {
  const { subsurfaceMaterial, subsurfaceMRT, subsurfaceScattering, ATTACHMENT_NAMES } = lib;
  const built = await buildScene('head', { aspect: width / height });
  if (away) built.camera.lookAt(built.camera.position.clone().add(new THREE.Vector3(-1, 0, -0.3)));
  const renderer = new THREE.WebGPURenderer({ antialias: false, forceWebGL: backend === 'webgl' });
  renderer.setSize(width, height, false);
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  await renderer.init();
  const scenePass = pass(built.scene, built.camera);
  const pipeline = new THREE.RenderPipeline(renderer);
  let sss = null;
  if (stage === 'plain') {
    pipeline.outputNode = scenePass;
  } else {
    built.scene.traverse((o) => { if (o.isMesh && built.subsurface.includes(o.material)) o.material = subsurfaceMaterial(o.material, { widthMm: built.widthMm }); });
    scenePass.setMRT(subsurfaceMRT());
    if (stage === 'split') {
      pipeline.outputNode = scenePass.getTextureNode(ATTACHMENT_NAMES.COLOR);
    } else {
      sss = subsurfaceScattering(scenePass, { worldUnitInMm: built.worldUnitInMm, kernelGroups, scattering: stage === 'node' });
      pipeline.outputNode = sss;
    }
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
  composerPlain: (w, h) => composerRow(w, h, { sss: false }),
  composer: (w, h) => composerRow(w, h),
  composerNoBlur: (w, h) => composerRow(w, h, { scattering: false }),
  webgpuPlain: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'plain' }),
  webgpuSplit: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'split' }),
  webgpuNoBlur: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'noBlur' }),
  webgpuNode: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'node' }),
  webgpuPlainAway: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'plain', away: true }),
  webgpuNodeAway: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'node', away: true }),
  webglPlain: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'plain' }),
  webglSplit: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'split' }),
  webglNoBlur: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'noBlur' }),
  webglNode: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'node' }),
  webglPlainAway: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'plain', away: true }),
  webglNodeAway: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'node', away: true }),
  composerIsotropic: (w, h) => composerRow(w, h, { kernelGroups: 'auto' }),
  webgpuNodeIsotropic: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'node', kernelGroups: 'auto' }),
  webglNodeIsotropic: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'node', kernelGroups: 'auto' }),
  composerBase: (w, h) => composerRow(w, h, { lib: BASE }),
  webgpuNodeBase: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'node', lib: BASE }),
  webglNodeBase: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'node', lib: BASE }),
  webgpuNodeAwayBase: (w, h) => webgpuRow(w, h, { backend: 'webgpu', stage: 'node', lib: BASE, away: true }),
  webglNodeAwayBase: (w, h) => webgpuRow(w, h, { backend: 'webgl', stage: 'node', lib: BASE, away: true }),
};

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

/**
 * Every row of `only` (default: all) in each of `rounds` rounds, `frames` timed frames each after
 * two warm-up frames; medians in ms.
 */
async function run({ width = 640, height = 360, rounds = 5, frames = 5, only = Object.keys(ROWS) } = {}) {
  const rows = {};
  for (const name of only) {
    rows[name] = await ROWS[name](width, height);
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

window.bench = { run, rows: Object.keys(ROWS) };
window.testReady = true;
