// Stage 3's base: a full-screen ShaderPass over the multi-target's diffuse light that follows the
// surface. The separable blur and the dense 2D reference share through it everything but their
// kernels: the camera and the screen scale, the diffuse and surface inputs, the depth rule
// (followSurface), the grazing-angle correction (foreshortening) and the sampling model's numbers.
import { Vector2 } from 'three';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import vertexShader from '../../shaders/common/fullscreen.vert.glsl?raw';
import finiteGlsl from '../../shaders/common/finite.glsl?raw';
import carriedDepthGlsl from '../../shaders/common/carriedDepth.glsl?raw';
import screenScaleGlsl from '../../shaders/common/screenScale.glsl?raw';
import surfaceSampleGlsl from '../../shaders/common/surfaceSample.glsl?raw';
import surfaceSlopeGlsl from '../../shaders/common/surfaceSlope.glsl?raw';
import surfaceTapGlsl from '../../shaders/common/surfaceTap.glsl?raw';
import { assembleGlsl, enumDefines, glslFloat, setDefines } from '../support/glsl.js';
import { checkBoolean, checkNumber, checkOneOf } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { PASS_BOOLEANS, booleanFields } from '../support/booleanFields.js';
import { isPerspective } from '../support/screenScale.js';
import { FOLLOW_SURFACE_MODES, MAX_MULTISAMPLING } from '../options.js';
import { ENERGY_LEFT, MAX_PLANE_SLOPE, MAX_SLOPE, MIN_KERNEL_PIXELS, PLANE_SLOPE_AGREEMENT, SLOPE_FADE } from './samplingModel.js';

/** samplingModel.js's numbers as the GLSL defines the shaders read. */
const SAMPLING_DEFINES = Object.freeze({
  SSS_MIN_KERNEL_PIXELS: glslFloat(MIN_KERNEL_PIXELS),
  SSS_MAX_SLOPE: glslFloat(MAX_SLOPE),
  SSS_PLANE_SLOPE_AGREEMENT: glslFloat(PLANE_SLOPE_AGREEMENT),
  SSS_MAX_PLANE_SLOPE: glslFloat(MAX_PLANE_SLOPE),
  SSS_SLOPE_FADE: glslFloat(SLOPE_FADE),
  SSS_ENERGY_LEFT: glslFloat(ENERGY_LEFT),
  // Several profiles: a texel is on a slot within half the smallest step a resolve makes between
  // two slots (1 / MAX_MULTISAMPLING), so a pixel two profiles share is on neither (surfaceSample.glsl).
  SSS_SLOT_TOLERANCE: glslFloat(0.5 / MAX_MULTISAMPLING),
  // and its slots' spread (mean slot² − mean slot²) within half the least a shared pixel has: a
  // share w = 1 / MAX_MULTISAMPLING of two slots one apart, w (1 − w). Slots 0 and 2 half and half
  // average to 1 but spread by 1: on neither, not on slot 1.
  SSS_SLOT_SPREAD_TOLERANCE: glslFloat(0.5 * (1 / MAX_MULTISAMPLING) * (1 - 1 / MAX_MULTISAMPLING)),
});

/** The chunks every surface pass includes: finiteness, the carried depth, screen scale, reading the surface, its slope, the tap rule. */
const SURFACE_CHUNKS = Object.freeze({
  'common/finite.glsl': finiteGlsl,
  'common/carriedDepth.glsl': carriedDepthGlsl,
  'common/screenScale.glsl': screenScaleGlsl,
  'common/surfaceSample.glsl': surfaceSampleGlsl,
  'common/surfaceSlope.glsl': surfaceSlopeGlsl,
  'common/surfaceTap.glsl': surfaceTapGlsl,
});

/**
 * A surface pass's fragment shader: `source` with SURFACE_CHUNKS and `chunks` included (assembleGlsl).
 * @param {string} name @param {string} source @param {Record<string, string>} [chunks]
 */
