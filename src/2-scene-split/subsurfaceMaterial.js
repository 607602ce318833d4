// Stage 2: the material hook. Patches a MeshStandardMaterial or MeshPhysicalMaterial through
// onBeforeCompile so that, drawn into the multi-target (src/2-scene-split/subsurfaceTarget.js) in
// the SPLIT phase, it writes its diffuse light (direct + indirect, plus transmittance) to the
// diffuse attachment, linear view depth and scattering width to the surface attachment, and keeps
// specular + emissive in the colour attachment. Drawn by no pipeline (a plain RenderPass, a
// minimap, a cube camera) it renders exactly as three's own material: no transmittance either,
// which belongs to a pipeline's light (with the latest pipeline's, 3.38 % of a back-lit scene's
// pixels differed from three's).
//
// One material can serve several pipelines: each binds its own settings (width, light, profile,
// debug output) to it, and every draw takes the settings of the pipeline drawing (a pipeline
// without settings of its own, such as a SubsurfaceScenePass used alone, takes the latest
// binding's). One program serves them all: transmittance is a uniform switch, not a define.
// Disposing one pipeline unbinds it; the last unbind restores the material.
//
// Our GLSL goes in at fixed points of three's MeshStandard/MeshPhysical fragment shader (`inject`,
// which fails loudly when three's shader no longer has the point); the declarations are assembled
// with the library's include resolver like every other shader. The user's own hooks
// (onBeforeCompile, customProgramCacheKey, onBeforeRender), set before or after, run first
// (src/support/userHooks.js); where their onBeforeCompile leaves out a point ours goes in at, the
// material is drawn as three draws it and `uncomposed` says why.
//
// A copy of a subsurface material (material.clone(), .copy(), drei's <Clone>) carries its
// userData, not our hooks: the mark COPY_MARK names the material it was copied from, and the frame
// that meets the copy binds it as its source is bound (followCopy), or says once that it cannot.
import { LessEqualDepth } from 'three';
import parsGlsl from '../../shaders/2-scene-split/material/pars.glsl?raw';
import outputsGlsl from '../../shaders/2-scene-split/material/outputs.glsl?raw';
import unsplitVertexGlsl from '../../shaders/2-scene-split/material/unsplit.vert.glsl?raw';
import unsplitFragmentGlsl from '../../shaders/2-scene-split/material/unsplit.frag.glsl?raw';
import hiddenGlsl from '../../shaders/2-scene-split/material/hidden.vert.glsl?raw';
import transmittedLightGlsl from '../../shaders/2-scene-split/material/transmittedLight.glsl?raw';
import splitGlsl from '../../shaders/2-scene-split/material/split.glsl?raw';
import clearcoatGlsl from '../../shaders/2-scene-split/material/clearcoat.glsl?raw';
import outputGlsl from '../../shaders/2-scene-split/material/output.glsl?raw';
import finiteGlsl from '../../shaders/common/finite.glsl?raw';
import carriedDepthGlsl from '../../shaders/common/carriedDepth.glsl?raw';
import { assembleGlsl, enumDefines } from '../support/glsl.js';
import { checkOneOf, checkOptions } from '../support/parameterChecks.js';
import { describe, refuseTransmission } from '../support/rendererSupport.js';
import { checkThreeRevision, supportedThreeNote, threeRelease } from '../support/threeVersion.js';
import { composeHooks } from '../support/userHooks.js';
import { MATERIAL_DEFAULTS, MATERIAL_SCHEMA, PIPELINE_SCHEMA, checkOption } from '../options.js';
import { ATTACHMENT_DEFINES, DRAW_PHASES, currentDraw, diffuseCarriesDepth } from './subsurfaceTarget.js';
import { MATERIAL_OUTPUTS } from '../4-compose/debugViews.js';
import { LightDepthTarget } from '../1-light-depth/LightDepthTarget.js';
import {
  LIGHT_TYPES, TRANSMITTANCE_CHUNKS, TRANSMITTED_LIGHT_DEFINES, lightUniformSlots, transmittanceSettings,
  transmittanceUniformSlots, writeTransmittedLight,
} from './transmittance.js';
import { MAX_LIGHTS } from '../options.js';

