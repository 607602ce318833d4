// Demo page bootstrap: renderer, head, subsurface pipeline, the before/after divider, the header's
// camera shots, the settings panel, URL state, the timings overlay, and the test API (window.demo)
// that the browser tests and the figure renderer drive.
import { ACESFilmicToneMapping, HalfFloatType, Vector3, WebGLRenderer, WebGLRenderTarget } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering, getProfile } from '../src/index.js';
import { loadHead } from './headModel.js';
import { createHeadScene, setLightDirection, HEAD_WORLD_UNIT_IN_MM } from './headScene.js';
import { SHOTS, shotCamera } from './framing.js';
import { readRenderTargetFloats } from '../dev/readback.js';
import { defaultState, parseHash, formatHash } from './state.js';
import { figureState } from './figures.js';
import { createControls } from './controls.js';
import { PassTimings } from './passTimings.js';
import { TimingsHud } from './hud.js';
import { Divider } from './divider.js';
import { drawKernel } from './kernelPlot.js';

const params = new URLSearchParams(location.search);
const container = document.getElementById('viewport');
const notice = document.getElementById('notice');
const hashNotice = document.getElementById('hash-notice');
const progress = document.getElementById('progress');
const kernelCanvas = document.getElementById('kernel-plot');
const header = document.getElementById('intro');
const footer = document.getElementById('attribution');
/** Phones and narrow windows: the panel starts folded (style.css has the same width). */
const narrow = matchMedia('(max-width: 700px)');

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

/** Reads the hash into a full state: defaults, then the figure preset, then explicit keys. */
function stateFromHash(hash) {
  const { values, problems } = parseHash(hash);
  const state = defaultState();
  if (values.figure) Object.assign(state, figureState(values.figure, 'after'));
  Object.assign(state, values);
  return { state, problems };
}

