// The settings of the pipeline and of its materials in one place: one schema per kind, each
// setting's default, check, doc and the entries that have it together. Both renderers' entries
// derive everything from it: the defaults (PIPELINE_DEFAULTS, NODE_DEFAULTS, MATERIAL_DEFAULTS),
// the checks at the edge (checkPipelineOptions, checkNodeOptions, checkMaterialOptions), the
// properties of SubsurfaceScattering and SubsurfaceScatteringNode (src/support/settings.js), the
// JSDoc typedefs below that the TypeScript declarations are built from, and the README's options
// table (`npm run options-doc`, scripts/optionsDoc.js; test/node/options.test.js fails on a drift).
import { FloatType, HalfFloatType } from 'three';
import { getProfile } from './profiles/presets.js';
import { MAX_PROFILES } from './profiles/profileSlots.js';
import { MAX_KERNEL_GROUPS, checkKernelGroups } from './3-blur/kernelGroups.js';
import { describe } from './support/rendererSupport.js';
import { DEBUG_VIEWS } from './4-compose/debugViews.js';
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
 * A light transmittance is drawn from.
 * @typedef {import('three').SpotLight|import('three').DirectionalLight|import('three').PointLight} TransmittingLight
 */

/**
 * A diffusion profile as the pipeline reads it back: a preset of `profiles`, or one made by
 * burleyProfile, dipoleProfile, gaussianSumProfile or radialProfile (src/profiles/). Distances in
 * mm, one value per RGB channel.
 * @typedef {object} DiffusionProfile
 * @property {string} name
 * @property {(rMm: number) => number[]} R the radial profile R(r)
 * @property {(xMm: number) => number[]} marginal R integrated along a line
 * @property {(aMm: number, bMm: number) => number[]} marginalIntegral the marginal's energy in [a, b]
 * @property {(sMm: number) => number[]} transmittance T(s) through s mm of material
 * @property {(fraction: number) => number[]} radiusMm the radius holding `fraction` of the energy
 */

export { DEBUG_VIEWS };

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

/** The most lights transmittance is drawn from at once (`light` as a list), each with its own map. */
export const MAX_LIGHTS = 4;

/** A SpotLight, DirectionalLight or PointLight (or null where `orNull`), else a TypeError naming `name`. */
function checkOneLight(light, name, orNull = true) {
  if ((light !== null || !orNull) && !(light?.isSpotLight || light?.isDirectionalLight || light?.isPointLight)) {
    throw new TypeError(`${name} must be a THREE.SpotLight, THREE.DirectionalLight${orNull ? `, THREE.PointLight, a list of them, '${CAST_SHADOW}' or null` : ' or THREE.PointLight'}, got ${describe(light)}`);
  }
  return light;
}

/** `light`'s value for every light of the scene that casts shadows (up to MAX_LIGHTS), found each frame. */
export const CAST_SHADOW = 'castShadow';

/**
 * The lights of a `light` setting, as a list: none for null, those of `scene` that cast shadows
 * for CAST_SHADOW (visible, in scene order, up to MAX_LIGHTS; none without a scene).
 * @param {*} light
 * @param {import('three').Scene} [scene]
 */
