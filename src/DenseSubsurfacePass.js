// The dense 2D reference of the subsurface blur, as a ShaderPass: brute-force screen-space
// convolution with the full radial profile (not separable), for validation and the speed-accuracy
// bench, not for production (its cost grows with the square of the on-screen kernel radius).
// It replaces the two blurs: [SubsurfaceScenePass, DenseSubsurfacePass, SubsurfaceComposePass].
// Same units, mask and depth rules as SubsurfaceBlurPass; see shaders/denseSubsurface.frag.glsl.
import { Vector2 } from 'three';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../shaders/fullscreen.vert.glsl?raw';
import denseGlsl from '../shaders/denseSubsurface.frag.glsl?raw';
import quadrantEnergyGlsl from '../shaders/quadrantEnergy.glsl?raw';
import surfaceSlopeGlsl from '../shaders/surfaceSlope.glsl?raw';
import finiteGlsl from '../shaders/finite.glsl?raw';
import { QuadrantEnergyLookup } from './QuadrantEnergyLookup.js';
import { SubsurfaceBlurPass } from './SubsurfaceBlurPass.js';
import { getProfile } from './profiles.js';
import { checkInteger, checkNumber } from './parameterChecks.js';
import { describe } from './rendererSupport.js';

const fragmentShader = denseGlsl.replace('QUADRANT_ENERGY_GLSL', quadrantEnergyGlsl).replace('SURFACE_SLOPE_GLSL', surfaceSlopeGlsl)
  .replace('FINITE_GLSL', finiteGlsl);

export class DenseSubsurfacePass extends ShaderPass {
  /**
   * @param {object} options
   * @param {import('three').Camera} options.camera the camera the scene was rendered with
   * @param {import('three').Texture} options.surfaceTexture the scene pass's surface attachment
   *   (r: linear view depth in world units, g: world units per profile mm, 0 off subsurface pixels)
   * @param {import('three').Texture|null} [options.diffuseTexture=null] the scene pass's diffuse
   *   attachment (alpha: the mask); null reads the composer's read buffer
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
  constructor({
    camera, surfaceTexture, diffuseTexture = null, profile = 'skin', energyLookup = null, coverage = 0.997,
    followSurface = 'drop', depthThresholdWorld = 0.006, foreshortening = true, maxRadiusPx = 128,
  } = {}) {
    if (!camera || camera.isCamera !== true) throw new TypeError(`DenseSubsurfacePass: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (!surfaceTexture || surfaceTexture.isTexture !== true) {
      throw new TypeError(`DenseSubsurfacePass: surfaceTexture must be a THREE.Texture, got ${describe(surfaceTexture)}`);
    }
    if (energyLookup !== null && !(energyLookup instanceof QuadrantEnergyLookup)) {
      throw new TypeError(`DenseSubsurfacePass: energyLookup must be a QuadrantEnergyLookup or null, got ${describe(energyLookup)}`);
    }
    checkInteger('maxRadiusPx', maxRadiusPx, 1, 4096, 'pixels');
    super({
      name: 'DenseSubsurfacePass',
      defines: { FOLLOW_SURFACE: 1, FORESHORTEN: 1 },
      uniforms: {
        tDiffuse: { value: null },
        tSurface: { value: null },
        tQuadrant: { value: null },
        quadrantRangeMm: { value: 1 },
        radiusMm: { value: 0 },
        projectionScale: { value: new Vector2(1, 1) },
        resolution: { value: new Vector2(1, 1) },
        depthFalloff: { value: 1 },
        perspective: { value: true },
        maxRadiusPx: { value: maxRadiusPx },
      },
      vertexShader,
      fragmentShader,
    });
    this.uniforms.tSurface.value = surfaceTexture; // after super: ShaderPass clones the textures it is given
    this.camera = camera;
    this._ownsLookup = energyLookup === null;
    this.energyLookup = energyLookup ?? new QuadrantEnergyLookup(profile);
    this.coverage = coverage;
    this.diffuseTexture = diffuseTexture;
    this.setCoverage(coverage);
    this.setFollowSurface(followSurface, depthThresholdWorld);
    this.setForeshortening(foreshortening);
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

  // The blur's setters, shared so the two cannot drift apart (same define and uniform names).

  /**
   * @param {'drop'|'lerp'|'off'} mode
   * @param {number} depthThresholdWorld world units, > 0
   */
  setFollowSurface(mode, depthThresholdWorld = this.depthThresholdWorld) {
    SubsurfaceBlurPass.prototype.setFollowSurface.call(this, mode, depthThresholdWorld);
  }

  /** @param {boolean} enabled the grazing-angle correction (see the constructor) */
  setForeshortening(enabled) {
    SubsurfaceBlurPass.prototype.setForeshortening.call(this, enabled);
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.uniforms.resolution.value.set(width, height);
  }

  render(renderer, writeBuffer, readBuffer, deltaTime, maskActive) {
    const projection = this.camera.projectionMatrix.elements;
    this.uniforms.projectionScale.value.set(projection[0], projection[5]);
    this.uniforms.perspective.value = this.camera.isPerspectiveCamera === true || projection[15] === 0;
    super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
  }

  dispose() {
    super.dispose();
    if (this._ownsLookup) this.energyLookup.dispose();
  }
}

// `diffuseTexture` (null: the composer's read buffer; a texture: that one) works as the blur's.
Object.defineProperty(DenseSubsurfacePass.prototype, 'diffuseTexture', Object.getOwnPropertyDescriptor(SubsurfaceBlurPass.prototype, 'diffuseTexture'));
