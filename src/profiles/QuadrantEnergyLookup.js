// A profile's energy over axis-aligned rectangles, for the dense reference
// (shaders/common/quadrantEnergy.glsl): Q(a, b) = ∫_0^a ∫_0^b R(√(x² + y²)) dy dx, odd in each
// argument, so a pixel's energy is a double difference of Q: exact however narrow the profile is
// against a pixel, and the differences of a row telescope, so interpolation errors cannot pile up.
// Texel (i, j) holds Q(x_i, x_j), x_k = (k / (size − 1))² · range, like ProfileLookup's rows.
import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { getProfile } from './presets.js';
import { gaussLegendre } from '../math/quadrature.js';
import { firstBelow } from '../math/roots.js';
import { checkInteger, checkOptions } from '../support/parameterChecks.js';

/** Energy left outside the table's range (per channel): invisible even at radiance 1000. */
const TAIL = 1e-6;
/** Gauss-Legendre points per cell and axis: cells are small against the profile's variation. */
const ORDER = 4;

/** Smallest radius (mm) outside which every channel holds < TAIL. */
const rangeOf = (profile) => firstBelow((r) => Math.max(...profile.transmittance(r)), TAIL);

export class QuadrantEnergyLookup {
  /**
   * @param {string | object} [profile='skin'] a profile name or object (see `profiles`)
   * @param {{ size?: number }} [options] texels per side (16..2048)
   */
  constructor(profile = 'skin', options = {}) {
    const { size = 384 } = checkOptions('QuadrantEnergyLookup options', options, ['size']);
    checkInteger('size', size, 16, 2048, 'texels');
    this.texture = new DataTexture(new Float32Array(size * size * 4), size, size, RGBAFormat, FloatType);
    this.texture.minFilter = this.texture.magFilter = NearestFilter;
    this.texture.name = 'QuadrantEnergyLookup';
    this.setProfile(profile);
  }

  /** Each cell by tensor Gauss-Legendre, then summed (float64) into Q. */
  setProfile(profile) {
    const p = getProfile(profile);
    const { data, width: n } = this.texture.image;
    const range = rangeOf(p);
    const grid = Float64Array.from({ length: n }, (_, k) => (k / (n - 1)) ** 2 * range);
    // Quadrature points along one axis (the same on both).
    const { nodes, weights } = gaussLegendre(ORDER);
    const points = new Float64Array((n - 1) * ORDER);
    const pointWeights = new Float64Array((n - 1) * ORDER);
    for (let k = 0; k + 1 < n; k++) {
      const centre = (grid[k] + grid[k + 1]) / 2;
      const half = (grid[k + 1] - grid[k]) / 2;
      for (let q = 0; q < ORDER; q++) {
        points[k * ORDER + q] = centre + half * nodes[q];
        pointWeights[k * ORDER + q] = half * weights[q];
      }
    }
    // cell(i, j) = cell(j, i): integrate j ≥ i only.
    const cells = new Float64Array((n - 1) * (n - 1) * 3);
    for (let j = 0; j + 1 < n; j++) {
      for (let i = 0; i <= j; i++) {
        let e0 = 0, e1 = 0, e2 = 0;
        for (let qy = 0; qy < ORDER; qy++) {
          const y = points[j * ORDER + qy];
          const wy = pointWeights[j * ORDER + qy];
          for (let qx = 0; qx < ORDER; qx++) {
            const x = points[i * ORDER + qx];
            const w = wy * pointWeights[i * ORDER + qx];
            const r = p.R(Math.sqrt(x * x + y * y));
            e0 += w * r[0];
            e1 += w * r[1];
            e2 += w * r[2];
          }
        }
        cells.set([e0, e1, e2], (j * (n - 1) + i) * 3);
        cells.set([e0, e1, e2], (i * (n - 1) + j) * 3);
      }
    }
    // Q(x_i, x_j) = Σ of the cells below and left of (i, j): a 2D prefix sum.
    const q = new Float64Array(n * n * 3);
    for (let j = 1; j < n; j++) {
      for (let i = 1; i < n; i++) {
        for (let c = 0; c < 3; c++) {
          q[(j * n + i) * 3 + c] = cells[((j - 1) * (n - 1) + i - 1) * 3 + c]
            + q[((j - 1) * n + i) * 3 + c] + q[(j * n + i - 1) * 3 + c] - q[((j - 1) * n + i - 1) * 3 + c];
        }
      }
    }
    for (let k = 0; k < n * n; k++) data.set([q[k * 3], q[k * 3 + 1], q[k * 3 + 2], 1], k * 4);
    this.profile = p;
    this.rangeMm = range;
    this.texture.needsUpdate = true;
  }

  /**
   * Q(a, b) read from the table as shaders/common/quadrantEnergy.glsl reads it.
   * @param {number} aMm
   * @param {number} bMm
   * @returns {number[]} [r, g, b]
   */
  quadrantEnergy(aMm, bMm) {
    const { data, width: n } = this.texture.image;
    const coordinate = (x) => {
      const position = Math.sqrt(Math.min(Math.abs(x) / this.rangeMm, 1)) * (n - 1);
      const below = Math.min(Math.floor(position), n - 2);
      return [below, position - below];
    };
    const [i, fx] = coordinate(aMm);
    const [j, fy] = coordinate(bMm);
    const sign = Math.sign(aMm) * Math.sign(bMm);
    return [0, 1, 2].map((c) => {
      const t = (di, dj) => data[((j + dj) * n + i + di) * 4 + c];
      const bottom = t(0, 0) * (1 - fx) + t(1, 0) * fx;
      const top = t(0, 1) * (1 - fx) + t(1, 1) * fx;
      return sign * (bottom * (1 - fy) + top * fy);
    });
  }

  dispose() {
    this.texture.dispose();
  }
}
