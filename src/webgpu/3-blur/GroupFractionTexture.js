// The isotropic blur's split of every footprint's energy between its groups, as the node's blur
// reads it: the WebGL shader's own split (src/3-blur/KernelGroupTable.js's splitFractions: the
// fractions of kernelGroups.js rounded to the 10-bit unorms of its integer texture, so both
// renderers blur with the same numbers) in a float RGBA texture, group g's RGB fractions of
// footprint table row r in texel row g · FOOTPRINT_ROWS + r, column 0 the centre and j + 1
// footprint j. The blur reads each group's row, in floats, which both of WebGPURenderer's
// backends load alike. Refilled only when the grouping or the footprint table changes (both are
// cached by scale step: a zoom refills it rarely).
import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { FOOTPRINT_ROWS } from '../../profiles/footprints.js';
import { MAX_KERNEL_GROUPS, groupEnergies } from '../../3-blur/kernelGroups.js';
import { splitFractions } from '../../3-blur/KernelGroupTable.js';

export class GroupFractionTexture {
  constructor() {
    /** @type {DataTexture|null} RGBA float, (columns + 1) × (MAX_KERNEL_GROUPS · FOOTPRINT_ROWS) */
    this.texture = null;
    /** Each group's share of the profile's energy, RGB (kernelGroups.js's groupEnergies), for the pixels that do no work. @type {number[][]} */
    this.energies = [];
    this._grouping = null;
    this._table = null;
  }

  /**
   * @param {ReturnType<typeof import('../../3-blur/kernelGroups.js').kernelGroups>} grouping
   * @param {{ data: Float32Array, columns: number }} table the footprint table the blur reads
   * @returns {DataTexture}
   */
  update(grouping, table) {
    if (this.texture && grouping === this._grouping && table === this._table) return this.texture;
    const fractions = splitFractions(grouping, table);
    const columns = table.columns + 1;
    const rows = MAX_KERNEL_GROUPS * FOOTPRINT_ROWS;
    if (!this.texture || this.texture.image.width !== columns) {
      this.texture?.dispose();
      this.texture = new DataTexture(new Float32Array(columns * rows * 4), columns, rows, RGBAFormat, FloatType);
      this.texture.minFilter = this.texture.magFilter = NearestFilter;
      this.texture.name = 'GroupFractionTexture';
    }
    const data = this.texture.image.data;
    for (let row = 0; row < FOOTPRINT_ROWS; row++) {
      for (let column = 0; column < columns; column++) {
        for (let g = 0; g < MAX_KERNEL_GROUPS; g++) {
          const from = ((row * columns + column) * MAX_KERNEL_GROUPS + g) * 3;
          data.set(fractions.subarray(from, from + 3), ((g * FOOTPRINT_ROWS + row) * columns + column) * 4);
        }
      }
    }
    this.texture.needsUpdate = true;
    this.energies = groupEnergies(grouping);
    this._grouping = grouping;
    this._table = table;
    return this.texture;
  }

  dispose() {
    this.texture?.dispose();
    this.texture = null;
    this.energies = [];
    this._grouping = this._table = null;
  }
}
