// The options of the pipeline and of its materials in one place: the accepted values, the
// defaults (one copy each) and the method table. The classes validate against these.

/**
 * How the blur weighs its taps, and what each method needs:
 * - kernel: which computeKernel method builds the separable passes' taps ('marginal' or 'reference');
 * - blur: the blur stage's mode ('footprint' or 'taps' of SubsurfaceBlurPass, or 'dense' for
 *   DenseSubsurfacePass instead of the two separable passes).
 * 'footprint' (default): per pixel, footprints of whole pixels weighed exactly (the sampling model,
 * item 8, in docs/ARCHITECTURE.md, "Stage 3: the sampling model"); 'marginal' and 'reference': computeKernel's fixed taps ('reference' is Jimenez 2012's
 * kernel, its profile built in); 'dense': the brute-force 2D reference, for validation only (its
 * cost grows with the square of the on-screen radius).
 */
export const METHOD_TABLE = Object.freeze({
  footprint: Object.freeze({ kernel: 'marginal', blur: 'footprint' }),
  marginal: Object.freeze({ kernel: 'marginal', blur: 'taps' }),
  reference: Object.freeze({ kernel: 'reference', blur: 'taps' }),
  dense: Object.freeze({ kernel: 'marginal', blur: 'dense' }), // the kernel only waits for a switch back
});

/**
 * How the blur weighs its taps (METHOD_TABLE).
 * @typedef {'footprint'|'marginal'|'reference'|'dense'} Method
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
 * 'footprint' method chooses per pixel instead): each is compiled once, so few levels keep shader
 * switches rare. The smallest is used whose (samples - 3) / 2 single-pixel footprints per side
 * reach AUTO_REACH of the on-screen radius holding 99 % of the marginal's energy.
 */
export const AUTO_SAMPLES = Object.freeze([5, 9, 13, 17, 25, 33, 45, 63]);

/**
 * Measured (docs/BENCH.md, "Footprint taps and auto quality"): the error against the dense reference
 * stops falling once (samples - 3) / 2 reaches 0.6-0.92 of the radius estimate, which is an upper
 * bound (the nearest bounding-box corner); 0.92 is the conservative end.
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

/** new SubsurfaceScattering({ ... }): every option's default. */
export const PIPELINE_DEFAULTS = Object.freeze({
  light: /** @type {null} */ (null),
  worldUnitInMm: 1000, // three.js's unit is the metre
  profile: 'skin',
  method: 'footprint',
  samples: 'auto', // per pixel, the fewest taps within AUTO_STEP_ERROR for its scale (src/profiles/footprints.js)
  followSurface: 'drop',
  depthThresholdMm: 6, // close to the reference's follow-surface constant at its field of view
  foreshortening: true,
  lightDepthSize: 1024,
  multisampling: 'auto', // MSAA samples of the scene split: 'auto' follows the composer's buffer
});

/** Every option new SubsurfaceScattering({ ... }) accepts (any other key is refused, naming it). */
export const PIPELINE_OPTIONS = Object.freeze([
  'scene', 'camera', ...Object.keys(PIPELINE_DEFAULTS), 'strength', 'falloff', 'type',
]);

/** The most MSAA samples accepted (GPUs offer 4 or 8; three clamps to the renderer's maximum). */
export const MAX_MULTISAMPLING = 16;

/**
 * makeSubsurface(material, { ... }): every option's default. widthMm 1 is the profile at its
 * physical size; shrinkMm 0.6 is the reference's 0.005 units at 1 unit = 1/8 m (REFERENCE §5).
 */
export const MATERIAL_DEFAULTS = Object.freeze({
  widthMm: 1,
  widthScale: 1,
  transmittance: true,
  translucency: 0,
  shrinkMm: 0.6,
});

/** Every option a pipeline's makeSubsurface(material, { ... }) accepts (`strength`: widthScale's old name). */
export const MATERIAL_OPTIONS = Object.freeze([...Object.keys(MATERIAL_DEFAULTS), 'strength']);