/** What the diffuse attachment receives (src/4-compose/debugViews.js). */
export { MATERIAL_OUTPUTS };

/** What makeSubsurface(material, { ... }) accepts. */
const STANDALONE_OPTIONS = Object.freeze(['widthMm', 'widthScale', 'worldUnitInMm', 'transmittance']);

/** The key of bindings made by makeSubsurface called on its own, outside a pipeline. */
const STANDALONE = Object.freeze({ name: 'makeSubsurface' });

/** The declarations before main(), with the finiteness check and transmittance. */
const declarations = assembleGlsl('makeSubsurface', parsGlsl, {
  '2-scene-split/material/outputs.glsl': outputsGlsl, 'common/finite.glsl': finiteGlsl, 'common/carriedDepth.glsl': carriedDepthGlsl, ...TRANSMITTANCE_CHUNKS,
});
const defines = Object.freeze({
  ...ATTACHMENT_DEFINES, ...enumDefines('SSS_OUTPUT', MATERIAL_OUTPUTS, 'diffuse'), ...enumDefines('SSS_LIGHT_TYPE', LIGHT_TYPES, 'spot'),
  ...TRANSMITTED_LIGHT_DEFINES, SSS_MAX_LIGHTS: MAX_LIGHTS,
});

/**
 * The per-light uniform arrays the material reads (pars.glsl), by the name of the one-light uniform
 * the model's writer fills (writeTransmittedLight): each light is written through a slot whose
 * uniforms are views of its index in these arrays.
 */
const LIGHT_ARRAYS = Object.freeze({
  sssTransmits: 'sssLightTransmits', sssLightType: 'sssLightTypes', sssLightColor: 'sssLightColors',
  sssLightPositionView: 'sssLightPositionsView', sssLightDirectionView: 'sssLightDirectionsView',
  sssLightCutoffDistance: 'sssLightCutoffDistances', sssLightDecay: 'sssLightDecays', sssSpotConeCos: 'sssSpotConeCosines',
  sssSpotPenumbraCos: 'sssSpotPenumbraCosines', sssLightDepthMap: 'sssLightDepthMaps', sssViewToLightView: 'sssViewToLightViews',
  sssLightProjection: 'sssLightProjections', sssLightCube: 'sssLightCubes',
});

/** The arrays of LIGHT_ARRAYS, each element a fresh slot's first value. */
function lightArrays() {
  const slots = Array.from({ length: MAX_LIGHTS }, () => ({ sssTransmits: { value: false }, sssLightType: { value: 0 }, ...lightUniformSlots(), ...transmittanceUniformSlots() }));
  return Object.fromEntries(Object.entries(LIGHT_ARRAYS).map(([one, many]) => [many, { value: slots.map((slot) => slot[one].value) }]));
}

/** Light `i`'s slot: the shared uniforms as they are, the per-light ones as views of element `i`. */
function lightSlot(uniforms, i) {
  const slot = { ...uniforms };
  for (const [one, many] of Object.entries(LIGHT_ARRAYS)) {
    const array = uniforms[many].value;
    slot[one] = { get value() { return array[i]; }, set value(v) { array[i] = v; } };
  }
  return slot;
}

/** material → its patch: { uniforms, bindings: Map<owner, binding>, restore() } */
const patches = new WeakMap();

/** The latest binding of a patch (Map order: the last one set), without allocating. */
function latest(bindings) {
  let last;
  for (const binding of bindings.values()) last = binding;
  return last;
}

/** Replaces `needle` in `source`, failing loudly (naming three's release and ours) if three's shader no longer has it. */
function inject(source, needle, replacement) {
  if (!source.includes(needle)) {
    throw new Error(`makeSubsurface: "${needle}" not found in the material's shader: ${threeRelease()} is not supported ${supportedThreeNote()}`);
  }
  return source.replace(needle, replacement);
}