async function start() {
  const renderer = new WebGLRenderer({ antialias: false, powerPreference: 'high-performance' });
  if (!renderer.capabilities.isWebGL2) throw new Error('This demo needs WebGL2.');
  renderer.setSize(container.clientWidth, container.clientHeight);
  renderer.shadowMap.enabled = true;
  renderer.toneMapping = ACESFilmicToneMapping; // applied by OutputPass, last
  container.appendChild(renderer.domElement);

  const head = await loadHead({ forceStandIn: params.has('standIn'), onProgress: (f) => { progress.value = f; } });
  progress.hidden = true;
  if (head.isStandIn) {
    showNotice(notice,
      `Showing a procedural stand-in bust: the head scan files are missing (${head.missing.join(', ')}); ${head.reason}. Run `,
      code('npm run assets'), ' with the files in ', code('public/assets/LeePerrySmith/'), ', or set ', code('SSS_ASSETS_DIR'),
      ' to a folder holding them, or run it online to download them.');
  }

  const rig = createHeadScene(head.mesh);
  const { scene, camera, light } = rig;
  const material = head.mesh.material;
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;

  // Skin at its physical scale (1 profile mm = 1 mm), light through the ears from the spot light.
  const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm: HEAD_WORLD_UNIT_IN_MM, samples: 'auto' });
  sss.makeSubsurface(material);

  // Linear HDR all the way to OutputPass (tone mapping + sRGB last).
  // MSAA: the scene split follows the composer's samples, so silhouettes and creases are antialiased.
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(1, 1, { type: HalfFloatType, samples: 4 }));
  composer.addPass(sss); // in place of a RenderPass
  const outputPass = new OutputPass();
  composer.addPass(outputPass);

  const timings = new PassTimings(renderer, sss);
  const hud = new TimingsHud(document.getElementById('hud'), timings);

  const initial = stateFromHash(location.hash);
  const state = initial.state;
  let problems = initial.problems;

  function resize() {
    const w = Math.max(1, container.clientWidth);
    const h = Math.max(1, container.clientHeight);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2) * state.resolutionScale);
    renderer.setSize(w, h);
    composer.setPixelRatio(renderer.getPixelRatio());
    composer.setSize(w, h);
    if (!state.camera) apply.camera(); // the shot is framed for the window's shape
  }

  // Nothing to compare: scattering off, the divider at an edge, or a view the split does not affect.
  const dividerVisible = () => state.sss && state.split > 0 && state.split < 1 && ['final', 'diffuse', 'kernel'].includes(state.view);
  const divider = new Divider(document.getElementById('divider'), {
    onInput: (fraction) => {
      state.split = fraction;
      apply.split();
      panel.refresh();
    },
    onCommit: () => onChange('split'),
  });

  // How each key reaches the scene and the pipeline.
  const kernelKeys = ['profile', 'method', 'samples', 'strength', 'falloff'];
  const apply = {
    sss: () => {
      sss.scattering = state.sss;
      divider.show(state.split, dividerVisible());
    },
    kernel: () => Object.assign(sss, {
      profile: state.profile, method: state.method, samples: state.samples,
      strength: [...state.strength], falloff: [...state.falloff],
    }),
    material: () => sss.makeSubsurface(material, { widthMm: state.width, translucency: state.translucency, shrinkMm: state.shrink }),
    followSurface: () => Object.assign(sss, { followSurface: state.followSurface, depthThresholdMm: state.depthThreshold }),
    transmittance: () => { sss.transmittance = state.transmittance; },
    lightDepthSize: () => sss.lightDepth.setSize(state.lightDepthSize),
    specular: () => { material.specularIntensity = state.specular; material.roughness = state.roughness; },
    light: () => {
      setLightDirection(rig, state.lightAzimuth, state.lightElevation);
      light.intensity = state.lightIntensity;
      light.color.set(state.lightColor);
    },
    split: () => {
      sss.split = state.split;
      divider.show(state.split, dividerVisible());
    },
    view: () => {
      // Depth view: white at the camera, black 30 units (1.5 m) away, past the head at any zoom.
      Object.assign(sss, { debugView: state.view === 'kernel' ? 'final' : state.view, debugDepthRange: 30 });
      kernelCanvas.hidden = state.view !== 'kernel';
      if (state.view === 'kernel') drawKernel(kernelCanvas, sss.kernel, state.method === 'reference' ? null : getProfile(state.profile));
      divider.show(state.split, dividerVisible());
    },
    resolutionScale: resize,
    camera: () => {
      const [x, y, z, tx, ty, tz] = state.camera ?? shotCamera(state.shot, camera.aspect, camera.fov);
      camera.position.set(x, y, z);
      controls.target.set(tx, ty, tz);
      controls.update();
      for (const button of shotButtons) button.setAttribute('aria-pressed', String(!state.camera && button.dataset.shot === state.shot));
    },
  };
  const shotButtons = [...header.querySelectorAll('[data-shot]')];
  const groupOf = (key) => {
    if (kernelKeys.includes(key)) return 'kernel';
    if (['width', 'translucency', 'shrink'].includes(key)) return 'material';
    if (key === 'depthThreshold') return 'followSurface';
    if (key === 'roughness') return 'specular';
    if (key === 'shot') return 'camera';
    if (key.startsWith('light') && key !== 'lightDepthSize') return 'light';
    return key;
  };
  function applyAll() {
    for (const group of Object.keys(apply)) apply[group]();
  }

  function writeHash() {
    const hash = formatHash(state);
    history.replaceState(null, '', hash ? `#${hash}` : location.pathname + location.search);
  }

  function onChange(key) {
    if (key !== 'figure' && key !== 'camera') state.figure = null;
    if (key === 'shot') state.camera = null; // a shot replaces an orbited camera
    apply[groupOf(key)]?.();
    if (key === 'view' || kernelKeys.includes(key)) apply.view();
    writeHash();
  }

  // A figure defines the whole view: everything else returns to its default (bar the resolution).
  function onFigure(id, side) {
    Object.assign(state, defaultState(), { resolutionScale: state.resolutionScale }, figureState(id, side));
    applyAll();
    panel.refresh();
    writeHash();
  }

  // Back to the first view: every setting at its default.
  function onReset() {
    Object.assign(state, defaultState());
    applyAll();
    resize();
    panel.refresh();
    writeHash();
  }

  function showProblems() {
    if (problems.length) {
      showNotice(hashNotice, ...problems.map((p) => {
        const line = document.createElement('div');
        line.textContent = p;
        return line;
      }));
    }
    else hashNotice.hidden = true;
  }

  const panel = createControls(state, { onChange, onFigure, onReset, container: document.getElementById('panel') });
  for (const button of shotButtons) {
    button.addEventListener('click', () => {
      state.shot = button.dataset.shot;
      onChange('shot');
      panel.refresh();
    });
  }
  applyAll();
  showProblems();
  controls.addEventListener('end', () => {
    state.camera = [...camera.position.toArray(), ...controls.target.toArray()].map((v) => Math.round(v * 1000) / 1000);
    state.figure = null;
    writeHash();
  });
  // An edited or pasted hash: start again from it (the panel is bound to `state`, so keep the object).
  window.addEventListener('hashchange', () => {
    const next = stateFromHash(location.hash);
    for (const key of Object.keys(state)) delete state[key];
    Object.assign(state, next.state);
    problems = next.problems;
    applyAll();
    panel.refresh();
    showProblems();
  });
  new ResizeObserver(resize).observe(container);
  // The window moved to a screen of another pixel ratio: the container's size may not change.
  const watchPixelRatio = () => {
    matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`).addEventListener('change', () => {
      resize();
      watchPixelRatio();
    }, { once: true });
  };
  watchPixelRatio();
  resize();

  // The panel starts folded where, open, it would cover the face: narrow windows, or a window
  // not wide enough for the face and the panel side by side (the shot's halfWidth either side of
  // the orbit target, projected).
  const panelCoversFace = () => {
    camera.updateMatrixWorld();
    const right = new Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
    const edge = controls.target.clone().addScaledVector(right, SHOTS[state.shot].halfWidth).project(camera);
    const canvasBox = renderer.domElement.getBoundingClientRect();
    return canvasBox.left + (edge.x * 0.5 + 0.5) * canvasBox.width > document.getElementById('panel').getBoundingClientRect().left;
  };
  if (narrow.matches || panelCoversFace()) panel.gui.close();

  let lastTimingsUpdate = 0;
  function frame() {
    controls.update();
    const t0 = performance.now();
    composer.render();
    timings.frame(performance.now() - t0);
    if (t0 - lastTimingsUpdate > 500) {
      hud.update();
      lastTimingsUpdate = t0;
    }
  }
  if (!params.has('still')) renderer.setAnimationLoop(frame);
  frame();

  window.demo = {
    rig, renderer, composer, head, sss, state, panel, timings, hud, divider, controls,
    isStandIn: head.isStandIn,
    /** The face centre, world units: where tests look for a lit face. */
    facePoint: rig.facePoint,
    /** The messages shown for ignored hash values. */
    get problems() { return problems; },
    /** Stops the animation loop (tests render on demand). */
    stop() { renderer.setAnimationLoop(null); },
    render() { frame(); },
    /** Sets a control's value as the panel would. */
    set(key, value) {
      state[key] = value;
      onChange(key);
      panel.refresh();
    },
    figure: onFigure,
    reset: onReset,
    /** Shows or hides everything over the image (header, panel, divider, timings, attribution). */
    chrome(visible) { document.body.classList.toggle('no-chrome', !visible); },
    /** Refreshes the timings overlay now (it updates itself twice a second while animating). */
    updateTimings() { hud.update(); },
    /** Reads the scene pass's surface attachment (linear depth, width) of the last frame. */
    readSurface() {
      return readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 2);
    },
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
  showNotice(notice, `The demo could not start: ${error.message}`);
  console.error(error);
  return false;
});
