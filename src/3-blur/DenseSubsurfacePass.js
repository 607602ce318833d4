// The dense 2D reference of the subsurface blur, as a ShaderPass: brute-force screen-space
// convolution with the full radial profile (not separable), for validation and the speed-accuracy
// bench, not for production (its cost grows with the square of the on-screen kernel radius).
// It replaces the two blurs (internals' useDenseReference, for validation). Same units, mask and depth
// rules as SubsurfaceBlurPass, through their shared base SurfacePass; see
// shaders/3-blur/denseSubsurface.frag.glsl.
import denseGlsl from '../../shaders/3-blur/denseSubsurface.frag.glsl?raw';
import quadrantEnergyGlsl from '../../shaders/common/quadrantEnergy.glsl?raw';
import { QuadrantEnergyLookup } from '../profiles/QuadrantEnergyLookup.js';
import { getProfile } from '../profiles/presets.js';
import { checkInteger, checkNumber, checkOptions } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { SurfacePass } from './SurfacePass.js';
import { nameClass } from '../support/className.js';

const CHUNKS = Object.freeze({ 'common/quadrantEnergy.glsl': quadrantEnergyGlsl });

export class DenseSubsurfacePass extends SurfacePass {
  /**
   * @param {object} options
   * @param {import('three').Camera} options.camera the camera the scene was rendered with
   * @param {import('three').Texture} options.surfaceTexture the scene pass's surface attachment
   *   (r: linear view depth in world units, g: world units per profile mm, 0 off subsurface pixels)
   * @param {import('three').Texture|null} [options.diffuseTexture=null] the scene pass's diffuse
   *   attachment (alpha: the mask, or the depth it carries: setLightCarriesDepth); null reads the
   *   composer's read buffer
   * @param {string|object} [options.profile='skin'] profile name or object (ignored when
   *   `energyLookup` is given)
   * @param {QuadrantEnergyLookup|null} [options.energyLookup=null] a table to share (not disposed
   *   by this pass); by default the pass builds and owns one for `profile`
   * @param {number} [options.coverage=0.997] fraction of the profile's energy inside the radius
   *   covered (the widest channel's radius), in (0, 1)
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop'] what a pixel on another surface does
   * @param {number} [options.depthThresholdWorld=0.006] depth difference (world units) at which a
   *   pixel counts fully as another surface
   * @param {boolean} [options.foreshortening=true] grazing angles, as the blur: shrink each axis by
   *   cos(tilt) of the surface along it and compare depths with the local plane
   * @param {number} [options.maxRadiusPx=128] bound on the radius in pixels (loop bound)
   */
  constructor(options = {}) {
    const { profile = 'skin', energyLookup = null, coverage = 0.997, maxRadiusPx = 128, ...surface } = checkOptions('DenseSubsurfacePass options', options);
    if (energyLookup !== null && !(energyLookup instanceof QuadrantEnergyLookup)) {
      throw new TypeError(`DenseSubsurfacePass: energyLookup must be a QuadrantEnergyLookup or null, got ${describe(energyLookup)}`);
    }
    checkInteger('maxRadiusPx', maxRadiusPx, 1, 4096, 'pixels');
    super({
      name: 'DenseSubsurfacePass',
      fragmentShader: denseGlsl,
      chunks: CHUNKS,
      uniforms: {
        tQuadrant: { value: null },
        quadrantRangeMm: { value: 1 },
        radiusMm: { value: 0 },
        maxRadiusPx: { value: maxRadiusPx },
      },
    }, surface);
    this._ownsLookup = energyLookup === null;
    this.energyLookup = energyLookup ?? new QuadrantEnergyLookup(profile);
    this.coverage = coverage;
    this.setCoverage(coverage);
  }

  /** The profile convolved with (the energy table's). */
  get profile() {
    return this.energyLookup.profile;
  }

  /**
   * Switches to another profile: rebuilds the owned table, or takes `energyLookup`'s.
   * @param {string|object|QuadrantEnergyLookup} profileOrLookup
   */
  setProfile(profileOrLookup) {
    if (profileOrLookup instanceof QuadrantEnergyLookup) {
      if (this._ownsLookup) this.energyLookup.dispose();
      this.energyLookup = profileOrLookup;
      this._ownsLookup = false;
    } else if (this._ownsLookup) {
      this.energyLookup.setProfile(getProfile(profileOrLookup));
    } else {
      this.energyLookup = new QuadrantEnergyLookup(profileOrLookup);
      this._ownsLookup = true;
    }
    this.setCoverage(this.coverage);
  }

  /** @param {number} coverage fraction of the energy inside the covered radius, in (0, 1) */
  setCoverage(coverage) {
    checkNumber('coverage', coverage, { min: 0, max: 1, minExclusive: true, maxExclusive: true });
    this.coverage = coverage;
    /** The covered radius, profile mm (the widest channel's). */
    this.radiusMm = Math.max(...this.profile.radiusMm(coverage));
    this.uniforms.radiusMm.value = this.radiusMm;
    this.uniforms.tQuadrant.value = this.energyLookup.texture;
    this.uniforms.quadrantRangeMm.value = this.energyLookup.rangeMm;
  }

  dispose() {
    super.dispose();
    if (this._ownsLookup) this.energyLookup.dispose();
  }
}

nameClass(DenseSubsurfacePass, 'DenseSubsurfacePass'); // its name in messages, minified or not