export function lightsOf(light, scene) {
  if (light !== CAST_SHADOW) return light === null ? [] : Array.isArray(light) ? light : [light];
  const casters = [];
  scene?.traverseVisible((object) => {
    if (object.castShadow === true && (object.isSpotLight || object.isDirectionalLight || object.isPointLight)) casters.push(object);
  });
  return casters;
}

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
 * @property {'assignable'|'readonly'|'constructor'} [access] a property checked on assignment
 *   (default), a property read only (it sizes or binds what the constructor built: make another
 *   pipeline), or an option of the constructor only
 * @property {boolean} [webgpu] whether the WebGPU node has it too (default true)
 * @property {string} [readType] the type it reads back as, where it differs from what it takes:
 *   the classes declare that property themselves (TypeScript's accessors), the settings' typedefs
 *   leave it out
 */

const SCALE_RANGE = Object.freeze({ min: MIN_SCALE_MM, max: MAX_SCALE_MM, unit: 'mm' });

/** A boolean setting: true or false, nothing else (a TypeError naming it). */
const isBoolean = (value, name) => checkBoolean(name, value);

/** A setting that takes a number above 0, up to `max`, in `unit` (an error naming it and the range otherwise). */
const positive = (unit, max = Infinity) => (value, name) => checkNumber(name, value, { min: 0, minExclusive: true, max, unit });

/** A setting that takes one of `list` (a RangeError naming it and the list otherwise). */
const oneOf = (list) => (value, name) => checkOneOf(name, value, list);

/** A preset's name or a profile object (getProfile throws a TypeError naming `profile` and the presets). */
const checkProfile = (value) => getProfile(value);

/** @param {string} name @param {*} value */
function checkSamples(value, name) {
  return value === 'auto' ? value : checkOddInteger(name, value, SAMPLE_RANGE.min, SAMPLE_RANGE.max);
}

/**
 * Every setting of the pipeline (new SubsurfaceScattering({ ... }) and its properties) and of the
 * WebGPU node (subsurfaceScattering(scenePass, { ... }), where `webgpu` is not false). `scene`
 * and `camera` are required on the pipeline (the node reads them from its scene pass); the rest
 * default as listed.
 * @type {Readonly<Record<string, OptionSpec>>}
 */
export const PIPELINE_SCHEMA = Object.freeze({
  scene: {
    default: undefined, required: true, webgpu: false, type: "import('three').Scene", doc: 'the scene drawn, read every frame',
    check(scene, name) {
      if (!scene || scene.isScene !== true) throw new TypeError(`${name} must be a THREE.Scene, got ${describe(scene)}`);
      return scene;
    },
  },
  camera: {
    default: undefined, required: true, webgpu: false, type: "import('three').Camera", doc: 'the camera drawn with, read every frame',
    check(camera, name) {
      if (!camera || camera.isCamera !== true) throw new TypeError(`${name} must be a THREE.Camera, got ${describe(camera)}`);
      return camera;
    },
  },
  light: {
    default: null, type: "import('./options.js').TransmittingLight|import('./options.js').TransmittingLight[]|'castShadow'|null",
    doc: `the spot, directional or point light shining through thin parts, a list of up to ${MAX_LIGHTS} (their light adds up), or 'castShadow' (the scene's casters, found each frame); null: none`,
    check(light, name) {
      if (light === CAST_SHADOW) return light;
      if (!Array.isArray(light)) return checkOneLight(light, name);
      if (light.length < 1 || light.length > MAX_LIGHTS) throw new RangeError(`${name} must list 1 to ${MAX_LIGHTS} lights, got ${light.length}`);
      light.forEach((each, i) => checkOneLight(each, `${name}[${i}]`, false));
      if (new Set(light).size < light.length) throw new RangeError(`${name} lists a light twice`);
      return Object.freeze([...light]); // read back as given, not changed behind the pipeline's back
    },
  },
  worldUnitInMm: {
    default: 1000, type: 'number', doc: 'millimetres per world unit (three.js: metres, 1000)',
    check: (value, name) => checkNumber(name, value, SCALE_RANGE),
  },
  profile: {
    default: 'skin', type: "import('./options.js').ProfileName|object", readType: "import('./options.js').DiffusionProfile",
    doc: "a preset's name ('skin', 'skinBurley', 'marble', 'milk') or a profile object (burleyProfile, dipoleProfile, gaussianSumProfile)",
    check: checkProfile,
  },
  method: {
    default: 'footprint', type: "import('./options.js').Method",
    doc: "how the blur weighs its taps: 'footprint' (each pixel's footprint, exactly), 'marginal' or 'reference' (fixed taps; Jimenez 2012's kernel); a switch to or from 'footprint' recompiles",
    check: oneOf(METHODS),
  },
  samples: {
    default: 'auto', type: "number|'auto'",
    doc: "taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs",
    check: checkSamples,
  },
  kernelGroups: {
    default: 1, type: "number|'auto'",
    doc: `method 'footprint': 1, one separable kernel (the fast blur); 'auto' or 2..${MAX_KERNEL_GROUPS}: the profile's Gaussians in groups, the same in every direction, slower`,
    check: (value, name) => checkKernelGroups(value, name),
  },
  strength: {
    default: undefined, type: "number[]|import('three').Color", doc: '[r, g, b] or a THREE.Color, 0..1: mix with no scattering (the reference model)',
    check: (value, name) => checkRgb(name, value, { min: 0, max: 1 }),
  },
  falloff: {
    default: undefined, webgpu: false, type: 'number[]', doc: "RGB, (0, 10]: method 'reference' only, its kernel's shape",
    check: (value, name) => checkRgb(name, value, { min: 0, max: 10, minExclusive: true }),
  },
  followSurface: {
    default: 'drop', type: "import('./options.js').FollowSurfaceMode",
    doc: "a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'",
    check: oneOf(FOLLOW_SURFACE_MODES),
  },
  depthThresholdMm: {
    default: 6, type: 'number', doc: 'mm of depth step taken for another surface',
    check: positive('mm', MAX_SCALE_MM),
  },
  foreshortening: {
    default: true, type: 'boolean', doc: 'narrow the blur on surfaces seen at grazing angles',
    check: isBoolean,
  },
  lightDepthSize: {
    default: 1024, type: 'number', doc: 'the light depth map resolution, pixels (16..8192)',
    check: (value, name) => checkInteger(name, value, LIGHT_DEPTH_SIZES.min, LIGHT_DEPTH_SIZES.max, 'pixels'),
  },
  type: {
    default: HalfFloatType, access: 'constructor', webgpu: false, defaultDoc: 'THREE.HalfFloatType', type: "import('three').TextureDataType", doc: 'THREE.HalfFloatType or THREE.FloatType light targets; constructor only',
    check(value, name) {
      if (value !== HalfFloatType && value !== FloatType) {
        throw new RangeError(`${name} must be THREE.HalfFloatType or THREE.FloatType (light needs HDR targets), got ${describe(value)}`);
      }
      return value;
    },
  },
  multisampling: {
    default: 'auto', webgpu: false, type: "number|'auto'",
    doc: "MSAA samples of the scene split, 0..16; 'auto': the composer buffer's `samples` (the node: its scene pass's)",
    check: (value, name) => (value === 'auto' ? value : checkInteger(name, value, 0, MAX_MULTISAMPLING, "samples (or 'auto')")),
  },
  scattering: {
    default: true, type: 'boolean', doc: 'false: no blur, the unblurred diffuse light composed (transmittance stays)',
    check: isBoolean,
  },
  transmittance: {
    default: true, type: 'boolean', doc: 'light through thin parts for every material (with `light`)',
    check: isBoolean,
  },
  debugView: {
    default: 'final', type: "import('./4-compose/debugViews.js').DebugView", check: oneOf(DEBUG_VIEWS),
    doc: "the final image or one ingredient: 'final', 'diffuse', 'specular', 'depth', 'mask', and with `light` 'thickness', 'transmittance'",
  },
  debugDepthRange: {
    default: 10, type: 'number', doc: "world units of view depth the 'depth' view maps from white (near) to black",
    check: positive('world units'),
  },
  debugThicknessRangeMm: {
    default: 10, type: 'number', doc: "profile mm of thickness the 'thickness' view maps from black to white",
    check: positive('mm'),
  },
  split: {
    default: 0, webgpu: false, type: 'number', doc: 'the fraction of the width, from the left, shown without scattering, 0..1',
    check: (value, name) => checkNumber(name, value, { min: 0, max: 1 }),
  },
});

/**
 * makeSubsurface(material, { ... }) of a pipeline: every option, with its default.
 * @type {Readonly<Record<string, OptionSpec>>}
 */
export const MATERIAL_SCHEMA = Object.freeze({
  widthMm: {
    default: 1, type: 'number', doc: 'mm of material per profile mm, (0, 1000] (1: the profile at its physical size)',
    check: positive('mm', MAX_WIDTH_MM),
  },
  widthScale: {
    default: 1, type: 'number', doc: 'scales the width, 0..1 (0: no scattering, the light kept)',
    check: (value, name) => checkNumber(name, value, { min: 0, max: 1 }),
  },
  transmittance: {
    default: true, type: 'boolean', doc: "light through thin parts (with the pipeline's light)",
    check: isBoolean,
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
    doc: `this material's diffusion profile, as the pipeline's \`profile\` (null: the pipeline's); up to ${MAX_PROFILES} per pipeline`,
    // null: the pipeline's again (a rebind keeps what it leaves out, so undefined cannot say it).
    check: (value) => (value === null ? undefined : (checkProfile(value), value)), // kept as given: a material's options read back as written
  },
});

/** The schema's entries the WebGPU node has (the node reads its scene and camera from its scene pass). */
export const NODE_SCHEMA = Object.freeze(Object.fromEntries(Object.entries(PIPELINE_SCHEMA).filter(([, spec]) => spec.webgpu !== false)));

/** @param {Readonly<Record<string, OptionSpec>>} schema */
const defaultsOf = (schema) => Object.freeze(Object.fromEntries(
  Object.entries(schema).filter(([, spec]) => !spec.required).map(([name, spec]) => [name, spec.default]),
));

/** new SubsurfaceScattering({ ... }): every option's default (scene and camera have none). */
export const PIPELINE_DEFAULTS = defaultsOf(PIPELINE_SCHEMA);

/** subsurfaceScattering(scenePass, { ... }) (the WebGPU node): every option's default, the pipeline's. */
export const NODE_DEFAULTS = defaultsOf(NODE_SCHEMA);

/** Every option new SubsurfaceScattering({ ... }) accepts (any other key is refused, naming it). */
export const PIPELINE_OPTIONS = Object.freeze(Object.keys(PIPELINE_SCHEMA));

/** makeSubsurface(material, { ... }) of a pipeline: every option's default. */
export const MATERIAL_DEFAULTS = defaultsOf(MATERIAL_SCHEMA);

/** Every option a pipeline's makeSubsurface(material, { ... }) accepts. */
export const MATERIAL_OPTIONS = Object.freeze(Object.keys(MATERIAL_SCHEMA));

/**
 * The settings that are properties of an entry's object: every entry of `schema` but the
 * constructor's own, each with whether it is assignable.
 * @param {Readonly<Record<string, OptionSpec>>} schema
 * @returns {ReadonlyArray<{ name: string, assignable: boolean }>}
 */
export const propertiesOf = (schema) => Object.freeze(Object.entries(schema)
  .filter(([, spec]) => spec.access !== 'constructor')
  .map(([name, spec]) => Object.freeze({ name, assignable: spec.access !== 'readonly' })));

/** The debug views that show what the light depth map gives: black without a `light` (said in `problems`). */
export const LIGHT_VIEWS = Object.freeze(['thickness', 'transmittance']);

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
 * @returns {Record<string, *>}
 */
export function checkSchemaOptions(what, schema, options) {
  if (options === undefined || options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new TypeError(`${what} must be an object, got ${describe(options)}`);
  }
  checkOptions(what, options, Object.keys(schema));
  const checked = {};
  for (const [name, spec] of Object.entries(schema)) {
    const given = Object.hasOwn(options, name) ? name : undefined;
    if (given === undefined) {
      if (spec.required) spec.check(undefined, name); // throws, naming the option and what it must be
      checked[name] = spec.default === undefined ? undefined : spec.check(spec.default, name); // as its check keeps it (a profile's name: the profile)
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
 * subsurfaceScattering(scenePass, { ... })'s options (the WebGPU node), checked, with the defaults.
 * @param {*} [options]
 */
export function checkNodeOptions(options = {}) {
  return checkSchemaOptions('subsurfaceScattering options', NODE_SCHEMA, options);
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
    merged[name] = MATERIAL_SCHEMA[name].check(value, name);
  }
  return merged;
}

// <options-typedef> (generated by scripts/optionsDoc.js from src/options.js)
/**
 * new SubsurfaceScattering({ ... }): the defaults are PIPELINE_DEFAULTS.
 * @typedef {object} SubsurfaceScatteringOptions
 * @property {import('three').Scene} scene the scene drawn, read every frame
 * @property {import('three').Camera} camera the camera drawn with, read every frame
 * @property {TransmittingLight|TransmittingLight[]|'castShadow'|null} [light=null] the spot, directional or point light shining through thin parts, a list of up to 4 (their light adds up), or 'castShadow' (the scene's casters, found each frame); null: none
 * @property {number} [worldUnitInMm=1000] millimetres per world unit (three.js: metres, 1000)
 * @property {ProfileName|object} [profile='skin'] a preset's name ('skin', 'skinBurley', 'marble', 'milk') or a profile object (burleyProfile, dipoleProfile, gaussianSumProfile)
 * @property {Method} [method='footprint'] how the blur weighs its taps: 'footprint' (each pixel's footprint, exactly), 'marginal' or 'reference' (fixed taps; Jimenez 2012's kernel); a switch to or from 'footprint' recompiles
 * @property {number|'auto'} [samples='auto'] taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs
 * @property {number|'auto'} [kernelGroups=1] method 'footprint': 1, one separable kernel (the fast blur); 'auto' or 2..4: the profile's Gaussians in groups, the same in every direction, slower
 * @property {number[]|import('three').Color} [strength] [r, g, b] or a THREE.Color, 0..1: mix with no scattering (the reference model)
 * @property {number[]} [falloff] RGB, (0, 10]: method 'reference' only, its kernel's shape
 * @property {FollowSurfaceMode} [followSurface='drop'] a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'
 * @property {number} [depthThresholdMm=6] mm of depth step taken for another surface
 * @property {boolean} [foreshortening=true] narrow the blur on surfaces seen at grazing angles
 * @property {number} [lightDepthSize=1024] the light depth map resolution, pixels (16..8192)
 * @property {import('three').TextureDataType} [type=THREE.HalfFloatType] THREE.HalfFloatType or THREE.FloatType light targets; constructor only
 * @property {number|'auto'} [multisampling='auto'] MSAA samples of the scene split, 0..16; 'auto': the composer buffer's `samples` (the node: its scene pass's)
 * @property {boolean} [scattering=true] false: no blur, the unblurred diffuse light composed (transmittance stays)
 * @property {boolean} [transmittance=true] light through thin parts for every material (with `light`)
 * @property {import('./4-compose/debugViews.js').DebugView} [debugView='final'] the final image or one ingredient: 'final', 'diffuse', 'specular', 'depth', 'mask', and with `light` 'thickness', 'transmittance'
 * @property {number} [debugDepthRange=10] world units of view depth the 'depth' view maps from white (near) to black
 * @property {number} [debugThicknessRangeMm=10] profile mm of thickness the 'thickness' view maps from black to white
 * @property {number} [split=0] the fraction of the width, from the left, shown without scattering, 0..1
 */

/**
 * subsurfaceScattering(scenePass, { ... }) (the WebGPU node): the defaults are NODE_DEFAULTS.
 * @typedef {object} SubsurfaceScatteringNodeOptions
 * @property {TransmittingLight|TransmittingLight[]|'castShadow'|null} [light=null] the spot, directional or point light shining through thin parts, a list of up to 4 (their light adds up), or 'castShadow' (the scene's casters, found each frame); null: none
 * @property {number} [worldUnitInMm=1000] millimetres per world unit (three.js: metres, 1000)
 * @property {ProfileName|object} [profile='skin'] a preset's name ('skin', 'skinBurley', 'marble', 'milk') or a profile object (burleyProfile, dipoleProfile, gaussianSumProfile)
 * @property {Method} [method='footprint'] how the blur weighs its taps: 'footprint' (each pixel's footprint, exactly), 'marginal' or 'reference' (fixed taps; Jimenez 2012's kernel); a switch to or from 'footprint' recompiles
 * @property {number|'auto'} [samples='auto'] taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs
 * @property {number|'auto'} [kernelGroups=1] method 'footprint': 1, one separable kernel (the fast blur); 'auto' or 2..4: the profile's Gaussians in groups, the same in every direction, slower
 * @property {number[]|import('three').Color} [strength] [r, g, b] or a THREE.Color, 0..1: mix with no scattering (the reference model)
 * @property {FollowSurfaceMode} [followSurface='drop'] a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'
 * @property {number} [depthThresholdMm=6] mm of depth step taken for another surface
 * @property {boolean} [foreshortening=true] narrow the blur on surfaces seen at grazing angles
 * @property {number} [lightDepthSize=1024] the light depth map resolution, pixels (16..8192)
 * @property {boolean} [scattering=true] false: no blur, the unblurred diffuse light composed (transmittance stays)
 * @property {boolean} [transmittance=true] light through thin parts for every material (with `light`)
 * @property {import('./4-compose/debugViews.js').DebugView} [debugView='final'] the final image or one ingredient: 'final', 'diffuse', 'specular', 'depth', 'mask', and with `light` 'thickness', 'transmittance'
 * @property {number} [debugDepthRange=10] world units of view depth the 'depth' view maps from white (near) to black
 * @property {number} [debugThicknessRangeMm=10] profile mm of thickness the 'thickness' view maps from black to white
 */

/**
 * SubsurfaceScattering's settings, as properties (assigning one checks it as the constructor does).
 * @typedef {object} PipelineSettings
 * @property {import('three').Scene} scene the scene drawn, read every frame
 * @property {import('three').Camera} camera the camera drawn with, read every frame
 * @property {TransmittingLight|TransmittingLight[]|'castShadow'|null} light the spot, directional or point light shining through thin parts, a list of up to 4 (their light adds up), or 'castShadow' (the scene's casters, found each frame); null: none
 * @property {number} worldUnitInMm millimetres per world unit (three.js: metres, 1000)
 * @property {Method} method how the blur weighs its taps: 'footprint' (each pixel's footprint, exactly), 'marginal' or 'reference' (fixed taps; Jimenez 2012's kernel); a switch to or from 'footprint' recompiles
 * @property {number|'auto'} samples taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs
 * @property {number|'auto'} kernelGroups method 'footprint': 1, one separable kernel (the fast blur); 'auto' or 2..4: the profile's Gaussians in groups, the same in every direction, slower
 * @property {number[]|import('three').Color|undefined} strength [r, g, b] or a THREE.Color, 0..1: mix with no scattering (the reference model)
 * @property {number[]|undefined} falloff RGB, (0, 10]: method 'reference' only, its kernel's shape
 * @property {FollowSurfaceMode} followSurface a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'
 * @property {number} depthThresholdMm mm of depth step taken for another surface
 * @property {boolean} foreshortening narrow the blur on surfaces seen at grazing angles
 * @property {number} lightDepthSize the light depth map resolution, pixels (16..8192)
 * @property {number|'auto'} multisampling MSAA samples of the scene split, 0..16; 'auto': the composer buffer's `samples` (the node: its scene pass's)
 * @property {boolean} scattering false: no blur, the unblurred diffuse light composed (transmittance stays)
 * @property {boolean} transmittance light through thin parts for every material (with `light`)
 * @property {import('./4-compose/debugViews.js').DebugView} debugView the final image or one ingredient: 'final', 'diffuse', 'specular', 'depth', 'mask', and with `light` 'thickness', 'transmittance'
 * @property {number} debugDepthRange world units of view depth the 'depth' view maps from white (near) to black
 * @property {number} debugThicknessRangeMm profile mm of thickness the 'thickness' view maps from black to white
 * @property {number} split the fraction of the width, from the left, shown without scattering, 0..1
 */

/**
 * SubsurfaceScatteringNode's settings, as properties (assigning one checks it as the constructor does).
 * @typedef {object} NodeSettings
 * @property {TransmittingLight|TransmittingLight[]|'castShadow'|null} light the spot, directional or point light shining through thin parts, a list of up to 4 (their light adds up), or 'castShadow' (the scene's casters, found each frame); null: none
 * @property {number} worldUnitInMm millimetres per world unit (three.js: metres, 1000)
 * @property {Method} method how the blur weighs its taps: 'footprint' (each pixel's footprint, exactly), 'marginal' or 'reference' (fixed taps; Jimenez 2012's kernel); a switch to or from 'footprint' recompiles
 * @property {number|'auto'} samples taps per direction, odd, 3..63 (a budget for 'footprint'); 'auto': as few as the on-screen scale needs
 * @property {number|'auto'} kernelGroups method 'footprint': 1, one separable kernel (the fast blur); 'auto' or 2..4: the profile's Gaussians in groups, the same in every direction, slower
 * @property {number[]|import('three').Color|undefined} strength [r, g, b] or a THREE.Color, 0..1: mix with no scattering (the reference model)
 * @property {FollowSurfaceMode} followSurface a tap on another surface: 'drop' (renormalise), 'lerp' (to the centre) or 'off'
 * @property {number} depthThresholdMm mm of depth step taken for another surface
 * @property {boolean} foreshortening narrow the blur on surfaces seen at grazing angles
 * @property {number} lightDepthSize the light depth map resolution, pixels (16..8192)
 * @property {boolean} scattering false: no blur, the unblurred diffuse light composed (transmittance stays)
 * @property {boolean} transmittance light through thin parts for every material (with `light`)
 * @property {import('./4-compose/debugViews.js').DebugView} debugView the final image or one ingredient: 'final', 'diffuse', 'specular', 'depth', 'mask', and with `light` 'thickness', 'transmittance'
 * @property {number} debugDepthRange world units of view depth the 'depth' view maps from white (near) to black
 * @property {number} debugThicknessRangeMm profile mm of thickness the 'thickness' view maps from black to white
 */

/**
 * makeSubsurface(material, { ... }) of a pipeline: the defaults are MATERIAL_DEFAULTS.
 * @typedef {object} SubsurfaceMaterialOptions
 * @property {number} [widthMm=1] mm of material per profile mm, (0, 1000] (1: the profile at its physical size)
 * @property {number} [widthScale=1] scales the width, 0..1 (0: no scattering, the light kept)
 * @property {boolean} [transmittance=true] light through thin parts (with the pipeline's light)
 * @property {number} [translucency=0] 0..1 (exclusive): light through regardless of thickness
 * @property {number} [shrinkMm=0.6] how far the light depth lookup moves inwards, mm (0..1000)
 * @property {ProfileName|object|null} [profile] this material's diffusion profile, as the pipeline's `profile` (null: the pipeline's); up to 8 per pipeline
 */
// </options-typedef>
