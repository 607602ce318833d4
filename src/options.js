// The options of the pipeline and of its materials in one place: one schema per constructor, each
// option's default, check and doc together. Everything else derives from it: the defaults
// (PIPELINE_DEFAULTS, MATERIAL_DEFAULTS), the checks at the edge (checkPipelineOptions and the
// setters of SubsurfaceScattering, checkMaterialOptions), the JSDoc typedefs the TypeScript
// declarations are built from, and the README's options tables (both written by
// `npm run options-doc`, scripts/optionsDoc.js; test/node/options.test.js fails when they drift).
import { FloatType, HalfFloatType } from 'three';
import { getProfile } from './profiles/presets.js';
import { MAX_PROFILES } from './profiles/profileSlots.js';
import { MAX_KERNEL_GROUPS, checkKernelGroups } from './3-blur/kernelGroups.js';
import { describe } from './support/rendererSupport.js';
import {
  checkBoolean, checkInteger, checkNumber, checkOddInteger, checkOneOf, checkOptions, checkRgb,
} from './support/parameterChecks.js';

/**
 * How the blur weighs its taps, and what each method needs:
 * - kernel: which computeKernel method builds the separable passes' taps ('marginal' or 'reference');
 * - blur: the mode of SubsurfaceBlurPass ('footprint' or 'taps'); src/3-blur/blurPlan.js dispatches on it;
 * - profiles: how many profiles (materials' `profile`) it blurs in one frame: 'footprint' reads each
 *   pixel's own tables, 'marginal' its own kernel; 'reference' blurs every profile with its built-in
 *   kernel (the profile drives transmittance only).
 * 'footprint' (default): per pixel, footprints of whole pixels weighed exactly (the sampling model,
 * item 8, in docs/ARCHITECTURE.md, "Stage 3: the sampling model"); 'marginal' and 'reference':
 * computeKernel's fixed taps ('reference' is Jimenez 2012's kernel, its profile built in). The dense
 * 2D reference the tests and the bench validate them against is no method: internals'
 * useDenseReference.
 */
export const METHOD_TABLE = Object.freeze({
  footprint: Object.freeze({ kernel: 'marginal', blur: 'footprint', profiles: MAX_PROFILES }),
  marginal: Object.freeze({ kernel: 'marginal', blur: 'taps', profiles: MAX_PROFILES }),
  reference: Object.freeze({ kernel: 'reference', blur: 'taps', profiles: MAX_PROFILES }),
});

/**
 * How the blur weighs its taps (METHOD_TABLE).
 * @typedef {'footprint'|'marginal'|'reference'} Method
 */
/**
 * What a tap on another surface does (FOLLOW_SURFACE_MODES).
 * @typedef {'off'|'drop'|'lerp'} FollowSurfaceMode
 */
/**
 * The preset diffusion profiles by name (src/profiles/presets.js's `profiles`).
 * @typedef {'skin'|'skinBurley'|'marble'|'milk'} ProfileName
 */

/**
 * The accepted `method` values.
 * @type {readonly Method[]}
 */
export const METHODS = Object.freeze(Object.keys(METHOD_TABLE));

/**
 * What a tap on another surface does: dropped and renormalised, lerped to the centre, or nothing.
 * @type {readonly FollowSurfaceMode[]}
 */
export const FOLLOW_SURFACE_MODES = Object.freeze(['off', 'drop', 'lerp']);

/**
 * Tap budgets 'auto' chooses from for the fixed-tap methods ('marginal', 'reference'; the
 * 'footprint' method chooses per pixel instead). The blur is compiled once for the largest and
 * told the frame's count by a uniform, so a change of count never recompiles. The smallest is used
 * whose (samples - 3) / 2 single-pixel footprints per side reach AUTO_REACH of the on-screen radius
 * holding 99 % of the marginal's energy.
 */
export const AUTO_SAMPLES = Object.freeze([5, 9, 13, 17, 25, 33, 45, 63]);

/**
 * Measured (docs/BENCH.md, "samples 'auto' against fixed budgets"): the error against the dense
 * reference stops falling once (samples - 3) / 2 reaches 0.6-0.92 of the radius estimate, which is
 * an upper bound (the nearest bounding-box corner); 0.92 is the conservative end.
 */
export const AUTO_REACH = 0.92;

/** Upper bound on worldUnitInMm and depthThresholdMm: a kilometre per unit; beyond is a mistake. */
export const MAX_SCALE_MM = 1e6;

