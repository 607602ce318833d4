// A diffusion profile as a float table the shaders read (shaders/common/profileLookup.glsl), so any
// profile works on the GPU: row 0 T(d), the energy beyond radius d; row 1 G(x) = ∫_0^x marginal,
// whose differences weigh the blur's footprints exactly. Texel i holds x = (i / (size - 1))² · range:
// dense near 0, where the narrow Gaussians are.
import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { getProfile } from './presets.js';
import { checkInteger, checkOptions } from '../support/parameterChecks.js';
import { firstBelow, solveDecreasing } from '../math/roots.js';
import { nameClass } from '../support/className.js';

/** Below this the tail of a row is invisible even at radiance 1000: the range ends there. */
const TAIL = 1e-5;

/** Smallest x (mm) past which every channel of f(x) is below `TAIL`. */
const rangeWhere = (f) => firstBelow((x) => Math.max(...f(x)), TAIL);

/** The x (mm) with 2 ∫_x^∞ marginal = tail in the widest channel: all but `tail` of both sides inside. */
const radiusHolding = (profile, tail) => solveDecreasing((x) => 2 * Math.max(...profile.marginalIntegral(x, Infinity)), tail, 0, 0.25);

export class ProfileLookup {
  /**
   * @param {string | object} [profile='skin'] a profile name or object (see `profiles`)
   * @param {{ size?: number }} [options] texels per row (16..4096); 512 puts skin's narrowest
   *   Gaussian (σ = 0.08 mm) over ~10 texels: interpolation error < 1e-6
   */
  constructor(profile = 'skin', options = {}) {
    const { size = 512 } = checkOptions('ProfileLookup options', options, ['size']);
    checkInteger('size', size, 16, 4096, 'texels');
    this.texture = new DataTexture(new Float32Array(size * 2 * 4), size, 2, RGBAFormat, FloatType);
    this.texture.minFilter = this.texture.magFilter = NearestFilter;
    this.texture.name = 'ProfileLookup';
    this.setProfile(profile);
  }

  setProfile(profile) {
    const p = getProfile(profile);
    this.profile = p;
    this.transmittanceRangeMm = rangeWhere((d) => p.transmittance(d));
    this.marginalRangeMm = rangeWhere((x) => p.marginalIntegral(x, Infinity));
    // What the 'footprint' blur must resolve pixel by pixel to be exact within about 1 %.
    this.marginalRadiusMm = radiusHolding(p, 0.01);
    const { data, width } = this.texture.image;
    for (let i = 0; i < width; i++) {
      const u = (i / (width - 1)) ** 2;
      data.set([...p.transmittance(u * this.transmittanceRangeMm), 1], i * 4);
      data.set([...p.marginalIntegral(0, u * this.marginalRangeMm), 1], (width + i) * 4);
    }
    this.texture.needsUpdate = true;
  }

  /**
   * G(x) = ∫_0^x marginal, read from the table as shaders/common/profileLookup.glsl reads row 1.
   * @param {number} xMm
   * @returns {number[]} [r, g, b]
   */
  marginalEnergy(xMm) {
    return this._read(1, xMm, this.marginalRangeMm);
  }

  _read(row, xMm, rangeMm) {
    const { data, width } = this.texture.image;
    const position = Math.sqrt(Math.min(Math.max(xMm / rangeMm, 0), 1)) * (width - 1);
    const below = Math.min(Math.floor(position), width - 2);
    const t = position - below;
    const i = (row * width + below) * 4;
    return [0, 1, 2].map((c) => data[i + c] * (1 - t) + data[i + 4 + c] * t);
  }

  dispose() {
    this.texture.dispose();
  }
}

nameClass(ProfileLookup, 'ProfileLookup'); // its name in messages, minified or not
