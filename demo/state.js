// The demo's state: one object whose keys are the control names and the URL hash keys, so a
// view can be shared. Each key has a schema; values read from the hash are validated, and invalid
// ones are ignored with a message the page shows. Pure: runs in Node for the unit tests.

import { SHOT_NAMES } from './framing.js';

/** The presets besides the paper's figures (demo/figures.js's PRESETS). */
export const PRESET_NAMES = ['earLight', 'foliage'];

const PROFILES = ['skin', 'skinBurley', 'marble', 'milk'];
const VIEWS = ['final', 'diffuse', 'specular', 'depth', 'mask', 'thickness', 'transmittance', 'kernel'];

const bool = (fallback) => ({ kind: 'bool', fallback });
const number = (min, max, fallback, unit = '') => ({ kind: 'number', min, max, fallback, unit });
const oneOf = (values, fallback) => ({ kind: 'oneOf', values, fallback });
const rgb = (min, max, fallback) => ({ kind: 'rgb', min, max, fallback });

/** Every key of the state, with its accepted values and default. */
export const STATE_SCHEMA = {
  // Scattering
  sss: bool(true),
  profile: oneOf(PROFILES, 'skin'),
  method: oneOf(['footprint', 'marginal', 'reference'], 'footprint'),
  width: number(0.05, 20, 1, 'mm'),
  samples: { kind: 'samples', fallback: 'auto' },
  // The isotropic blur's groups (method 'footprint'; 1: one separable kernel, as in version 0.2).
  groups: oneOf([1, 'auto', 2, 3, 4], 1),
  strength: rgb(0, 1, [1, 1, 1]),
  falloff: rgb(0.01, 10, [1, 0.37, 0.3]),
  followSurface: oneOf(['drop', 'lerp', 'off'], 'drop'),
  depthThreshold: number(0.5, 200, 6, 'mm'),
  // A marble ball beside the head in the same pipeline, with its own profile (off by default).
  marble: bool(false),
  // A plant beside the head whose leaves sway through an onBeforeCompile of their own (demo/foliage.js).
  foliage: bool(false),
  // Transmittance
  transmittance: bool(true),
  translucency: number(0, 0.95, 0),
  lightDepthSize: oneOf([256, 512, 1024, 2048], 1024),
  shrink: number(0, 5, 0.6, 'mm'),
  // Specular
  specular: number(0, 2, 1),
  roughness: number(0.05, 1, 0.45),
  // Light: the first view's key light, high and to the face's right, so the brows, nose and lips
  // cast shadows whose edges the blur visibly softens.
  lightAzimuth: number(-180, 360, -35, '°'),
  lightElevation: number(-80, 89, 50, '°'),
  lightIntensity: number(0, 20, 5),
  lightColor: { kind: 'colour', fallback: '#ffffff' },
  // A second transmitting light: the point light behind the right ear (demo/headScene.js).
  pointLight: bool(false),
  // View: the page opens split in two (left without scattering), on the close-up of the face.
  split: number(0, 1, 0.5),
  view: oneOf(VIEWS, 'final'),
  resolutionScale: number(0.25, 2, 1),
  shot: oneOf(SHOT_NAMES, 'face'),
  figure: { kind: 'figure', fallback: null },
  preset: oneOf(PRESET_NAMES, null),
  // Set when the camera was moved (orbit) or by a figure; null: the shot, framed to the window.
  camera: { kind: 'camera', fallback: null },
};

/** A fresh state with every default. */
export function defaultState() {
  const state = {};
  for (const [key, schema] of Object.entries(STATE_SCHEMA)) {
    state[key] = Array.isArray(schema.fallback) ? [...schema.fallback] : schema.fallback;
  }
  return state;
}

/** The accepted values of a key, in words, for messages. */
function accepted(schema) {
  switch (schema.kind) {
    case 'bool': return '0 or 1';
    case 'number': return `a number in [${schema.min}, ${schema.max}]${schema.unit ? ` ${schema.unit}` : ''}`;
    case 'oneOf': return `one of ${schema.values.join(', ')}`;
    case 'rgb': return `three numbers in [${schema.min}, ${schema.max}], comma-separated`;
    case 'samples': return "'auto' or an odd integer in 3..63";
    case 'colour': return 'a colour like #ffcc88';
    case 'figure': return 'an integer in 1..5';
    case 'camera': return 'six numbers: position x,y,z and target x,y,z';
    default: return 'a valid value';
  }
}

/** Parses one hash value for `schema`; returns undefined when it is not acceptable. */
function parseValue(schema, text) {
  const num = (t) => (t.trim() === '' ? NaN : Number(t));
  switch (schema.kind) {
    case 'bool': return text === '1' || text === 'true' ? true : text === '0' || text === 'false' ? false : undefined;
    case 'number': {
      const v = num(text);
      return Number.isFinite(v) && v >= schema.min && v <= schema.max ? v : undefined;
    }
    case 'oneOf': {
      const v = schema.values.find((option) => String(option) === text);
      return v;
    }
    case 'rgb': {
      const parts = text.split(',').map(num);
      return parts.length === 3 && parts.every((v) => Number.isFinite(v) && v >= schema.min && v <= schema.max) ? parts : undefined;
    }
    case 'samples': {
      if (text === 'auto') return 'auto';
      const v = num(text);
      return Number.isInteger(v) && v >= 3 && v <= 63 && v % 2 === 1 ? v : undefined;
    }
    case 'colour': return /^#[0-9a-f]{6}$/i.test(text) ? text.toLowerCase() : undefined;
    case 'figure': {
      const v = num(text);
      return Number.isInteger(v) && v >= 1 && v <= 5 ? v : undefined;
    }
    case 'camera': {
      const parts = text.split(',').map(num);
      return parts.length === 6 && parts.every(Number.isFinite) ? parts : undefined;
    }
    default: return undefined;
  }
}

/** Writes one value for the hash. */
function formatValue(schema, value) {
  const round = (v) => String(Math.round(v * 1e4) / 1e4);
  switch (schema.kind) {
    case 'bool': return value ? '1' : '0';
    case 'number': return round(value);
    case 'rgb':
    case 'camera': return value.map(round).join(',');
    default: return String(value);
  }
}

/**
 * Reads a URL hash ("#sss=0&width=2") into a partial state.
 * @param {string} hash
 * @returns {{ values: object, problems: string[] }} accepted values, and a message per ignored entry
 */
export function parseHash(hash) {
  const values = {};
  const problems = [];
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  for (const [key, text] of params) {
    const schema = STATE_SCHEMA[key];
    if (!schema) {
      problems.push(`Ignored "${key}": not a setting (known: ${Object.keys(STATE_SCHEMA).join(', ')}).`);
      continue;
    }
    const value = parseValue(schema, text);
    if (value === undefined) problems.push(`Ignored ${key}=${text}: it must be ${accepted(schema)}.`);
    else values[key] = value;
  }
  return { values, problems };
}

/**
 * Writes the state's non-default values as a URL hash (without '#'), in schema order.
 * @param {object} state
 */
export function formatHash(state) {
  const defaults = defaultState();
  const params = new URLSearchParams();
  for (const [key, schema] of Object.entries(STATE_SCHEMA)) {
    const value = state[key];
    if (value === null || value === undefined) continue;
    if (JSON.stringify(value) === JSON.stringify(defaults[key])) continue;
    params.set(key, formatValue(schema, value));
  }
  return params.toString().replaceAll('%2C', ',').replaceAll('%23', '#');
}
