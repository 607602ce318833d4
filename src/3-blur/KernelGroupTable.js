// The isotropic blur's split of every footprint's energy between its groups, as the integer
// texture shaders/3-blur/kernelGroups.glsl reads (one texel per footprint: groups 1..3's RGB
// fractions as 10-bit unorms, three to a channel; the last group takes the rest, so the parts sum
// to the footprint's exact energy whatever the rounding), and the groups' energy shares as its uniform.
// Slot p's rows follow the footprint table's stacking (p · FOOTPRINT_ROWS + row). One table serves
// both passes (the horizontal and the vertical split alike). Refilled only when a slot's grouping
// or footprint table changes (both are cached by scale step: a zoom refills it rarely).
import { DataTexture, NearestFilter, RGBAIntegerFormat, UnsignedIntType } from 'three';
import { FOOTPRINT_ROWS } from '../profiles/footprints.js';
import { MAX_KERNEL_GROUPS, footprintGroupFractions, groupEnergies } from './kernelGroups.js';

/** fractions → packed texels, cached per grouping and footprint table (both are cached objects). */
const packedTables = new WeakMap();

/**
 * A footprint is past groups 1 and 2's reach when their share of its energy is at most this in every
 * channel (two of the unorm's steps): the shader then blurs it for groups 3 and 4 alone, their split
 * taking the whole weight (kernelGroups.glsl's second loop). The centre texel's a holds how many
 * footprints of its row are within the reach.
 */
const NEAR_SHARE = 2 / 1023;

/** The 10-bit unorm's one (the shader divides by it). */
const UNORM_ONE = 1023;

/**
 * `fractions` (summing to 1) as integers summing to UNORM_ONE exactly, each within one of its
 * share (largest remainders), so the shader's parts add up to the footprint's weight; into
 * `shares` (a scratch array: the table packs thousands a refill).
 */
function unormShares(fractions, shares = new Array(fractions.length)) {
  const n = fractions.length;
  let left = UNORM_ONE;
  for (let g = 0; g < n; g++) {
    shares[g] = Math.floor(Math.min(Math.max(fractions[g], 0), 1) * UNORM_ONE);
    left -= shares[g];
  }
  // What is left goes round the groups from the largest remainder down (ties to the lower group):
  // whole rounds to every group, then one more to each of the largest.
  const rounds = Math.floor(left / n);
  for (let g = 0; g < n; g++) shares[g] += rounds;
  let taken = 0; // bit g: group g has had its one more
  for (left -= rounds * n; left > 0; left--) {
    let best = -1;
    let bestRemainder = -Infinity;
    for (let g = 0; g < n; g++) {
      const remainder = Math.min(Math.max(fractions[g], 0), 1) * UNORM_ONE - (shares[g] - rounds);
      if (!(taken & (1 << g)) && remainder > bestRemainder) [best, bestRemainder] = [g, remainder];
    }
    shares[best]++;
    taken |= 1 << best;
  }
  return shares;
}

/**
 * footprintGroupFractions packed as the shader reads them: texel channel g holds group g + 1's
 * (r, g, b) share in bits 0, 10, 20; group 4 takes the rest in the shader.
 */
function packedFractions(grouping, table) {
  let byTable = packedTables.get(grouping);
  if (!byTable) packedTables.set(grouping, (byTable = new WeakMap()));
  if (!byTable.has(table)) {
    const fractions = footprintGroupFractions(grouping, table);
    const texels = fractions.length / (MAX_KERNEL_GROUPS * 3);
    const packed = new Uint32Array(texels * 4);
    const columns = table.columns + 1;
    const parts = new Array(MAX_KERNEL_GROUPS); // scratch, per texel and channel
    const shares = new Array(MAX_KERNEL_GROUPS);
    for (let t = 0; t < texels; t++) {
      const column = t % columns;
      const at = t * MAX_KERNEL_GROUPS * 3;
      // Within groups 1 and 2's reach: the row's near count is one past the last such footprint.
      const near = fractions[at] + fractions[at + 3] > NEAR_SHARE || fractions[at + 1] + fractions[at + 4] > NEAR_SHARE || fractions[at + 2] + fractions[at + 5] > NEAR_SHARE;
      if (column > 0 && near) packed[(t - column) * 4 + 3] = column;
      for (let c = 0; c < 3; c++) {
        for (let g = 0; g < MAX_KERNEL_GROUPS; g++) parts[g] = fractions[at + g * 3 + c];
        unormShares(parts, shares);
        for (let g = 0; g < MAX_KERNEL_GROUPS - 1; g++) packed[t * 4 + g] |= shares[g] << (10 * c);
      }
    }
    byTable.set(table, packed);
  }
  return byTable.get(table);
}