/** Where our GLSL goes in: the shader stage, the point of three's shader, and what takes its place. */
const INJECTIONS = Object.freeze([
  ['fragmentShader', 'void main() {', () => `${declarations}\nvoid main() {`],
  ['fragmentShader', '#include <lights_fragment_end>', () => `#include <lights_fragment_end>\n${transmittedLightGlsl}`],
  ['fragmentShader', 'vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;', () => splitGlsl],
  ['fragmentShader', '#include <opaque_fragment>', () => `${clearcoatGlsl}\n#include <opaque_fragment>`],
  ['fragmentShader', '#include <dithering_fragment>', () => `#include <dithering_fragment>\n${outputGlsl}`],
  ['vertexShader', 'void main() {', () => `uniform bool sssHidden; // true in the scene split's first call\nvoid main() {\n${hiddenGlsl}`],
]);

/** The split, put into three's MeshStandard/MeshPhysical shader at INJECTIONS. */
function splitShader(shader) {
  for (const [stage, needle, replacement] of INJECTIONS) shader[stage] = inject(shader[stage], needle, replacement());
}

/**
 * The material as three draws it, for the split's calls, whatever its own hook made of the shader:
 * its main() renamed and called from ours, which writes the attachments 0 (a draw into the split
 * call needs them: shaders/2-scene-split/material/unsplit.frag.glsl) and draws the material in the
 * first call only (unsplit.vert.glsl).
 */
function unsplitShader(shader) {
  shader.fragmentShader = `${outputsGlsl}\n#define main sssMaterialMain\n${shader.fragmentShader}\n${unsplitFragmentGlsl}`;
  shader.vertexShader = `#define main sssMaterialMain\n${shader.vertexShader}\n${unsplitVertexGlsl}`;
}

/** A material as a message names it. */
const labelOf = (material) => (material.name ? `material "${material.name}"` : `an unnamed ${material.type}`);

/** The mark a subsurface material's userData carries, naming it (its uuid) for its copies. */
export const COPY_MARK = 'three-separable-sss';

/** uuid → the material it names, for every material made subsurface (a copy finds its source). */
const byUuid = new Map();
const forget = typeof FinalizationRegistry === 'function' ? new FinalizationRegistry((uuid) => { if (!byUuid.get(uuid)?.deref()) byUuid.delete(uuid); }) : null;

