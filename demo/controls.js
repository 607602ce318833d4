// The settings panel (lil-gui, shipped with three): a reset button, the paper's figures as presets,
// the controls a visitor reaches for first (compare, light, skin) open, and the rest folded under
// "More". One control per state key; changes go to `onChange(key)`; `refresh()` pulls values back
// after a preset or a hash change. Its stylesheet is demo/lil-gui.css, linked by index.html:
// lil-gui's own would be an inline <style>, which the demo's Content-Security-Policy refuses.
import GUI from 'three/addons/libs/lil-gui.module.min.js';
import { STATE_SCHEMA } from './state.js';
import { FIGURES, PRESETS } from './figures.js';

const LABELS = {
  sss: 'scattering', width: 'width (mm)', depthThreshold: 'threshold (mm)', shrink: 'inward shrink (mm)',
  lightDepthSize: 'depth map size', lightAzimuth: 'azimuth (°)', lightElevation: 'elevation (°)',
  lightIntensity: 'intensity', lightColor: 'colour', followSurface: 'follow surface', split: 'divider (left: off)',
  resolutionScale: 'resolution scale', marble: 'marble piece (its own profile)', foliage: 'swaying leaves',
  groups: 'isotropy groups (1: one kernel)', pointLight: 'ear point light',
};

/** Short names of the figures, for the preset rows. */
const FIGURE_NAMES = { 1: 'Nose', 2: 'Ear', 3: 'Skin', 4: 'Edges', 5: 'Full model' };
/** What "without" turns off, per figure toggle. */
const TOGGLE_NAMES = { transmittance: 'transmittance', sss: 'scattering', followSurface: 'depth test' };

/**
 * @param {object} state the demo state (see state.js); edited in place
 * @param {object} hooks
 * @param {(key: string) => void} hooks.onChange
 * @param {(id: number, side: 'before'|'after') => void} hooks.onFigure
 * @param {(name: string) => void} hooks.onPreset shows one of figures.js's PRESETS
 * @param {() => void} hooks.onReset back to the first view
 * @param {HTMLElement} hooks.container where the panel goes
 * @param {'webgl'|'webgpu'} [hooks.renderer='webgl'] the page's renderer
 * @param {(kind: 'webgl'|'webgpu') => void} [hooks.onRenderer] switches to the other one
 */
