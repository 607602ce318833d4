// Several profiles' GPU tables stacked for one blur pass (PROFILE_COUNT > 1), read by a pixel's slot
// (src/profiles/profileSlots.js): profileTexture rows 2p (T(d)) and 2p + 1 (G(x)); footprintTexture
// rows p · FOOTPRINT_ROWS + row (same columns for the same tap budget). Refilled only when the
// profiles or the tap budget change: a table takes tens of ms.
import { DataTexture, FloatType, NearestFilter, RGBAFormat, RGFormat } from 'three';
import { FOOTPRINT_ROWS } from './footprints.js';
import { tableOf } from './FootprintTable.js';

/** Nearest-filtered: the shaders interpolate themselves. */
function floatTexture(data, width, height, format, name) {
  const texture = new DataTexture(data, width, height, format, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.name = name;
  texture.needsUpdate = true;
  return texture;
}

export class ProfileStack {
  constructor() {
    this.profileTexture = null;
    this.footprintTexture = null;
    /** Slot p's marginal range, mm (the shader's marginalRangesMm[PROFILE_COUNT]). */
    this.marginalRangesMm = new Float32Array(0);
    this._profiles = [];
    this._samples = 0;
  }

  /**
   * Makes the textures hold `lookups`' tables, in slot order, for `samples` taps.
   * @param {readonly import('./ProfileLookup.js').ProfileLookup[]} lookups two or more
   * @param {number|'auto'} samples see FootprintTable.update
   */
  update(lookups, samples) {
    const profiles = lookups.map((lookup) => lookup.profile);
    if (samples === this._samples && profiles.length === this._profiles.length && profiles.every((p, i) => p === this._profiles[i])) return;
    this.dispose();
    const width = lookups[0].texture.image.width;
    if (lookups.some((lookup) => lookup.texture.image.width !== width)) throw new RangeError('ProfileStack: every ProfileLookup must have the same size');
    const rows = new Float32Array(width * 2 * 4 * lookups.length);
    lookups.forEach((lookup, slot) => rows.set(lookup.texture.image.data, slot * width * 2 * 4));
    this.profileTexture = floatTexture(rows, width, 2 * lookups.length, RGBAFormat, 'ProfileStack.profiles');
    const tables = lookups.map((lookup) => tableOf(lookup, samples));
    const footprints = new Float32Array(tables[0].data.length * tables.length);
    tables.forEach((table, slot) => footprints.set(table.data, slot * table.data.length));
    this.footprintTexture = floatTexture(footprints, tables[0].columns, FOOTPRINT_ROWS * tables.length, RGFormat, 'ProfileStack.footprints');
    this.marginalRangesMm = Float32Array.from(lookups, (lookup) => lookup.marginalRangeMm);
    this._profiles = profiles;
    this._samples = samples;
  }

  dispose() {
    this.profileTexture?.dispose();
    this.footprintTexture?.dispose();
    this.profileTexture = this.footprintTexture = null;
    this._profiles = [];
  }
}
