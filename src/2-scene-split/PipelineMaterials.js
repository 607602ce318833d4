// The materials one pipeline made subsurface, with the options it was given for each: what
// SubsurfaceScattering.makeSubsurface binds (the material hook keeps one binding per pipeline),
// rebinds when transmittance is switched, points at a debug output, and unbinds on dispose. Each
// material's profile (its own `profile`, or the pipeline's) picks its transmittance table and,
// through the pipeline's slots (src/profiles/profileSlots.js), the index it writes.
import { MATERIAL_DEFAULTS, checkMaterialOptions } from '../options.js';
import { getProfile } from '../profiles/presets.js';
import { makeSubsurface, getSubsurface, subsurfaceBindingOf } from './subsurfaceMaterial.js';

export class PipelineMaterials {
  /**
   * @param {object} owner the pipeline whose settings the bindings are
   * @param {() => { worldUnitInMm: number, lightDepths: object[], profile: object, lookupOf: (profile: object) => object,
   *   checkProfiles: (profiles: object[]) => void, debugOutput: string }} settings the pipeline's current scale, light
   *   depth maps (one per light; none: no transmittance), profile (the materials' default), the tables of a profile, the check of the
   *   profiles its materials would use (throws when the pipeline cannot blur them) and debug output
   */
  constructor(owner, settings) {
    this.owner = owner;
    this.settings = settings;
    /** material → { hook: its binding, options } */
    this.entries = new Map();
  }

  /**
   * Binds (or rebinds) `material` with `options` on top of those it had.
   * @param {import('three').MeshStandardMaterial} material
   * @param {{ widthMm?: number, widthScale?: number, strength?: number, transmittance?: boolean, translucency?: number, shrinkMm?: number }} options
   */
  bind(material, options = {}) {
    // Checked whole here, so a later switch of transmittance cannot fail half-way.
    const o = checkMaterialOptions(options, { ...MATERIAL_DEFAULTS, ...this.entries.get(material)?.options });
    const { worldUnitInMm, lightDepths, lookupOf, checkProfiles, debugOutput } = this.settings();
    checkProfiles(this.profiles(undefined, { material, options: o })); // before binding: a refusal changes nothing
    const lookup = lookupOf(this.profileOf(o));
    const hook = makeSubsurface(material, {
      widthMm: o.widthMm,
      widthScale: o.widthScale,
      worldUnitInMm,
      transmittance: o.transmittance && lightDepths.length > 0 ? { lightDepth: lightDepths, lookup, translucency: o.translucency, shrinkMm: o.shrinkMm } : null,
    }, this.owner);
    hook.debugOutput = debugOutput;
    this.entries.set(material, { hook, options: o });
    return hook;
  }

  /**
   * Unbinds `material` from this pipeline (it is restored once no pipeline has it).
   * @param {import('three').Material} material
   * @returns {boolean} whether it was bound
   */
  unbind(material) {
    const entry = this.entries.get(material);
    if (!entry) return false;
    entry.hook.dispose();
    this.entries.delete(material);
    return true;
  }

  /** The profile of a material bound with options `o`: its own, or the pipeline's (`profile`, default the current one). */
  profileOf(o, profile = this.settings().profile) {
    return o.profile === undefined ? profile : getProfile(o.profile);
  }

  /**
   * Every bound material's profile, in binding order (see profileOf), as they are or with one
   * material's options changed (`change`, a material bound or about to be).
   * @param {object} [profile] the pipeline's profile (default: the current one)
   * @param {{ material: object, options: object }|null} [change]
   */
  profiles(profile = this.settings().profile, change = null) {
    const options = [...this.entries].map(([material, entry]) => (material === change?.material ? change.options : entry.options));
    if (change && !this.entries.has(change.material)) options.push(change.options);
    return options.map((o) => this.profileOf(o, profile));
  }

  /** Rebinds every material with the pipeline's current settings. */
  rebindAll() {
    for (const material of this.entries.keys()) this.bind(material);
  }

  /** @param {string} output one of the material hook's MATERIAL_OUTPUTS */
  setDebugOutput(output) {
    for (const { hook } of this.entries.values()) hook.debugOutput = output;
  }

  /** World units per profile millimetre `material` writes when this pipeline draws it (width × widthScale). */
  widthWorldOf(material) {
    return (subsurfaceBindingOf(material, this.owner) ?? getSubsurface(material)).widthWorld;
  }

  /** Unbinds every material (each is restored once no pipeline has it). */
  dispose() {
    for (const { hook } of this.entries.values()) hook.dispose();
    this.entries.clear();
  }
}