export function createControls(state, { onChange, onFigure, onPreset, onReset, container, renderer = 'webgl', onRenderer = () => {} }) {
  const gui = new GUI({ title: 'Settings', container, injectStyles: false });
  const add = (folder, key, ...args) => {
    const schema = STATE_SCHEMA[key];
    let controller;
    if (schema.kind === 'colour') controller = folder.addColor(state, key);
    else if (schema.kind === 'oneOf') controller = folder.add(state, key, schema.values);
    else if (schema.kind === 'number') controller = folder.add(state, key, schema.min, schema.max, ...args);
    else controller = folder.add(state, key, ...args);
    return controller.name(LABELS[key] ?? key).onChange(() => onChange(key));
  };
  const addRgb = (folder, key, step) => {
    const schema = STATE_SCHEMA[key];
    const sub = folder.addFolder(`${key} (RGB)`).close();
    ['r', 'g', 'b'].forEach((channel, c) => {
      const proxy = { get [channel]() { return state[key][c]; }, set [channel](v) { state[key][c] = v; } };
      sub.add(proxy, channel, schema.min, schema.max, step).onChange(() => onChange(key));
    });
  };

  gui.add({ reset: onReset }, 'reset').name('↺ reset to the first view');

  // The paper's figures: one row each, "without" and "with" side by side (lil-gui has no such
  // row, so plain buttons inside the folder). The row of the figure shown is marked.
  const presets = gui.addFolder("Presets: the paper's figures");
  presets.domElement.classList.add('presets');
  const rows = FIGURES.map((f) => {
    const row = document.createElement('div');
    row.className = 'preset-row';
    row.title = f.caption;
    const name = document.createElement('span');
    name.className = 'preset-name';
    name.textContent = `${f.id} · ${FIGURE_NAMES[f.id]}`;
    row.append(name);
    for (const side of ['before', 'after']) {
      const button = document.createElement('button');
      button.type = 'button';
      button.dataset.figure = String(f.id);
      button.dataset.side = side;
      button.textContent = side === 'before' ? 'without' : 'with';
      button.title = `Figure ${f.id}, ${f.title.toLowerCase()}: ${side === 'before' ? 'without' : 'with'} ${TOGGLE_NAMES[f.toggle]}`;
      button.addEventListener('click', () => onFigure(f.id, side));
      row.append(button);
    }
    presets.$children.append(row);
    return { figure: f, row };
  });
  const markPreset = () => {
    for (const { figure, row } of rows) {
      const shown = state.figure === figure.id;
      row.classList.toggle('active', shown);
      for (const button of row.querySelectorAll('button')) {
        const side = state[figure.toggle] === figure[button.dataset.side];
        button.setAttribute('aria-pressed', String(shown && side));
      }
    }
  };

  const compare = gui.addFolder('Compare');
  add(compare, 'sss');
  add(compare, 'split', 0.01);
  add(compare, 'view');

  const light = gui.addFolder('Light');
  add(light, 'lightAzimuth', 1);
  add(light, 'lightElevation', 1);
  add(light, 'lightIntensity', 0.1);
  // A second light: the preset frames the ear; the switch itself is under More › Transmittance.
  light.add({ earLight: () => onPreset('earLight') }, 'earLight').name('▶ preset: ear light').domElement.title = PRESETS.earLight.caption;
  // Leaves lit from behind, swaying: the switch itself is under More.
  light.add({ foliage: () => onPreset('foliage') }, 'foliage').name('▶ preset: leaves').domElement.title = PRESETS.foliage.caption;

  const skin = gui.addFolder('Skin');
  add(skin, 'width', 0.05);
  add(skin, 'transmittance');
  add(skin, 'translucency', 0.01);

  // Everything else, folded.
  const more = gui.addFolder('More').close();
  const kernel = more.addFolder('Kernel');
  add(kernel, 'profile');
  add(kernel, 'method');
  // Samples: 'auto' or an odd count; lil-gui has no such control, so a dropdown of both.
  kernel.add(state, 'samples', ['auto', 3, 5, 7, 9, 11, 13, 17, 25, 33, 45, 63]).name('samples').onChange(() => onChange('samples'));
  add(kernel, 'groups');
  addRgb(kernel, 'strength', 0.01);
  addRgb(kernel, 'falloff', 0.01);
  const edges = more.addFolder('Depth edges');
  add(edges, 'followSurface');
  add(edges, 'depthThreshold', 0.5);
  const transmittance = more.addFolder('Transmittance');
  add(transmittance, 'lightDepthSize');
  add(transmittance, 'shrink', 0.05);
  add(transmittance, 'pointLight');
  const specular = more.addFolder('Specular');
  add(specular, 'specular', 0.01);
  add(specular, 'roughness', 0.01);
  add(more, 'marble');
  add(more, 'foliage');
  add(more, 'lightColor');
  add(more, 'shot');
  add(more, 'resolutionScale', 0.05);
  // The other renderer: a reload (?renderer=webgpu), the hash kept.
  const other = renderer === 'webgpu' ? 'webgl' : 'webgpu';
  more.add({ switch: () => onRenderer(other) }, 'switch').name(other === 'webgpu' ? '⇄ WebGPU (reloads)' : '⇄ WebGL (reloads)');

  markPreset();
  return {
    gui,
    /** Shows the state's current values (after a preset or a hash change). */
    refresh() {
      for (const c of gui.controllersRecursive()) c.updateDisplay();
      markPreset();
    },
  };
}
