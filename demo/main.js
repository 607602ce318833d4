// Demo page bootstrap, in named steps (start() at the bottom calls them in order): renderer, head,
// subsurface pipeline, the before/after divider, the header's camera shots, the settings panel, URL
// state, the timings overlay, and the test API (demo/testApi.js) that the browser tests and the
// figure renderer drive. How the state reaches the pipeline is demo/appliers.js. With
// ?renderer=webgpu the renderer and the pipeline are WebGPURenderer and the node
// (demo/webgpuPipeline.js), where the browser has WebGPU; elsewhere a notice says so and the
// page is the WebGL one.
import { ACESFilmicToneMapping, HalfFloatType, Vector3, WebGLRenderer, WebGLRenderTarget } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from '../src/index.js';
import { loadHead } from './headModel.js';
import { createHeadScene, createMarblePiece, HEAD_WORLD_UNIT_IN_MM } from './headScene.js';
import { createFoliagePiece } from './foliage.js';
import { SHOTS } from './framing.js';
import { defaultState, parseHash, formatHash } from './state.js';
import { figureState, presetState } from './figures.js';
import { createControls } from './controls.js';
import { PassTimings } from './passTimings.js';
import { TimingsHud } from './hud.js';
import { Divider } from './divider.js';
import { createAppliers, groupOf, KERNEL_KEYS } from './appliers.js';
import { testApi } from './testApi.js';
import { allowPlainTextHtml } from './trustedTypes.js';

const params = new URLSearchParams(location.search);
const container = document.getElementById('viewport');
const notice = document.getElementById('notice');
const hashNotice = document.getElementById('hash-notice');
const rendererNotice = document.getElementById('renderer-notice');
const progress = document.getElementById('progress');
const kernelCanvas = document.getElementById('kernel-plot');
const header = document.getElementById('intro');
const footer = document.getElementById('attribution');
/** Phones and narrow windows: the panel starts folded (style.css has the same width). */
const narrow = matchMedia('(max-width: 700px)');
const shotButtons = [...header.querySelectorAll('[data-shot]')];

// The header's, the attribution's and the timings' heights, for the layout (style.css) to keep
// clear of them.
const layoutObserver = new ResizeObserver(() => {
  const style = document.documentElement.style;
  style.setProperty('--header-h', `${header.offsetHeight}px`);
  style.setProperty('--footer-h', `${footer.offsetHeight}px`);
  style.setProperty('--hud-h', `${document.getElementById('hud').offsetHeight + 6}px`);
});
for (const element of [document.body, header, footer, document.getElementById('hud')]) layoutObserver.observe(element);

/** Shows a notice made of text and elements (no HTML strings: the page runs under a strict CSP). */
function showNotice(element, ...parts) {
  element.replaceChildren(...parts);
  element.hidden = false;
}

/** A <code> element holding `text`. */
function code(text) {
  const element = document.createElement('code');
  element.textContent = text;
  return element;
}

/** Reads the hash into a full state: defaults, then the figure or preset, then explicit keys. */
function stateFromHash(hash) {
  const { values, problems } = parseHash(hash);
  const state = defaultState();
  if (values.figure) Object.assign(state, figureState(values.figure, 'after'));
  if (values.preset) Object.assign(state, presetState(values.preset));
  Object.assign(state, values);
  return { state, problems };
}

/** The renderer, in the viewport: WebGL2, shadows, tone mapping applied by OutputPass (last). */
function createRenderer() {
  const renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
  if (!renderer.capabilities.isWebGL2) throw new Error('This demo needs WebGL2.');
  renderer.setSize(container.clientWidth, container.clientHeight);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping;
  container.appendChild(renderer.domElement);
  return renderer;
}

/** The head scan (or the stand-in bust, saying why), with the progress bar while it loads. */
async function loadHeadShowingProgress() {
  const head = await loadHead({ forceStandIn: params.has('standIn'), onProgress: (f) => { progress.value = f; } });
  progress.hidden = true;
  if (head.isStandIn) {
    showNotice(notice,
      `Showing a procedural stand-in bust: the head scan files are missing (${head.missing.join(', ')}); ${head.reason}. Run `,
      code('npm run assets'), ' with the files in ', code('public/assets/LeePerrySmith/'), ', or set ', code('SSS_ASSETS_DIR'),
      ' to a folder holding them, or run it online to download them.');
  }
  return head;
}

/**
 * The WebGPU page's module when ?renderer=webgpu asks for it and the browser has WebGPU; null
 * otherwise (the WebGL page), with a notice saying why where it was asked for.
 */
