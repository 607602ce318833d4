// The paper's five figures (Tetzlaff 2013, after Jimenez) as presets: camera, light and settings,
// and the one setting that differs between the "before" and "after" images. Then the demo's own
// presets (`#preset=<name>`), one view each.
import { DEFAULT_CAMERA } from './headScene.js';

// Coordinates are the scan's (Y up, facing +Z, ~5 cm per unit): nose tip (−0.09, 1.10, 2.59),
// ears at x ≈ ±1.8, y ≈ 1.5, z ≈ −0.16, top of the head at y ≈ 3.97.

/**
 * @typedef {object} Figure
 * @property {number} id 1..5, as in the paper
 * @property {string} title
 * @property {string} caption what to look for
 * @property {number[]} camera position x,y,z and target x,y,z
 * @property {object} settings state values of the "after" image (light, widths, ...)
 * @property {string} toggle the state key that differs; `before` and `after` are its values
 */

/** @type {Figure[]} */
export const FIGURES = [
  {
    id: 1,
    title: 'Nose without and with transmittance',
    caption: 'Lit from the other side and below, the thin parts of the nose (wing, tip) let red light through.',
    camera: [-3.5, 0.8, 7.5, -0.1, 1.0, 2.3],
    settings: { lightAzimuth: 80, lightElevation: -15, lightIntensity: 6, translucency: 0.7 },
    toggle: 'transmittance', before: false, after: true,
  },
  {
    id: 2,
    title: 'Ear without and with transmittance',
    caption: 'With the light behind the head the ear glows red-orange: thin, so light crosses it; the thin rim is the most orange, the skull stays dark.',
    camera: [6.5, 1.7, 4.5, 1.7, 1.3, -0.2],
    // Behind and a little to the ear's side and above: from the other side the skull would stand
    // between the light and the ear. Calibrated against the skin profile's T(d) (docs/FIGURES.md,
    // "Calibrating figure 2"): the light crosses ~8 mm of ear (median, obliquely); translucency
    // 0.945 makes that 0.44 profile mm, where T's green is 30 % of its red: red-orange on screen.
    // At the old 0.7 (2.4 mm) green was 0.7 % of red, which ACES shows as pure red. The finer
    // light depth map keeps the ear's rim smooth.
    settings: { lightAzimuth: 175, lightElevation: 15, lightIntensity: 8, translucency: 0.945, lightDepthSize: 2048 },
    toggle: 'transmittance', before: false, after: true,
  },
  {
    id: 3,
    title: 'Skin without and with the blur',
    caption: 'The blur softens the diffuse light: pores and bumps keep their specular sparkle but lose the hard, dry look.',
    camera: [1.6, 1.4, 7.5, 0.9, 1.2, 1.8],
    settings: { lightAzimuth: 70, lightElevation: 20, lightIntensity: 2.6 },
    toggle: 'sss', before: false, after: true,
  },
  {
    id: 4,
    title: 'Edge of the head without and with depth consideration',
    caption: 'Without it, light bleeds across depth edges (nose over the far cheek, brows, ear): halos; with it, each surface keeps its own light. Width exaggerated to 4 mm.',
    camera: [4, 1.2, 8, 0.2, 1.1, 1.5],
    settings: { lightAzimuth: 45, lightElevation: 10, lightIntensity: 2.6, width: 4 },
    toggle: 'followSurface', before: 'off', after: 'drop',
  },
  {
    id: 5,
    title: 'The full model without and with subsurface scattering',
    caption: 'Diffusion and transmittance together: softer, warmer skin, red ear rims and nostrils.',
    camera: [...DEFAULT_CAMERA],
    settings: { lightAzimuth: 30, lightElevation: 25, lightIntensity: 2.6 },
    toggle: 'sss', before: false, after: true,
  },
];

/** What every figure sets besides its own settings: the whole image on one side of the comparison. */
const FIGURE_BASE = Object.freeze({ split: 0 });

/** The state values a figure sets for its "before" or "after" image. */
export function figureState(id, side = 'after') {
  const figure = FIGURES.find((f) => f.id === id);
  if (!figure) throw new RangeError(`figure must be an integer in 1..5, got ${id}`);
  return { ...FIGURE_BASE, ...figure.settings, camera: [...figure.camera], figure: id, [figure.toggle]: figure[side] };
}

/** The demo's presets beyond the paper, by name (state.js's PRESET_NAMES): title, caption, camera, settings. */
export const PRESETS = {
  earLight: {
    title: 'Two lights: the key light and a point light behind the ear',
    caption: 'The pipeline takes a list of lights, each with its own thickness map: the point light behind the ear makes it glow while the key light keeps lighting the face.',
    // Figure 2's view of the right ear, lit as figure 5; translucency as figure 2's (its calibration).
    camera: [6.5, 1.7, 4.5, 1.7, 1.3, -0.2],
    settings: { lightAzimuth: 30, lightElevation: 25, lightIntensity: 2.6, translucency: 0.945, pointLight: true },
  },
  foliage: {
    title: 'Leaves lit from behind, swaying',
    caption: 'Each leaf is one plane cut out by its texture: a sheet of no thickness lets through the light that enters it, coloured by the leaf. The wind is an onBeforeCompile of the page\'s own; the light\'s depth pass runs it too, so the glow stays on the leaves as they move.',
    // In front of the plant (demo/foliage.js's FOLIAGE_CENTRE), the key light behind it, a little to
    // its right and low, so that the head does not stand between them, nor one leaf before another.
    camera: [3.0, 2.3, 14, 3.0, 2.2, 2.2],
    settings: { lightAzimuth: 165, lightElevation: 8, lightIntensity: 6, foliage: true },
  },
};

/** The state values a preset sets. */
export function presetState(name) {
  const preset = PRESETS[name];
  if (!preset) throw new RangeError(`preset must be one of ${Object.keys(PRESETS).join(', ')}, got ${name}`);
  return { ...FIGURE_BASE, ...preset.settings, camera: [...preset.camera], preset: name };
}