/** Lower bound on worldUnitInMm: a nanometre per unit; below is a mistake (a scene in metres has 1000). */
export const MIN_SCALE_MM = 1e-6;

/**
 * Largest width or height setSize accepts before it knows the GPU; the first frame checks the
 * GPU's own limits (MAX_TEXTURE_SIZE, MAX_RENDERBUFFER_SIZE), which are smaller on most devices.
 */
export const MAX_TARGET_SIZE = 65536;

/** The most MSAA samples accepted (GPUs offer 4 or 8; three clamps to the renderer's maximum). */
export const MAX_MULTISAMPLING = 16;

/** Taps per direction a pipeline accepts (odd: a centre and pairs). */
export const SAMPLE_RANGE = Object.freeze({ min: 3, max: 63 });

/** The light depth map's resolution, pixels. */
export const LIGHT_DEPTH_SIZES = Object.freeze({ min: 16, max: 8192 });

/** The widest material accepted, mm of material per profile mm (a metre of skin is a mistake). */
export const MAX_WIDTH_MM = 1000;

/**
 * One option: its default, its check (returns the accepted value, throws naming `name` and the
 * range) and its doc, with the TypeScript type the typedef declares.
 * @typedef {object} OptionSpec
 * @property {*} default the value when the option is left out (undefined: none)
 * @property {(value: *, name: string) => *} check
 * @property {string} type the TypeScript type, e.g. "number|'auto'"
 * @property {string} doc one line, units first
 * @property {boolean} [required] the option has no default: leaving it out is an error
 * @property {string} [defaultDoc] the default as the docs write it, where its value is a code
 */

const SCALE_RANGE = Object.freeze({ min: MIN_SCALE_MM, max: MAX_SCALE_MM, unit: 'mm' });

/** A preset's name or a profile object (getProfile throws a TypeError naming `profile` and the presets). */
const checkProfile = (value) => (getProfile(value), value);

/** @param {string} name @param {*} value */
function checkSamples(value, name) {
  return value === 'auto' ? value : checkOddInteger(name, value, SAMPLE_RANGE.min, SAMPLE_RANGE.max);
}

/**
 * new SubsurfaceScattering({ ... }): every option. `scene` and `camera` are required; the rest
 * default as listed. Assignable on the pipeline with the same check, except `light`, `type` and
 * `lightDepthSize` (they size targets: make a new pipeline).
 * @type {Readonly<Record<string, OptionSpec>>}
 */