async function webgpuModule() {
  if (params.get('renderer') !== 'webgpu') return null;
  let missing;
  try {
    const webgpu = await import('./webgpuPipeline.js');
    missing = await webgpu.webgpuMissing();
    if (!missing) {
      showNotice(rendererNotice, 'WebGPURenderer, through ', code('three-separable-sss/webgpu'),
        ' (the divider, per-pass timings and the marble piece\'s own profile: WebGL page only).');
      return webgpu;
    }
  } catch (error) {
    missing = `its module did not load (${error.message})`;
  }
  showNotice(rendererNotice, `WebGPU is not available here: ${missing}. This is the WebGL page (WebGLRenderer and EffectComposer) instead.`);
  return null;
}

/** The scene around the head, the orbit controls, the pipeline and the composer it runs in. */
function createPipeline(renderer, head) {
  const rig = createHeadScene(head.mesh);
  const { scene, camera, light } = rig;
  const material = head.mesh.material;
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;

  // Skin at its physical scale (1 profile mm = 1 mm), light through the ears from the spot light.
  const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, samples: 'auto' });
  sss.makeSubsurface(material);
  const marble = createMarblePiece(); // made subsurface, with its own profile, while shown (demo/appliers.js)
  scene.add(marble);
  const foliage = createFoliagePiece(); // made subsurface while shown; its wind moves with the frames
  scene.add(foliage.piece);

  // Linear HDR all the way to OutputPass (tone mapping + sRGB last).
  // MSAA: the scene split follows the composer's samples, so silhouettes and creases are antialiased.
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(1, 1, { type: HalfFloatType, samples: 4 }));
  composer.addPass(sss); // in place of a RenderPass
  const outputPass = new OutputPass();
  composer.addPass(outputPass);
  return { renderer, head, rig, camera, light, material, marble, foliage, controls, sss, composer, outputPass };
}

/** The pipeline's parts with the timings overlay. */
function withTimings(parts) {
  const timings = new PassTimings(parts.renderer, parts.sss);
  return { ...parts, timings, hud: new TimingsHud(document.getElementById('hud'), timings) };
}

/** Follows the viewport's size and the pixel ratio (and the shot's framing, for the window's shape). */
function resize(demo) {
  const { camera, renderer, composer, state } = demo;
  const w = Math.max(1, container.clientWidth);
  const h = Math.max(1, container.clientHeight);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2) * state.resolutionScale);
  renderer.setSize(w, h);
  composer.setPixelRatio(renderer.getPixelRatio());
  composer.setSize(w, h);
  if (!state.camera) demo.apply.camera(); // the shot is framed for the window's shape
}

/** What the panel, the divider, the shot buttons and the hash do to the state (and the URL). */
function createActions(demo) {
  const { state } = demo;
  const applyAll = () => { for (const group of Object.keys(demo.apply)) demo.apply[group](); };
  const writeHash = () => {
    const hash = formatHash(state);
    history.replaceState(null, '', hash ? `#${hash}` : location.pathname + location.search);
  };
  // A figure or preset defines the whole view: everything else returns to its default (bar the resolution).
  const showPreset = (values) => {
    Object.assign(state, defaultState(), { resolutionScale: state.resolutionScale }, values);
    applyAll();
    demo.panel.refresh();
    writeHash();
  };
  const actions = {
    applyAll,
    writeHash,
    onChange(key) {
      if (!['figure', 'preset', 'camera'].includes(key)) Object.assign(state, { figure: null, preset: null });
      if (key === 'shot') state.camera = null; // a shot replaces an orbited camera
      demo.apply[groupOf(key)]?.();
      if (key === 'view' || KERNEL_KEYS.includes(key)) demo.apply.view();
      writeHash();
    },
    onFigure: (id, side) => showPreset(figureState(id, side)),
    onPreset: (name) => showPreset(presetState(name)),
    // Back to the first view: every setting at its default.
    onReset() {
      Object.assign(state, defaultState());
      applyAll();
      resize(demo);
      demo.panel.refresh();
      writeHash();
    },
    // An edited or pasted hash: start again from it (the panel is bound to `state`, so keep the object).
    onHash() {
      const next = stateFromHash(location.hash);
      for (const key of Object.keys(state)) delete state[key];
      Object.assign(state, next.state);
      demo.problems = next.problems;
      applyAll();
      demo.panel.refresh();
      showProblems(demo.problems);
    },
  };
  return actions;
}

