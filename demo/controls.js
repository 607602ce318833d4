// The tuning panel (lil-gui, shipped with three): one control per state key, grouped like the
// pipeline. Changes go to `onChange(key)`; `refresh()` pulls values back after a preset. Its
// stylesheet is demo/lil-gui.css, linked by index.html: lil-gui's own would be an inline <style>,
// which the demo's Content-Security-Policy refuses.
import GUI from 'three/addons/libs/lil-gui.module.min.js';
import { STATE_SCHEMA } from './state.js';
import { FIGURES } from './figures.js';

const LABELS = {
  sss: 'scattering', width: 'width (mm)', depthThreshold: 'threshold (mm)', shrink: 'inward shrink (mm)',
  lightDepthSize: 'depth map size', lightAzimuth: 'azimuth (°)', lightElevation: 'elevation (°)',
  lightIntensity: 'intensity', lightColor: 'colour', followSurface: 'follow surface', split: 'split (left: off)',
  resolutionScale: 'resolution scale',
};

/**
 * @param {object} state the demo state (see state.js); edited in place
 * @param {object} hooks
 * @param {(key: string) => void} hooks.onChange
 * @param {(id: number, side: 'before'|'after') => void} hooks.onFigure
 * @param {() => object} hooks.timings the current timings summary
 */
export function createControls(state, { onChange, onFigure, timings }) {
  const gui = new GUI({ title: 'three-separable-sss', injectStyles: false });
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

  const scattering = gui.addFolder('Scattering');
  add(scattering, 'sss');
  add(scattering, 'profile');
  add(scattering, 'method');
  add(scattering, 'width', 0.05);
  // Samples: 'auto' or an odd count; lil-gui has no such control, so a dropdown of both.
  scattering.add(state, 'samples', ['auto', 3, 5, 7, 9, 11, 13, 17, 25, 33, 45, 63]).name('samples').onChange(() => onChange('samples'));
  addRgb(scattering, 'strength', 0.01);
  addRgb(scattering, 'falloff', 0.01);
  add(scattering, 'followSurface');
  add(scattering, 'depthThreshold', 0.5);

  const transmittance = gui.addFolder('Transmittance');
  add(transmittance, 'transmittance');
  add(transmittance, 'translucency', 0.01);
  add(transmittance, 'lightDepthSize');
  add(transmittance, 'shrink', 0.05);

  const specular = gui.addFolder('Specular');
  add(specular, 'specular', 0.01);
  add(specular, 'roughness', 0.01);

  const light = gui.addFolder('Light');
  add(light, 'lightAzimuth', 1);
  add(light, 'lightElevation', 1);
  add(light, 'lightIntensity', 0.1);
  add(light, 'lightColor');

  const view = gui.addFolder('View');
  add(view, 'split', 0.01);
  add(view, 'view');

  const figures = gui.addFolder("The paper's figures");
  for (const f of FIGURES) {
    const actions = {
      before: () => onFigure(f.id, 'before'),
      after: () => onFigure(f.id, 'after'),
    };
    const label = f.title.replace(' without and with ', ': ');
    figures.add(actions, 'before').name(`${f.id}. ${label} — without`);
    figures.add(actions, 'after').name(`${f.id}. ${label} — with`);
  }

  const performance = gui.addFolder('Performance');
  add(performance, 'resolutionScale', 0.05);
  const readout = { gpu: '…', cpu: '…', fps: '…' };
  const gpu = performance.add(readout, 'gpu').name('GPU ms / pass').disable();
  const cpu = performance.add(readout, 'cpu').name('CPU ms / frame').disable();
  const fps = performance.add(readout, 'fps').name('fps').disable();
  const showTimings = () => {
    const t = timings();
    const passes = Object.entries(t).filter(([k]) => k !== 'cpu' && k !== 'fps');
    readout.gpu = passes.length ? passes.map(([k, v]) => `${k} ${v.toFixed(2)}`).join(' · ') : 'no timer queries: CPU only';
    readout.cpu = Number.isFinite(t.cpu) ? t.cpu.toFixed(2) : '…';
    readout.fps = Number.isFinite(t.fps) ? t.fps.toFixed(1) : '…';
    gpu.updateDisplay();
    cpu.updateDisplay();
    fps.updateDisplay();
  };

  return {
    gui,
    /** Shows the state's current values (after a preset or a hash change). */
    refresh() {
      for (const c of gui.controllersRecursive()) c.updateDisplay();
    },
    showTimings,
  };
}
