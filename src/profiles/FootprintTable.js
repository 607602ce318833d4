// The 'footprint' blur's tap allocation (src/profiles/footprints.js) for one profile and tap budget,
// as a float table the shader reads: row r (scale FOOTPRINT_SCALES.min · 2^(r / perOctave) px/mm)
// holds, per footprint, its outer edge and where it is sampled, in profile mm (RG float).
// Tables are pure numbers computed from the ProfileLookup's marginal row (the energies the GPU
// reads), kept per profile and budget: 'auto' switches between a few budgets.
import { DataTexture, FloatType, NearestFilter, RGFormat } from 'three';
import { footprintTable, FOOTPRINT_ROWS } from './footprints.js';

/** profile → samples (or 'auto') → table (computing one takes tens of ms; 'auto' a few hundred). */
const tables = new WeakMap();

/**
 * The footprint table's numbers for the lookup's current profile and `samples` (cached per profile).
 * @param {import('./ProfileLookup.js').ProfileLookup} lookup
 * @param {number|'auto'} samples
 */
export function tableOf(lookup, samples) {
  let bySamples = tables.get(lookup.profile);
  if (!bySamples) tables.set(lookup.profile, (bySamples = new Map()));
  if (!bySamples.has(samples)) bySamples.set(samples, footprintTable((x) => lookup.marginalEnergy(x), samples));
  return bySamples.get(samples);
}

export class FootprintTable {
  /** @param {import('./ProfileLookup.js').ProfileLookup} lookup */
  constructor(lookup) {
    this.lookup = lookup;
    this.texture = null;
    this.profile = null;
    this.samples = 0;
    /** The table's numbers: { data, columns, rows, stepError } (see footprintTable). */
    this.table = null;
  }

  /**
   * Makes the texture hold the table of the lookup's current profile for `samples` taps.
   * @param {number|'auto'} samples taps per direction (odd, ≥ 3), or 'auto': per scale the fewest
   *   within AUTO_STEP_ERROR (the shader's loop then runs to AUTO_MAX_SAMPLES at most)
   * @returns {DataTexture}
   */
  update(samples) {
    if (this.profile === this.lookup.profile && this.samples === samples) return this.texture;
    const table = tableOf(this.lookup, samples);
    if (!this.texture || this.texture.image.width !== table.columns) {
      this.texture?.dispose();
      this.texture = new DataTexture(new Float32Array(table.data.length), table.columns, FOOTPRINT_ROWS, RGFormat, FloatType);
      this.texture.minFilter = this.texture.magFilter = NearestFilter;
      this.texture.name = 'FootprintTable';
    }
    this.texture.image.data.set(table.data);
    this.texture.needsUpdate = true;
    this.profile = this.lookup.profile;
    this.samples = samples;
    this.table = table;
    return this.texture;
  }

  dispose() {
    this.texture?.dispose();
  }
}