export const PIPELINE_SCHEMA = Object.freeze({
  scene: {
    default: undefined, required: true, type: "import('three').Scene", doc: 'read every frame (assignable)',
    check(scene, name) {
      if (!scene || scene.isScene !== true) throw new TypeError(`SubsurfaceScattering: ${name} must be a THREE.Scene, got ${describe(scene)}`);
      return scene;
    },
  },
  camera: {
    default: undefined, required: true, type: "import('three').Camera", doc: 'read every frame (assignable: switches the view)',
    check(camera, name) {
      if (!camera || camera.isCamera !== true) throw new TypeError(`SubsurfaceScattering: ${name} must be a THREE.Camera, got ${describe(camera)}`);
      return camera;
    },
  },
  light: {
    default: null, type: "import('three').SpotLight|import('three').DirectionalLight|null",
    doc: 'the light shining through thin parts (transmittance); null: no transmittance',
    check(light, name) {
      if (light !== null && !(light?.isSpotLight || light?.isDirectionalLight)) {
        throw new TypeError(`SubsurfaceScattering: ${name} must be a THREE.SpotLight, THREE.DirectionalLight or null, got ${describe(light)}`);
      }
      return light;
    },
  },
  worldUnitInMm: {
    default: 1000, type: 'number', doc: 'millimetres per world unit (three.js: metres, 1000)',
    check: (value, name) => checkNumber(name, value, SCALE_RANGE),
  },
  profile: {
    default: 'skin', type: "import('./options.js').ProfileName|object",
    doc: "a preset's name ('skin', 'skinBurley', 'marble', 'milk') or a profile object (burleyProfile, dipoleProfile, gaussianSumProfile)",
    check: checkProfile,
  },
  method: {
    default: 'footprint', type: "import('./options.js').Method",
    doc: "how the blur weighs its taps: 'footprint', 'marginal' or 'reference' (METHOD_TABLE)",
    check: (value, name) => checkOneOf(name, value, METHODS),
  },
  samples: {
    default: 'auto', type: "number|'auto'",
    doc: "taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs",
    check: checkSamples,
  },
  kernelGroups: {
    default: 1, type: "number|'auto'",
    doc: `method 'footprint': 1, one separable kernel (exact along the screen axes only; the fast blur); 'auto' or 2..${MAX_KERNEL_GROUPS}: the profile's Gaussians blurred in groups, the same in every direction, at 1.7 (two groups) to 3 (four) times the blur's time on SwiftShader ('auto': one group where one is within the isotropy budget, a far head, else ${MAX_KERNEL_GROUPS})`,
    check: (value, name) => checkKernelGroups(value, name),
  },
  strength: {
    default: undefined, type: 'number[]', doc: 'RGB, 0..1: mix with no scattering (the reference model)',
    check: (value, name) => checkRgb(name, value, { min: 0, max: 1 }),
  },
  falloff: {
    default: undefined, type: 'number[]', doc: "RGB, (0, 10]: method 'reference' only, its kernel's shape",
    check: (value, name) => checkRgb(name, value, { min: 0, max: 10, minExclusive: true }),
  },
  followSurface: {
    default: 'drop', type: "import('./options.js').FollowSurfaceMode",
    doc: "a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'",
    check: (value, name) => checkOneOf(name, value, FOLLOW_SURFACE_MODES),
  },
  depthThresholdMm: {
    default: 6, type: 'number', doc: "mm of depth step taken for another surface (close to the reference's constant at its field of view)",
    check: (value, name) => checkNumber(name, value, { min: 0, minExclusive: true, max: MAX_SCALE_MM, unit: 'mm' }),
  },
  foreshortening: {
    default: true, type: 'boolean', doc: 'narrow the blur on surfaces seen at grazing angles',
    check: (value, name) => checkBoolean(name, value),
  },
  lightDepthSize: {
    default: 1024, type: 'number', doc: 'the light depth map resolution, pixels (16..8192)',
    check: (value, name) => checkInteger(name, value, LIGHT_DEPTH_SIZES.min, LIGHT_DEPTH_SIZES.max, 'pixels'),
  },
  type: {
    default: HalfFloatType, defaultDoc: 'THREE.HalfFloatType', type: "import('three').TextureDataType", doc: 'THREE.HalfFloatType or THREE.FloatType light targets',
    check(value, name) {
      if (value !== HalfFloatType && value !== FloatType) {
        throw new RangeError(`SubsurfaceScattering: ${name} must be THREE.HalfFloatType or THREE.FloatType (light needs HDR targets), got ${describe(value)}`);
      }
      return value;
    },
  },
  multisampling: {
    default: 'auto', type: "number|'auto'",
    doc: "MSAA samples of the scene split, 0..16; 'auto': the composer buffer's `samples`",
    check: (value, name) => (value === 'auto' ? value : checkInteger(name, value, 0, MAX_MULTISAMPLING, "samples (or 'auto')")),
  },
});

/**
 * makeSubsurface(material, { ... }) of a pipeline: every option, with its default.
 * @type {Readonly<Record<string, OptionSpec>>}
 */
export const MATERIAL_SCHEMA = Object.freeze({
  widthMm: {
    default: 1, type: 'number', doc: 'mm of material per profile mm, (0, 1000] (1: the profile at its physical size)',
    check: (value, name) => checkNumber(name, value, { min: 0, minExclusive: true, max: MAX_WIDTH_MM, unit: 'mm' }),
  },
  widthScale: {
    default: 1, type: 'number', doc: 'scales the width, 0..1 (0: no scattering, the light kept)',
    check: (value, name) => checkNumber(name, value, { min: 0, max: 1 }),
  },
  transmittance: {
    default: true, type: 'boolean', doc: "light through thin parts (with the pipeline's light)",
    check: (value, name) => checkBoolean(name, value),
  },
  translucency: {
    default: 0, type: 'number', doc: '0..1 (exclusive): light through regardless of thickness',
    check: (value, name) => checkNumber(name, value, { min: 0, max: 1, maxExclusive: true }),
  },
  shrinkMm: {
    // The reference's 0.005 units at 1 unit = 1/8 m (REFERENCE §5).
    default: 0.6, type: 'number', doc: 'how far the light depth lookup moves inwards, mm (0..1000)',
    check: (value, name) => checkNumber(name, value, { min: 0, max: 1000, unit: 'mm' }),
  },
  profile: {
    default: undefined, type: "import('./options.js').ProfileName|object|null",
    doc: `this material's diffusion profile, as the pipeline's \`profile\` (left out: as before, at first the pipeline's; null: back to the pipeline's); up to ${MAX_PROFILES} per pipeline`,
    // null: the pipeline's again (a rebind keeps what it leaves out, so undefined cannot say it).
    check: (value) => (value === null ? undefined : checkProfile(value)),
  },
});

