// The browser side of bench/lights.js: the demo's head lit from behind by three lights (the key
// spot, the ear's point light, a directional rim light), one renderer and pipeline per row:
//   ours<n>   transmittance from the first n lights, each with a thickness map of our own; three's
//             shadow maps off
//   three<n>  no transmittance; the first n lights cast three's shadows (shadowMap on, castShadow):
//             the pass that reading thickness from three's shadow maps would have shared
//   both<n>   the two together: a user with shadows who turns transmittance on today
//   hook<n>   transmittance from the first n lights, the head's material moved by a vertex hook of
//             the user's (onBeforeCompile: it breathes), which the light's pass runs in a depth
//             material of the head's own: hook1 − hook0 against ours1 − ours0 is the light's pass
//             with the hook against without
// A frame's time is the wall time of composer.render() and a 1-pixel read-back (a fence).
// SwiftShader's times are CPU times: compare rows of one run, as ratios.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { HEAD_CENTRE, HEAD_WORLD_UNIT_IN_MM, setLightDirection } from '/demo/headScene.js';
import { headRig } from '/test/pages/headRig.js';
import { median } from '/dev/gpuTimer.js';

/** Each row's transmitting lights and shadow-casting lights, counted from the first. */
const ROWS = {
  ours0: { transmitting: 0, shadows: 0 },
  ours1: { transmitting: 1, shadows: 0 },
  ours3: { transmitting: 3, shadows: 0 },
  three1: { transmitting: 0, shadows: 1 },
  three3: { transmitting: 0, shadows: 3 },
  both1: { transmitting: 1, shadows: 1 },
  both3: { transmitting: 3, shadows: 3 },
  hook0: { transmitting: 0, shadows: 0, hook: true },
  hook1: { transmitting: 1, shadows: 0, hook: true },
};

/** A vertex hook as users write them: the head breathes along its normals, half a millimetre. */
function breathe(shader) {
  shader.uniforms.breath = { value: 1 };
  shader.vertexShader = `uniform float breath;\n${shader.vertexShader.replace('#include <begin_vertex>', '#include <begin_vertex>\n\ttransformed += objectNormal * 0.01 * sin( breath );')}`;
}

/** The rig's three lights, all behind the head (so each one's map is drawn), shadows at 1024². */
function threeLights(rig) {
  setLightDirection(rig, 175, 15);
  rig.pointLight.visible = true;
  const rim = new THREE.DirectionalLight(0xffffff, 1.5);
  rim.position.copy(HEAD_CENTRE).add(new THREE.Vector3(-12, 6, -12));
  rim.target.position.copy(HEAD_CENTRE);
  Object.assign(rim.shadow.camera, { left: -5, right: 5, top: 5, bottom: -5, near: 1, far: 40 });
  rig.scene.add(rim, rim.target);
  const lights = [rig.light, rig.pointLight, rim];
  for (const light of lights) light.shadow.mapSize.set(1024, 1024);
  return lights;
}

async function makeRow(width, height, { transmitting, shadows, hook = false }) {
  const rig = await headRig(width / height);
  const lights = threeLights(rig);
  lights.forEach((light, i) => { light.castShadow = i < shadows; });
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = shadows > 0;
  const sss = new SubsurfaceScattering({
    scene: rig.scene, camera: rig.camera, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, light: transmitting ? lights.slice(0, transmitting) : null,
  });
  if (hook) rig.head.material.onBeforeCompile = breathe;
  sss.makeSubsurface(rig.head.material);
  const composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  const pixel = new Float32Array(4);
  return {
    sss,
    renderer,
    isStandIn: rig.isStandIn,
    frame() {
      const start = performance.now();
      composer.render();
      renderer.readRenderTargetPixels(composer.readBuffer, 0, 0, 1, 1, pixel);
      return performance.now() - start;
    },
    dispose() { sss.dispose(); composer.dispose(); renderer.dispose(); renderer.forceContextLoss(); },
  };
}

/** The light depth maps a frame of `row` draws (its stage timer counts them). */
function lightMapsDrawn(row) {
  let maps = 0;
  row.sss.stageTimer = { begin(stage) { if (stage === 'lightDepth') maps++; }, end() {} };
  row.frame();
  row.sss.stageTimer = null;
  return maps;
}

/** Every row in each of `rounds` rounds, `frames` timed frames each, after two untimed ones (compiles). */
async function run({ width = 640, height = 360, rounds = 5, frames = 5 } = {}) {
  const rows = {};
  for (const [name, setup] of Object.entries(ROWS)) {
    rows[name] = await makeRow(width, height, setup);
    rows[name].frame();
  }
  const lightMaps = Object.fromEntries(Object.entries(rows).map(([name, row]) => [name, lightMapsDrawn(row)]));
  const times = Object.fromEntries(Object.keys(rows).map((name) => [name, []]));
  for (let round = 0; round < rounds; round++) {
    for (const [name, row] of Object.entries(rows)) {
      for (let i = 0; i < frames; i++) times[name].push(row.frame());
    }
  }
  const isStandIn = rows.ours0.isStandIn;
  const glError = Math.max(...Object.values(rows).map((row) => row.renderer.getContext().getError()));
  for (const row of Object.values(rows)) row.dispose();
  return {
    width, height, rounds, frames, rows: ROWS, isStandIn, glError, lightMaps,
    medianMs: Object.fromEntries(Object.entries(times).map(([name, t]) => [name, median(t)])), times,
  };
}

window.bench = { run };
window.testReady = true;