/** The messages for ignored hash values, one line each (or none). */
function showProblems(problems) {
  if (!problems.length) {
    hashNotice.hidden = true;
    return;
  }
  showNotice(hashNotice, ...problems.map((p) => {
    const line = document.createElement('div');
    line.textContent = p;
    return line;
  }));
}

/** The header's shot buttons, the orbit controls, the hash, the viewport's size and pixel ratio. */
function listen(demo, actions) {
  const { state, camera, controls } = demo;
  for (const button of shotButtons) {
    button.addEventListener('click', () => {
      state.shot = button.dataset.shot;
      actions.onChange('shot');
      demo.panel.refresh();
    });
  }
  controls.addEventListener('end', () => {
    state.camera = [...camera.position.toArray(), ...controls.target.toArray()].map((v) => Math.round(v * 1000) / 1000);
    Object.assign(state, { figure: null, preset: null });
    actions.writeHash();
  });
  window.addEventListener('hashchange', actions.onHash);
  new ResizeObserver(() => resize(demo)).observe(container);
  // The window moved to a screen of another pixel ratio: the container's size may not change.
  const watchPixelRatio = () => {
    matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`).addEventListener('change', () => {
      resize(demo);
      watchPixelRatio();
    }, { once: true });
  };
  watchPixelRatio();
}

/**
 * Whether the open panel would cover the face: the window is not wide enough for the face and the
 * panel side by side (the shot's halfWidth either side of the orbit target, projected).
 */
function panelCoversFace({ camera, controls, renderer, state }) {
  camera.updateMatrixWorld();
  const right = new Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
  const edge = controls.target.clone().addScaledVector(right, SHOTS[state.shot].halfWidth).project(camera);
  const canvasBox = renderer.domElement.getBoundingClientRect();
  return canvasBox.left + (edge.x * 0.5 + 0.5) * canvasBox.width > document.getElementById('panel').getBoundingClientRect().left;
}

/** One frame: the controls' damping, the wind, the composer, the timings (the overlay twice a second). */
function createFrame({ controls, composer, timings, hud, foliage }, animated) {
  let lastTimingsUpdate = 0;
  return () => {
    controls.update();
    if (animated) foliage.setTime(performance.now() / 1000); // still pages keep the wind where a test sets it
    const t0 = performance.now();
    composer.render();
    timings.frame(performance.now() - t0);
    if (t0 - lastTimingsUpdate > 500) {
      hud.update();
      lastTimingsUpdate = t0;
    }
  };
}

/** Reloads the page on the other renderer (the query's `renderer`), keeping the hash. */
function switchRenderer(kind) {
  const url = new URL(location.href);
  if (kind === 'webgpu') url.searchParams.set('renderer', 'webgpu');
  else url.searchParams.delete('renderer');
  location.assign(url);
}

/** The page's steps in order: each named above. */
async function start() {
  allowPlainTextHtml(); // before lil-gui writes its first title
  const webgpu = await webgpuModule();
  const renderer = webgpu ? await webgpu.createWebgpuRenderer(container) : createRenderer();
  const head = await loadHeadShowingProgress();
  const parts = webgpu ? webgpu.createWebgpuPipeline(renderer, head) : createPipeline(renderer, head);
  const demo = { ...withTimings(parts), ...stateFromHash(location.hash), kernelCanvas, shotButtons, rendererKind: webgpu ? 'webgpu' : 'webgl' };
  demo.resize = () => resize(demo);
  // The node shows one image: no divider on the WebGPU page.
  demo.divider = webgpu ? { show() {} } : new Divider(document.getElementById('divider'), {
    onInput: (fraction) => {
      demo.state.split = fraction;
      demo.apply.split();
      demo.panel.refresh();
    },
    onCommit: () => actions.onChange('split'),
  });
  demo.apply = createAppliers(demo);
  const actions = createActions(demo);
  demo.panel = createControls(demo.state, {
    ...actions, container: document.getElementById('panel'), renderer: demo.rendererKind, onRenderer: switchRenderer,
  });
  actions.applyAll();
  showProblems(demo.problems);
  listen(demo, actions);
  resize(demo);
  // The panel starts folded where, open, it would cover the face.
  if (narrow.matches || panelCoversFace(demo)) demo.panel.gui.close();
  const frame = createFrame(demo, !params.has('still'));
  if (!params.has('still')) renderer.setAnimationLoop(frame);
  frame();
  window.demo = testApi(demo, actions, frame);
}

window.testReady = start().then(() => true, (error) => {
  progress.hidden = true;
  showNotice(notice, `The demo could not start: ${error.message}`);
  console.error(error);
  return false;
});