/** Patches `material` once: its shader, its program cache key and a per-draw uniform refresh. */
function patch(material) {
  const uniforms = {
    sssSplit: { value: false },
    sssHidden: { value: false },
    sssWidthWorld: { value: 0 },
    sssWidthScale: { value: 1 },
    sssDebugOutput: { value: 0 },
    sssDiffuseCarriesDepth: { value: false },
    sssProfileSlot: { value: 0 },
    sssTransmits: { value: false },
    ...transmittanceUniformSlots(), // the shared ones (the one-light map and matrices go unread)
    ...lightArrays(),
  };
  const lightSlots = Array.from({ length: MAX_LIGHTS }, (_, i) => lightSlot(uniforms, i));
  const bindings = new Map();

  const hooks = composeHooks(material, {
    onBeforeCompile(shader, renderer, userHook) {
      const before = { vertexShader: shader.vertexShader, fragmentShader: shader.fragmentShader };
      userHook?.call(this, shader, renderer);
      Object.assign(shader.uniforms, uniforms);
      shader.defines = { ...shader.defines, ...defines, SSS_LIGHT_SLOTS: state.lightSlotsCompiled };
      // A point three's shader has and the user's hook took out: drawn as three draws it (a point
      // three's shader lacks is an unsupported three: inject throws).
      const lost = INJECTIONS.find(([stage, needle]) => before[stage].includes(needle) && !shader[stage].includes(needle));
      state.uncomposed = lost
        ? `${labelOf(material)}: its onBeforeCompile takes "${lost[1]}" out of three's ${lost[0] === 'vertexShader' ? 'vertex' : 'fragment'} shader, where the subsurface split goes in, so it is drawn as three draws it, without scattering or transmittance`
        : null;
      if (lost) unsplitShader(shader);
      else splitShader(shader);
    },
    programKey: () => `subsurface${state.lightSlotsCompiled}`,
    // Per draw: what to write (the phase) and whose settings (the pipeline drawing, else the latest
    // binding; none outside any pipeline: three's own output). Three uploads uniforms once per
    // material per render call, which is all these change at.
    onBeforeRender(renderer, scene, camera) {
      const draw = currentDraw(renderer.getRenderTarget());
      uniforms.sssSplit.value = draw.phase === DRAW_PHASES.SPLIT;
      uniforms.sssHidden.value = draw.phase === DRAW_PHASES.HIDDEN;
      uniforms.sssDiffuseCarriesDepth.value = draw.phase === DRAW_PHASES.SPLIT && diffuseCarriesDepth(draw.target);
      const binding = draw.owner === null ? undefined : bindings.get(draw.owner) ?? latest(bindings);
      if (binding) applyBinding(uniforms, lightSlots, binding, scene, camera);
      else uniforms.sssTransmits.value = false;
    },
  });
  // The mark its copies will carry (a copy made subsurface in turn is marked as itself, its
  // source's mark put back when it is restored).
  const mark = { had: Object.hasOwn(material.userData, COPY_MARK), value: material.userData[COPY_MARK] };
  material.userData[COPY_MARK] = material.uuid;
  byUuid.set(material.uuid, new WeakRef(material));
  forget?.register(material, material.uuid);

  const state = {
    uniforms,
    lightSlots,
    bindings,
    /** Why the material is drawn as three draws it (its own onBeforeCompile left out a point of ours), or null. */
    uncomposed: null,
    /** The lights the program reads (1..MAX_LIGHTS): the most any binding has; one reads one map. */
    lightSlotsCompiled: 1,
    /** Recompiles (once) when the most lights a binding has changes. */
    fitLightSlots() {
      const most = Math.max(1, ...[...bindings.values()].map((b) => b.transmittance?.length ?? 0));
      if (most === this.lightSlotsCompiled) return;
      this.lightSlotsCompiled = most;
      material.needsUpdate = true;
    },
    restore() {
      hooks.restore(); // the user's hooks as they are now
      if (mark.had) material.userData[COPY_MARK] = mark.value;
      else delete material.userData[COPY_MARK];
      patches.delete(material);
      // Release the material's compiled programs: three keeps them per material by cache key,
      // with the uniform objects of the last compile, so a later patch would find its key's old
      // program and run it with stale (or no) uniforms. three recompiles on the next draw.
      material.dispose();
    },
  };
  patches.set(material, state);
  material.needsUpdate = true;
  return state;
}

/** Writes one pipeline's settings into the material's uniforms for this draw (each light through its slot). */
function applyBinding(uniforms, lightSlots, binding, scene, camera) {
  const { options, transmittance } = binding;
  uniforms.sssWidthWorld.value = options.widthMm / options.worldUnitInMm;
  uniforms.sssWidthScale.value = options.widthScale;
  uniforms.sssDebugOutput.value = MATERIAL_OUTPUTS.indexOf(binding.debugOutput);
  uniforms.sssProfileSlot.value = binding.profileSlot;
  uniforms.sssLightTransmits.value.fill(false);
  uniforms.sssTransmits.value = false;
  if (!transmittance || !scene || !camera) return;
  transmittance.forEach((settings, i) => writeTransmittedLight(lightSlots[i], settings, scene, camera));
  uniforms.sssTransmits.value = uniforms.sssLightTransmits.value.includes(true);
}

/** The light depth maps of a binding's transmittance: one, or a list of up to MAX_LIGHTS. */
function lightDepthsOf(lightDepth) {
  if (!Array.isArray(lightDepth)) return [lightDepth];
  if (lightDepth.length < 1 || lightDepth.length > MAX_LIGHTS) throw new RangeError(`transmittance: lightDepth must list 1 to ${MAX_LIGHTS} light depth maps, got ${lightDepth.length}`);
  return lightDepth;
}


