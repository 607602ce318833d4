// Demo page bootstrap: renderer, composer, controls, resize, loading progress and the test API
// (window.demo) that the browser tests and the figure renderer drive.
import { ACESFilmicToneMapping, HalfFloatType, WebGLRenderer, WebGLRenderTarget } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from '../src/index.js';
import { loadHead } from './headModel.js';
import { createHeadScene, FACE_CENTRE, HEAD_WORLD_UNIT_IN_MM } from './headScene.js';
import { readRenderTargetFloats } from './readback.js';

const params = new URLSearchParams(location.search);
const container = document.getElementById('viewport');
const notice = document.getElementById('notice');
const progress = document.getElementById('progress');

function showNotice(html) {
  notice.innerHTML = html;
  notice.hidden = false;
}

async function start() {
  const renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
  if (!renderer.capabilities.isWebGL2) throw new Error('This demo needs WebGL2.');
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setSize(container.clientWidth, container.clientHeight);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping; // applied by OutputPass, last
  container.appendChild(renderer.domElement);

  const head = await loadHead({
    forceStandIn: params.has('standIn'),
    onProgress: (f) => { progress.value = f; },
  });
  progress.hidden = true;
  if (head.isStandIn) {
    showNotice(
      `Showing a procedural stand-in bust: the head scan files are missing (${head.missing.join(', ')}); ${head.reason}. ` +
      'Run <code>npm run assets</code> with the files in <code>public/assets/LeePerrySmith/</code>, ' +
      'or set <code>SSS_ASSETS_DIR</code> to a folder holding them, or run it online to download them.',
    );
  }

  const rig = createHeadScene(head.mesh);
  const { scene, camera } = rig;
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(FACE_CENTRE);
  controls.enableDamping = true;
  controls.update();

  // Skin at its physical scale (1 profile mm = 1 mm), light through the ears from the spot light.
  const sss = new SubsurfaceScattering({
    scene, camera, light: rig.light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, profile: 'skin', samples: 17,
  });
  sss.makeSubsurface(head.mesh.material, { widthMm: 1, translucency: 0 });

  // Linear HDR all the way to OutputPass (tone mapping + sRGB last).
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(1, 1, { type: HalfFloatType }));
  sss.addTo(composer);
  const outputPass = new OutputPass();
  composer.addPass(outputPass);

  function resize() {
    const w = Math.max(1, container.clientWidth);
    const h = Math.max(1, container.clientHeight);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    renderer.setSize(w, h);
    composer.setPixelRatio(renderer.getPixelRatio());
    composer.setSize(w, h);
  }
  new ResizeObserver(resize).observe(container);
  resize();

  let animate = !params.has('still');
  renderer.setAnimationLoop(() => {
    if (!animate) return;
    controls.update();
    composer.render();
  });
  composer.render();

  window.demo = {
    rig, renderer, composer, head, sss,
    /** The face centre, world units: where tests look for a lit face. */
    facePoint: FACE_CENTRE,
    isStandIn: head.isStandIn,
    /** Stops the animation loop (tests render on demand). */
    stop() { animate = false; },
    render() { composer.render(); },
    /** Renders once and reads the linear HDR image that OutputPass would receive. */
    async readHdr() {
      outputPass.enabled = false;
      composer.renderToScreen = false;
      try {
        composer.render();
        const target = composer.readBuffer;
        return { width: target.width, height: target.height, data: await readRenderTargetFloats(renderer, target) };
      } finally {
        outputPass.enabled = true;
        composer.renderToScreen = true;
      }
    },
  };
}

window.testReady = start().then(() => true, (error) => {
  progress.hidden = true;
  showNotice(`The demo could not start: ${error.message}`);
  console.error(error);
  return false;
});