/** Old option names still accepted, each mapped to its schema name (one minor version; see CHANGELOG.md). */
export const MATERIAL_ALIASES = Object.freeze({ strength: 'widthScale' });

/** @param {Readonly<Record<string, OptionSpec>>} schema */
const defaultsOf = (schema) => Object.freeze(Object.fromEntries(
  Object.entries(schema).filter(([, spec]) => !spec.required).map(([name, spec]) => [name, spec.default]),
));

/** new SubsurfaceScattering({ ... }): every option's default (scene and camera have none). */
export const PIPELINE_DEFAULTS = defaultsOf(PIPELINE_SCHEMA);

/** Every option new SubsurfaceScattering({ ... }) accepts (any other key is refused, naming it). */
export const PIPELINE_OPTIONS = Object.freeze(Object.keys(PIPELINE_SCHEMA));

/** makeSubsurface(material, { ... }) of a pipeline: every option's default. */
export const MATERIAL_DEFAULTS = defaultsOf(MATERIAL_SCHEMA);

/** Every option a pipeline's makeSubsurface(material, { ... }) accepts (`strength`: widthScale's old name). */
export const MATERIAL_OPTIONS = Object.freeze([...Object.keys(MATERIAL_SCHEMA), ...Object.keys(MATERIAL_ALIASES)]);

/**
 * Checks one option against its schema: the accepted value, or a TypeError/RangeError naming it.
 * @param {Readonly<Record<string, OptionSpec>>} schema
 * @param {string} name
 * @param {*} value
 */
export function checkOption(schema, name, value) {
  return schema[name].check(value, name);
}

/**
 * Checks a whole options object at the edge: unknown keys refused (named), required ones present,
 * every given value checked (undefined too, where the option has a default: `light: maybeLight`
 * with maybeLight undefined is refused, not read as no light); returns the options with the
 * defaults filled in.
 * @param {string} what e.g. 'SubsurfaceScattering options'
 * @param {Readonly<Record<string, OptionSpec>>} schema
 * @param {*} options
 * @param {Readonly<Record<string, string>>} [aliases] old name → schema name
 * @returns {Record<string, *>}
 */
export function checkSchemaOptions(what, schema, options, aliases = {}) {
  if (options === undefined || options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`${what} must be an object, got ${describe(options)}`);
  }
  checkOptions(what, options, [...Object.keys(schema), ...Object.keys(aliases)]);
  const checked = {};
  for (const [name, spec] of Object.entries(schema)) {
    const alias = Object.keys(aliases).find((old) => aliases[old] === name && Object.hasOwn(options, old));
    const given = Object.hasOwn(options, name) ? name : alias;
    if (given === undefined) {
      if (spec.required) spec.check(undefined, name); // throws, naming the option and what it must be
      checked[name] = spec.default;
    } else if (options[given] === undefined && spec.default === undefined && !spec.required) {
      checked[name] = undefined; // an option without a default may be given as undefined
    } else {
      // Given, even as undefined: checked (a misspelt variable must not pass for "left out").
      checked[name] = spec.check(options[given], given);
    }
  }
  return checked;
}

/**
 * new SubsurfaceScattering({ ... })'s options, checked, with the defaults filled in.
 * @param {*} options
 */
export function checkPipelineOptions(options) {
  if (options === undefined || options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`SubsurfaceScattering: options must be an object { scene, camera, ... }, got ${describe(options)}`);
  }
  return checkSchemaOptions('SubsurfaceScattering options', PIPELINE_SCHEMA, options);
}

/**
 * A pipeline's makeSubsurface(material, { ... }) options, checked, on top of `previous` (the
 * material's earlier options in that pipeline, or the defaults).
 * @param {*} options
 * @param {Record<string, *>} [previous]
 */
export function checkMaterialOptions(options = {}, previous = MATERIAL_DEFAULTS) {
  const given = checkOptions('makeSubsurface options', options, MATERIAL_OPTIONS);
  const merged = { ...previous };
  for (const [name, value] of Object.entries(given)) {
    if (value === undefined) continue;
    const target = MATERIAL_ALIASES[name] ?? name;
    merged[target] = MATERIAL_SCHEMA[target].check(value, name);
  }
  return merged;
}