export function assembleSurfaceGlsl(name, source, chunks = {}) {
  return assembleGlsl(name, source, { ...SURFACE_CHUNKS, ...chunks });
}

export class SurfacePass extends ShaderPass {
  /**
   * @param {object} shader
   * @param {string} shader.name the pass's name (messages, three's material name)
   * @param {string} shader.fragmentShader GLSL with `#include "…"` lines
   * @param {Record<string, string>} [shader.chunks] the chunks it includes besides SURFACE_CHUNKS (see assembleGlsl)
   * @param {object} [shader.defines] the subclass's own defines
   * @param {object} [shader.uniforms] the subclass's own uniforms
   * @param {object} options
   * @param {import('three').Camera} options.camera the camera the scene was rendered with (read every frame)
   * @param {import('three').Texture} options.surfaceTexture the multi-target's surface attachment
   * @param {import('three').Texture|null} [options.diffuseTexture=null] the light to blur; null reads the composer's read buffer
   * @param {'drop'|'lerp'|'off'} [options.followSurface='drop'] what a tap on another surface does
   * @param {number} [options.depthThresholdWorld=0.006] depth difference (world units) at which a tap
   *   counts fully as another surface
   * @param {boolean} [options.foreshortening=true] grazing angles: shrink the step by cos(tilt) of the
   *   surface along each axis and compare depths with the local plane
   */
  constructor({ name, fragmentShader, chunks = {}, defines = {}, uniforms = {} }, {
    camera, surfaceTexture, diffuseTexture = null, followSurface = 'drop', depthThresholdWorld = 0.006, foreshortening = true,
  }) {
    if (!camera || camera.isCamera !== true) throw new TypeError(`${name}: camera must be a THREE.Camera, got ${describe(camera)}`);
    if (!surfaceTexture || surfaceTexture.isTexture !== true) {
      throw new TypeError(`${name}: surfaceTexture must be a THREE.Texture, got ${describe(surfaceTexture)}`);
    }
    super({
      name,
      defines: { ...SAMPLING_DEFINES, ...enumDefines('FOLLOW_SURFACE', FOLLOW_SURFACE_MODES, 'drop'), FORESHORTEN: 1, SSS_COVERAGE: 0, SSS_LIGHT_CARRIES_DEPTH: 0, PROFILE_COUNT: 1, ...defines },
      uniforms: {
        tDiffuse: { value: null },
        tSurface: { value: null },
        tCoverage: { value: null }, // setLightCarriesDepth, with MSAA
        projectionScale: { value: new Vector2(1, 1) },
        resolution: { value: new Vector2(1, 1) },
        viewOrigin: { value: new Vector2(0, 0) },
        depthFalloff: { value: 1 },
        perspective: { value: true },
        ...uniforms,
      },
      vertexShader,
      fragmentShader: assembleSurfaceGlsl(name, fragmentShader, chunks),
    });
    this.uniforms.tSurface.value = surfaceTexture; // after super: ShaderPass clones the textures it is given
    /** The camera the scene was rendered with; its projection is read every frame. */
    this.camera = camera;
    this.diffuseTexture = diffuseTexture;
    this.setFollowSurface(followSurface, depthThresholdWorld);
    this.setForeshortening(foreshortening);
    this.multisampled = false;
    this.lightCarriesDepth = false;
    this._viewportScale = [1, 1]; // the view's viewport over its rectangle (setView)
  }

  /**
   * Whether the light this pass reads carries the depth in its alpha
   * (shaders/common/carriedDepth.glsl: the multi-target's diffuse without MSAA,
   * SubsurfaceScenePass.diffuseCarriesDepth, or the horizontal blur's output): each tap then
   * fetches one texel, not two. Off (the default): the alpha is the
   * mask (the coverage with MSAA) and the depth is read from the surface.
   * @param {boolean} enabled
   * @param {import('three').Texture|null} [coverage=null] with MSAA: a texture whose alpha is the
   *   coverage (the multi-target's diffuse), since the light's alpha then holds the depth
   */
  setLightCarriesDepth(enabled, coverage = null) {
    checkBoolean(`${this.material.name}.setLightCarriesDepth enabled`, enabled);
    if (coverage !== null && coverage?.isTexture !== true) throw new TypeError(`${this.material.name}: setLightCarriesDepth's coverage must be a THREE.Texture or null, got ${describe(coverage)}`);
    setDefines(this.material, { SSS_LIGHT_CARRIES_DEPTH: enabled ? 1 : 0 });
    this.uniforms.tCoverage.value = coverage;
    this.lightCarriesDepth = enabled;
  }

