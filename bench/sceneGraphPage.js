// The browser side of bench/sceneGraph.js: the pipeline's frame against three's plain frame (a
// RenderPass composer) in three scenes, one renderer per row, interleaved rounds:
//   offScreen  the head among 2,000 ordinary boxes, the camera turned to its side (boxes in view),
//              the key light behind the head: nothing subsurface on the screen
//   inView     the head at the demo's first view, the same light (for scale)
//   crowd      the head in view among 2,000 ordinary boxes (20 materials) around the camera, the
//              key light behind the head transmitting
// Per frame: its wall time closed by a 1-pixel read-back (a fence), the time composer.render()
// takes to return (the JS side: SwiftShader draws on the GPU process), and three's draw calls.
// SwiftShader's times are CPU times: compare rows of one run, as ratios.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { HEAD_CENTRE, HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { mulberry32 } from '/demo/seededRandom.js';
import { headRig } from '/test/pages/headRig.js';
import { median } from '/dev/gpuTimer.js';

/** 2,000 boxes in a 40-unit cube around the head (the scan's units, 5 cm each), 20 materials, seeded. */
function addCrowd(scene) {
  const random = mulberry32(11);
  const geometry = new THREE.BoxGeometry(0.6, 0.6, 0.6);
  const materials = Array.from({ length: 20 }, (_, i) => new THREE.MeshStandardMaterial({ color: new THREE.Color().setHSL(i / 20, 0.5, 0.5), roughness: 0.7 }));
  for (let i = 0; i < 2000; i++) {
    const box = new THREE.Mesh(geometry, materials[i % 20]);
    box.position.set(random() * 40 - 20, random() * 40 - 20, random() * 40 - 20);
    if (box.position.distanceTo(HEAD_CENTRE) < 4) box.position.multiplyScalar(3); // none inside the head
    box.rotation.set(random() * 3, random() * 3, 0);
    scene.add(box);
  }
}

const SCENES = {
  offScreen(rig) {
    addCrowd(rig.scene);
    rig.camera.lookAt(rig.camera.position.clone().add(new THREE.Vector3(-1, 0, -0.3))); // the boxes to its left in view
  },
  inView() {},
  crowd(rig) { addCrowd(rig.scene); },
};

async function makeRow(width, height, sceneName, withPipeline) {
  const rig = await headRig(width / height);
  setLightDirection(rig, 175, 15); // behind the head: its map is drawn wherever the head is on the screen
  SCENES[sceneName](rig);
  rig.camera.updateMatrixWorld();
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.info.autoReset = false;
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
  composer.renderToScreen = false;
  let sss = null;
  if (withPipeline) {
    sss = new SubsurfaceScattering({ scene: rig.scene, camera: rig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: rig.light });
    sss.makeSubsurface(rig.head.material);
    composer.addPass(sss);
  } else {
    composer.addPass(new RenderPass(rig.scene, rig.camera));
  }
  const pixel = new Uint16Array(4);
  return {
    isStandIn: rig.isStandIn,
    renderer,
    frame() {
      renderer.info.reset();
      const start = performance.now();
      composer.render();
      const js = performance.now() - start;
      const calls = renderer.info.render.calls;
      renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel);
      return { ms: performance.now() - start, js, calls };
    },
    dispose() { sss?.dispose(); composer.dispose(); renderer.dispose(); renderer.forceContextLoss(); },
  };
}

/** Every row in each of `rounds` rounds, `frames` timed frames each, after two untimed ones (compiles). */
async function run({ width = 640, height = 360, rounds = 5, frames = 5 } = {}) {
  const rows = {};
  for (const scene of Object.keys(SCENES)) {
    for (const [kind, withPipeline] of [['Plain', false], ['Ours', true]]) {
      const row = await makeRow(width, height, scene, withPipeline);
      row.frame();
      row.frame();
      rows[`${scene}${kind}`] = row;
    }
  }
  const samples = Object.fromEntries(Object.keys(rows).map((name) => [name, []]));
  for (let round = 0; round < rounds; round++) {
    for (const [name, row] of Object.entries(rows)) {
      for (let i = 0; i < frames; i++) samples[name].push(row.frame());
    }
  }
  const isStandIn = rows.inViewOurs.isStandIn;
  const glError = Math.max(...Object.values(rows).map((row) => row.renderer.getContext().getError()));
  for (const row of Object.values(rows)) row.dispose();
  const medianOf = (key) => Object.fromEntries(Object.entries(samples).map(([name, s]) => [name, median(s.map((f) => f[key]))]));
  return { width, height, rounds, frames, isStandIn, glError, medianMs: medianOf('ms'), medianJsMs: medianOf('js'), drawCalls: medianOf('calls') };
}

window.bench = { run };
window.testReady = true;