/**
 * One pipeline's settings on a subsurface material (what makeSubsurface returns).
 * @typedef {object} SubsurfaceBinding
 * @property {import('three').MeshStandardMaterial} material
 * @property {Record<string, import('three').IUniform>} uniforms the hook's uniforms (shared by every binding of the material)
 * @property {{ widthMm: number, widthScale: number, worldUnitInMm: number, transmittance: object|null }} options
 * @property {'diffuse'|'transmittance'|'thickness'} debugOutput what the diffuse attachment receives
 * @property {number} profileSlot the slot of the material's profile in the pipeline's frame
 *   (src/profiles/profileSlots.js; 0 with one profile), written to the surface attachment's b
 * @property {number} widthWorld world units per profile millimetre (width × widthScale)
 * @property {(options?: { widthMm?: number, widthScale?: number, worldUnitInMm?: number, transmittance?: object|null }) => void} update
 * @property {() => void} dispose unbinds these settings; the material is restored once none is left
 * @property {((copy: import('three').Material) => void) | null} followCopy how the owner binds a copy of the material (null: with these options)
 */

/**
 * Makes a MeshStandardMaterial or MeshPhysicalMaterial subsurface-scattering (idempotent: a second
 * call with the same owner updates the options). Drawn by no pipeline, the material renders
 * exactly as three's own (without transmittance).
 * @param {import('three').MeshStandardMaterial} material
 * @param {object} [options]
 * @param {number} [options.widthMm=1] scattering width: millimetres of material per profile
 *   millimetre (1 = the profile's physical size; 0 < widthMm ≤ 1000)
 * @param {number} [options.widthScale=1] 0..1, scales the width (0 = no scattering, the light kept)
 * @param {number} [options.worldUnitInMm=1000] millimetres per world unit (three.js: metres)
 * @param {object|null} [options.transmittance=null] light through thin parts:
 *   `{ lightDepth: LightDepthTarget, lookup: ProfileLookup, translucency?, shrinkMm? }` (lightDepth:
 *   a list of up to 4 for several lights, their light added up)
 * @param {object} [owner] the pipeline these settings are for (SubsurfaceScattering passes itself);
 *   omitted: settings of their own, used wherever a pipeline without settings of its own draws
 * @returns {SubsurfaceBinding}
 */
export function makeSubsurface(material, options = {}, owner = STANDALONE) {
  checkThreeRevision('makeSubsurface');
  if (!material || material.isMeshStandardMaterial !== true) {
    throw new TypeError(`makeSubsurface: material must be a THREE.MeshStandardMaterial or MeshPhysicalMaterial, got ${describe(material)}`);
  }
  refuseTransmission(material, 'makeSubsurface');
  // The split draw depth-tests subsurface against subsurface as three's opaque pass does.
  if (material.depthFunc !== LessEqualDepth) {
    throw new RangeError('makeSubsurface: material.depthFunc must be THREE.LessEqualDepth (the default) for the split draw');
  }
  checkOptions('makeSubsurface options', options, STANDALONE_OPTIONS);
  const state = patches.get(material) ?? patch(material);
  const existing = state.bindings.get(owner);
  if (existing) {
    existing.update(options);
    return existing;
  }

  const binding = {
    material,
    uniforms: state.uniforms,
    options: { widthMm: MATERIAL_DEFAULTS.widthMm, widthScale: MATERIAL_DEFAULTS.widthScale, worldUnitInMm: 1000, transmittance: null },
    /** Checked transmittance settings, or null. */
    transmittance: null,
    _debugOutput: 'diffuse',
    /** The profile's slot in this pipeline's frame (its pipeline sets it; 0: one profile). */
    profileSlot: 0,
    /**
     * Binds a copy of the material for this binding's owner (followCopy), where the owner keeps
     * its materials itself (a pipeline sets it); null: the same options are bound to the copy.
     * @type {((copy: import('three').Material) => void) | null}
     */
    followCopy: null,
    /** What the diffuse attachment receives: one of MATERIAL_OUTPUTS ('diffuse' normally; the others for debug views). */
    set debugOutput(mode) {
      this._debugOutput = checkOneOf('debugOutput', mode, MATERIAL_OUTPUTS);
    },
    get debugOutput() {
      return this._debugOutput;
    },
    /** World units per profile millimetre this binding writes (width × widthScale). */
    get widthWorld() {
      return (this.options.widthMm / this.options.worldUnitInMm) * this.options.widthScale;
    },
    update(next = {}) {
      checkOptions('makeSubsurface options', next, STANDALONE_OPTIONS);
      const o = { ...this.options, ...next };
      checkOption(MATERIAL_SCHEMA, 'widthMm', o.widthMm);
      checkOption(MATERIAL_SCHEMA, 'widthScale', o.widthScale);
      checkOption(PIPELINE_SCHEMA, 'worldUnitInMm', o.worldUnitInMm);
      this.transmittance = o.transmittance ? lightDepthsOf(o.transmittance.lightDepth)
        .map((lightDepth) => transmittanceSettings({ ...o.transmittance, lightDepth, worldUnitInMm: o.worldUnitInMm, widthMm: o.widthMm }, LightDepthTarget)) : null;
      this.options = o;
      state.fitLightSlots();
      if (latest(state.bindings) === this) applyBinding(state.uniforms, state.lightSlots, this); // the uniforms show the latest settings
    },
    /** Unbinds these settings; the material is restored once no binding is left. Idempotent. */
    dispose() {
      if (state.bindings.get(owner) !== this) return;
      state.bindings.delete(owner);
      if (state.bindings.size === 0) state.restore();
      else state.fitLightSlots();
    },
  };
  state.bindings.set(owner, binding);
  binding.update(options);
  return binding;
}