  /** The light to blur: a texture, or null for the composer's read buffer. */
  set diffuseTexture(texture) {
    this._diffuseTexture = texture;
    this.uniforms.tDiffuse.value = texture;
    this.textureID = texture ? null : 'tDiffuse'; // ShaderPass wires readBuffer only to textureID
  }

  get diffuseTexture() {
    return this._diffuseTexture;
  }

  /**
   * @param {'drop'|'lerp'|'off'} mode
   * @param {number} depthThresholdWorld world units, > 0
   */
  setFollowSurface(mode, depthThresholdWorld = this.depthThresholdWorld) {
    checkOneOf('followSurface', mode, FOLLOW_SURFACE_MODES);
    checkNumber('depthThresholdWorld', depthThresholdWorld, { min: 0, minExclusive: true, unit: 'world units' });
    setDefines(this.material, enumDefines('FOLLOW_SURFACE', FOLLOW_SURFACE_MODES, mode));
    this.followSurface = mode;
    this.depthThresholdWorld = depthThresholdWorld;
    this.uniforms.depthFalloff.value = 1 / depthThresholdWorld;
  }

  /** @param {boolean} enabled the grazing-angle correction (see the constructor) */
  setForeshortening(enabled) {
    if (typeof enabled !== 'boolean') throw new TypeError(`${this.material.name}: foreshortening must be a boolean, got ${describe(enabled)}`);
    setDefines(this.material, { FORESHORTEN: enabled ? 1 : 0 });
    this.foreshortening = enabled;
  }

  /**
   * @param {boolean} multisampled the inputs were rendered with MSAA and resolved: their alpha is the
   *   coverage, their colour, depth and width premultiplied by it (shaders/common/surfaceSample.glsl)
   */
  setMultisampled(multisampled) {
    if (typeof multisampled !== 'boolean') throw new TypeError(`${this.material.name}: multisampled must be a boolean, got ${describe(multisampled)}`);
    setDefines(this.material, { SSS_COVERAGE: multisampled ? 1 : 0 });
    this.multisampled = multisampled;
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.setView({ x: 0, y: 0, width, height });
  }

  /**
   * The view the pass blurs (device pixels): the whole frame (setSize), or one of an ArrayCamera's
   * views (src/support/cameraViews.js): taps and slopes stay inside `rect` as inside the frame
   * (its edges are the screen's), and a profile mm spans what it spans in `viewport` (NDC spans
   * it; `rect` is its part inside the target).
   * @param {{ x: number, y: number, width: number, height: number }} rect
   * @param {{ width: number, height: number }} [viewport=rect]
   */
  setView(rect, viewport = rect) {
    this.uniforms.viewOrigin.value.set(rect.x, rect.y);
    this.uniforms.resolution.value.set(rect.width, rect.height);
    // The shaders scale by projectionScale × resolution: the viewport's size times the projection's.
    this._viewportScale = [viewport.width / rect.width, viewport.height / rect.height];
  }

  render(renderer, writeBuffer, readBuffer, deltaTime, maskActive) {
    const projection = this.camera.projectionMatrix.elements;
    const [sx, sy] = this._viewportScale;
    this.uniforms.projectionScale.value.set(projection[0] * sx, projection[5] * sy);
    this.uniforms.perspective.value = isPerspective(this.camera);
    super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
  }
}

booleanFields(SurfacePass.prototype, PASS_BOOLEANS);
