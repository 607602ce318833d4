// The 'footprint' blur's tap allocation (src/profiles/footprints.js) as the texture the shader reads,
// computed from the ProfileLookup's marginal row (the energies the GPU reads).
import { DataTexture, FloatType, NearestFilter, RGFormat } from 'three';
import { footprintTable, FOOTPRINT_ROWS } from './footprints.js';

/** profile → samples → table: one takes tens of ms, 'auto' a few hundred. */
const tables = new WeakMap();

/**
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
   * @param {number|'auto'} samples taps per direction (odd, ≥ 3), or 'auto' (footprintTable)
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