/**
 * The latest settings bound to a material made subsurface (those a pipeline without settings of its
 * own draws it with), or undefined for a material that is not subsurface.
 * @param {import('three').Material} material
 * @returns {SubsurfaceBinding|undefined}
 */
export function getSubsurface(material) {
  const state = patches.get(material);
  return state ? latest(state.bindings) : undefined;
}

/**
 * The settings `owner` bound to `material`, or undefined.
 * @param {import('three').Material} material
 * @param {object} owner
 */
export function subsurfaceBindingOf(material, owner) {
  return patches.get(material)?.bindings.get(owner);
}

/**
 * Why `material`, made subsurface, is drawn as three draws it (its own onBeforeCompile took out a
 * point the split goes in at), or null: found when three compiles it.
 * @param {import('three').Material} material
 * @returns {string|null}
 */
export function uncomposedReason(material) {
  return patches.get(material)?.uncomposed ?? null;
}

/**
 * Makes a copy of a subsurface material (material.clone(), .copy(): its userData carries COPY_MARK
 * naming the material it was copied from) subsurface as that material is now: each of that
 * material's bindings binds the copy too (through the binding's `followCopy` where its pipeline
 * set one, so that the pipeline keeps it with its own; else with the same options).
 * @param {import('three').Material} material
 * @returns {{ follows: true } | { follows: false, reason: string } | null} null: nothing to follow
 *   (not a copy, subsurface already, or its source is not subsurface now: then neither is the copy);
 *   a reason where it cannot follow (its source unknown to this page: loaded from JSON, or gone; or a
 *   kind of material makeSubsurface refuses)
 */
export function followCopy(material) {
  const mark = material.userData?.[COPY_MARK];
  if (typeof mark !== 'string' || patches.has(material)) return null;
  const source = byUuid.get(mark)?.deref();
  if (!source) {
    return { follows: false, reason: `${labelOf(material)} carries the subsurface mark of a material this page never made subsurface (a scene loaded from JSON, or a material since collected), so it is drawn as three draws it: make it subsurface with makeSubsurface` };
  }
  const sourceState = patches.get(source);
  if (source === material || !sourceState) return null;
  if (material.isMeshStandardMaterial !== true || material.transmission > 0 || material.depthFunc !== LessEqualDepth) {
    return { follows: false, reason: `${labelOf(material)} is a copy of the subsurface ${labelOf(source)} that makeSubsurface refuses (a ${material.type}${material.transmission > 0 ? ' with transmission' : ''}${material.depthFunc !== LessEqualDepth ? ' with another depthFunc' : ''}), so it is drawn as three draws it` };
  }
  for (const [owner, binding] of sourceState.bindings) {
    if (binding.followCopy) {
      binding.followCopy(material);
    } else {
      const copy = makeSubsurface(material, binding.options, owner);
      Object.assign(copy, { debugOutput: binding.debugOutput, profileSlot: binding.profileSlot });
    }
  }
  return { follows: true };
}
