// The materials one pipeline made subsurface, with the options it was given for each: what
// SubsurfaceScattering.makeSubsurface binds (the material hook keeps one binding per pipeline),
// rebinds when transmittance is switched, points at a debug output, and unbinds on dispose. Each
// material's profile (its own `profile`, or the pipeline's) picks its transmittance table and,
// through the pipeline's slots (src/profiles/profileSlots.js), the index it writes.
import { MATERIAL_DEFAULTS, checkMaterialOptions } from '../options.js';
import { getProfile } from '../profiles/presets.js';
import { makeSubsurface, getSubsurface, subsurfaceBindingOf, uncomposedReason } from './subsurfaceMaterial.js';

export class PipelineMaterials {
  /**
   * @param {object} owner the pipeline whose settings the bindings are
   * @param {() => { worldUnitInMm: number, lightDepths: object[], profile: object, lookupOf: (profile: object) => object,
   *   checkProfiles: (profiles: object[]) => void, debugOutput: string }} settings the pipeline's current scale, light
   *   depth maps (one per light; none: no transmittance), profile (the materials' default), the tables of a profile, the check of the
   *   profiles its materials would use (throws when the pipeline cannot blur them) and debug output
   * @param {() => void} [onCopies] called when a copy of a bound material was bound or unbound in a frame
   *   (the pipeline's profile slots follow)
   */
  constructor(owner, settings, onCopies = () => {}) {
    this.owner = owner;
    this.settings = settings;
    /** material → { hook: its binding, options } */
    this.entries = new Map();
    /** material → the copies of it bound as it (material.clone(), .copy(): followCopy), which follow its options and its removal */
    this.copies = new Map();
    this._onCopies = onCopies;
    // A copy disposed of is unbound (drawn again, it follows its source again).
    this._onCopyDispose = (event) => {
      this.unbind(event.target);
      this._onCopies();
    };
  }

  /**
   * Binds (or rebinds) `material` with `options` on top of those it had; its copies follow them. A
   * copy bound here is the user's own from then on.
   * @param {import('three').MeshStandardMaterial} material
   * @param {{ widthMm?: number, widthScale?: number, strength?: number, transmittance?: boolean, translucency?: number, shrinkMm?: number }} options
   */
  bind(material, options = {}) {
    // Checked whole here, so a later switch of transmittance cannot fail half-way.
    const o = checkMaterialOptions(options, { ...MATERIAL_DEFAULTS, ...this.entries.get(material)?.options });
    const { checkProfiles } = this.settings();
    checkProfiles(this.profiles(undefined, { material, options: o })); // before binding: a refusal changes nothing
    for (const copies of this.copies.values()) if (copies.delete(material)) material.removeEventListener('dispose', this._onCopyDispose);
    const hook = this._bind(material, o);
    for (const copy of this.copies.get(material) ?? []) this._bind(copy, o);
    return hook;
  }

  /** Binds `material` with checked options `o`. */
  _bind(material, o) {
    const { worldUnitInMm, lightDepths, lookupOf, debugOutput } = this.settings();
    const lookup = lookupOf(this.profileOf(o));
    const hook = makeSubsurface(material, {
      widthMm: o.widthMm,
      widthScale: o.widthScale,
      worldUnitInMm,
      transmittance: o.transmittance && lightDepths.length > 0 ? { lightDepth: lightDepths, lookup, translucency: o.translucency, shrinkMm: o.shrinkMm } : null,
    }, this.owner);
    hook.debugOutput = debugOutput;
    hook.followCopy = (copy) => this.bindCopy(copy, material);
    this.entries.set(material, { hook, options: o });
    return hook;
  }

  /**
   * Binds `copy`, a copy of the bound `source` met in a frame (followCopy), with the source's options.
   * @param {import('three').MeshStandardMaterial} copy
   * @param {import('three').MeshStandardMaterial} source
   */
  bindCopy(copy, source) {
    const entry = this.entries.get(source);
    if (!entry) return;
    this._bind(copy, entry.options);
    if (!this.copies.has(source)) this.copies.set(source, new Set());
    this.copies.get(source).add(copy);
    copy.addEventListener('dispose', this._onCopyDispose);
    this._onCopies();
  }

  /**
   * Unbinds `material` from this pipeline (it is restored once no pipeline has it), and the copies
   * that follow it.
   * @param {import('three').Material} material
   * @returns {boolean} whether it was bound
   */
  unbind(material) {
    const entry = this.entries.get(material);
    if (!entry) return false;
    for (const copies of this.copies.values()) if (copies.delete(material)) material.removeEventListener('dispose', this._onCopyDispose);
    for (const copy of this.copies.get(material) ?? []) {
      copy.removeEventListener('dispose', this._onCopyDispose);
      this.entries.get(copy)?.hook.dispose();
      this.entries.delete(copy);
    }
    this.copies.delete(material);
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
    for (const [material, { options }] of this.entries) this._bind(material, options);
  }

  /** @param {string} output one of the material hook's MATERIAL_OUTPUTS */
  setDebugOutput(output) {
    for (const { hook } of this.entries.values()) hook.debugOutput = output;
  }

  /** World units per profile millimetre `material` writes when this pipeline draws it (width × widthScale). */
  widthWorldOf(material) {
    return (subsurfaceBindingOf(material, this.owner) ?? getSubsurface(material)).widthWorld;
  }

  /**
   * Names what this pipeline's frame cannot make subsurface, each once (`checks`, FrameChecks): a
   * bound material whose own onBeforeCompile took out a point the split goes in at, and the copies
   * of subsurface materials the scene split met and could not follow (`notFollowed`: material → why).
   * @param {{ problem(key: string, message: string): void }} checks
   * @param {Map<import('three').Material, string>} notFollowed
   */
  checkMaterials(checks, notFollowed) {
    for (const material of this.entries.keys()) {
      const reason = uncomposedReason(material);
      if (reason) checks.problem(`uncomposed:${material.uuid}`, reason);
    }
    for (const [material, reason] of notFollowed) checks.problem(`copy:${material.uuid}`, reason);
  }

  /** Unbinds every material (each is restored once no pipeline has it). */
  dispose() {
    for (const copies of this.copies.values()) for (const copy of copies) copy.removeEventListener('dispose', this._onCopyDispose);
    this.copies.clear();
    for (const { hook } of this.entries.values()) hook.dispose();
    this.entries.clear();
  }
}