/**
 * The split the shader makes of each footprint's energy (kernelGroups.glsl's sssSplit and its far
 * loop) from the packed texels, as fractions in footprintGroupFractions' layout: groups 1..3 the
 * unorms, the grouping's last group the rest; past groups 1 and 2's reach (the row's near count)
 * they take nothing, group 3 its unorm and group 4 the rest (three groups: group 3 all). The WebGPU
 * node's blur reads these (src/webgpu/3-blur/GroupFractionTexture.js), so both renderers split alike.
 * @param {ReturnType<typeof import('./kernelGroups.js').kernelGroups>} grouping
 * @param {{ data: Float32Array, columns: number }} table
 * @returns {Float32Array}
 */
export function splitFractions(grouping, table) {
  const packed = packedFractions(grouping, table);
  const count = grouping.members[0].length;
  const columns = table.columns + 1;
  const out = new Float32Array((packed.length / 4) * MAX_KERNEL_GROUPS * 3);
  for (let t = 0; t < packed.length / 4; t++) {
    const column = t % columns;
    const far = count > 2 && column > 0 && column - 1 >= packed[(t - column) * 4 + 3];
    for (let c = 0; c < 3; c++) {
      const unorm = (g) => ((packed[t * 4 + g] >>> (10 * c)) & 1023) / UNORM_ONE;
      const parts = new Array(MAX_KERNEL_GROUPS).fill(0);
      if (far) {
        parts[2] = count === 3 ? 1 : unorm(2);
        if (count === 4) parts[3] = Math.max(1 - parts[2], 0);
      } else {
        for (let g = 0; g < count - 1; g++) parts[g] = unorm(g);
        parts[count - 1] = Math.max(1 - parts.slice(0, count - 1).reduce((a, b) => a + b, 0), 0);
      }
      parts.forEach((part, g) => { out[(t * MAX_KERNEL_GROUPS + g) * 3 + c] = part; });
    }
  }
  return out;
}

export class KernelGroupTable {
  constructor() {
    /** @type {DataTexture|null} RGBA32UI, (columns + 1) × FOOTPRINT_ROWS per slot */
    this.texture = null;
    /** The groups' energy shares, the shader's groupEnergies: slot p's group g's RGB at (p · MAX_KERNEL_GROUPS + g) · 3. */
    this.energies = new Float32Array(MAX_KERNEL_GROUPS * 3);
    this._key = [];
  }

  /**
   * @param {ReadonlyArray<ReturnType<typeof import('./kernelGroups.js').kernelGroups>>} groupings per slot
   * @param {ReadonlyArray<{ data: Float32Array, columns: number }>} tables per slot, the footprint tables the blur reads
   * @returns {DataTexture}
   */
  update(groupings, tables) {
    const key = [...groupings, ...tables];
    if (this.texture && key.length === this._key.length && key.every((k, i) => k === this._key[i])) return this.texture;
    const columns = tables[0].columns + 1;
    if (tables.some((t) => t.columns + 1 !== columns)) throw new RangeError('KernelGroupTable: every slot\'s footprint table must have the same columns');
    const rows = FOOTPRINT_ROWS * groupings.length;
    if (!this.texture || this.texture.image.width !== columns || this.texture.image.height !== rows) {
      this.texture?.dispose();
      this.texture = new DataTexture(new Uint32Array(columns * rows * 4), columns, rows, RGBAIntegerFormat, UnsignedIntType);
      this.texture.internalFormat = 'RGBA32UI';
      this.texture.minFilter = this.texture.magFilter = NearestFilter;
      this.texture.name = 'KernelGroupTable';
    }
    groupings.forEach((grouping, slot) => this.texture.image.data.set(packedFractions(grouping, tables[slot]), slot * columns * FOOTPRINT_ROWS * 4));
    this.texture.needsUpdate = true;
    this.energies = new Float32Array(groupings.length * MAX_KERNEL_GROUPS * 3);
    groupings.forEach((grouping, slot) => groupEnergies(grouping).forEach((rgb, g) => this.energies.set(rgb, (slot * MAX_KERNEL_GROUPS + g) * 3)));
    this._key = key;
    return this.texture;
  }

  dispose() {
    this.texture?.dispose();
    this.texture = null;
    this._key = [];
  }
}
