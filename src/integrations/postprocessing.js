// three-separable-sss/postprocessing: the pipeline as a Pass of pmndrs `postprocessing`'s
// EffectComposer, in place of its RenderPass:
//   const composer = new EffectComposer(renderer, { frameBufferType: HalfFloatType });
//   const sss = new SubsurfaceScatteringPass({ scene, camera, light, worldUnitInMm: 1000 });
//   sss.makeSubsurface(skinMaterial);
//   composer.addPass(sss);                                   // instead of new RenderPass(scene, camera)
//   composer.addPass(new EffectPass(camera, new BloomEffect(), new ToneMappingEffect()));
//
// SSS cannot be one of pmndrs's Effects: an Effect is a fragment function over the image, and the
// pipeline needs its own draws of the scene (the split into diffuse light, depth and width). So it
// is a Pass that behaves like pmndrs's RenderPass: it renders the scene into the composer's input
// buffer (needsSwap false), leaves the scene's depth in that buffer's depth attachment and asks
// the composer to blit it (needsDepthBlit), so EffectPass effects that read depth (SSAO, depth of
// field) see the scene. The work is the three.js pass's (src/SubsurfaceScattering.js): this file
// only adapts pmndrs's calling convention, render(renderer, inputBuffer, outputBuffer, deltaTime,
// stencilTest), initialize(renderer, alpha, frameBufferType), setSize, setDepthTexture, dispose.
//
// The light it writes is linear HDR (the tone mapping comes last, e.g. a ToneMappingEffect), so
// the composer's buffers must be half-float: pmndrs's default 8-bit buffers would clamp it at 1
// and, with an sRGB output, store linear values where sRGB ones are expected. initialize() throws
// a RangeError naming the fix instead of rendering that.
import { Pass } from 'postprocessing';
import { FloatType, HalfFloatType, UnsignedByteType } from 'three';
import { SubsurfaceScattering } from '../index.js';
import { booleanFields } from '../support/booleanFields.js';

/** The frame buffer types whose range holds linear HDR light. */
const HDR_TYPES = Object.freeze([HalfFloatType, FloatType]);

function typeName(type) {
  return type === UnsignedByteType ? 'THREE.UnsignedByteType (8-bit)' : `${type} (not THREE.HalfFloatType or THREE.FloatType)`;
}

export class SubsurfaceScatteringPass extends Pass {
  /** @param {import('../options.js').SubsurfaceScatteringOptions} options as for SubsurfaceScattering */
  constructor(options) {
    // The pipeline checks the options (TypeError naming the one that is wrong) before pmndrs's
    // Pass would substitute a scene and camera of its own for missing ones.
    const pipeline = new SubsurfaceScattering(options);
    super('SubsurfaceScatteringPass', pipeline.scene, pipeline.camera);
    /** The three.js pass doing the work: every setting of SubsurfaceScattering is on it. */
    this.pipeline = pipeline;
    this.needsSwap = false; // like pmndrs's RenderPass: the scene goes into the input buffer
    this.needsDepthBlit = true; // the input buffer holds the scene's depth after render()
  }

  // `scene` and `camera` stay pmndrs Pass's plain properties (assignable, read every frame): render()
  // hands them to the pipeline.

  /** EffectComposer.setMainScene sets this, as for its RenderPass. @param {import('three').Scene} scene */
  set mainScene(scene) {
    this.scene = this.pipeline.scene = scene;
  }

  /** EffectComposer.setMainCamera sets this, as for its RenderPass. @param {import('three').Camera} camera */
  set mainCamera(camera) {
    this.camera = this.pipeline.camera = camera;
  }

  /** As pmndrs's RenderPass: true clears the input buffer first, false draws over it. @type {boolean} */
  get clear() {
    return this.pipeline.clear;
  }

  set clear(clear) {
    this.pipeline.clear = clear;
  }

  /**
   * Makes `material` scatter with this pass's profile, scale and light (SubsurfaceScattering.makeSubsurface).
   * @param {import('three').MeshStandardMaterial} material
   * @param {import('../options.js').SubsurfaceMaterialOptions} [options]
   */
  makeSubsurface(material, options) {
    return this.pipeline.makeSubsurface(material, options);
  }

  /** The scene's depth from the last frame, a DepthTexture (the pipeline's). */
  getDepthTexture() {
    return this.pipeline.depthTexture;
  }

  /**
   * Checks the composer's buffers: 8-bit ones cannot hold the linear HDR light this pass writes.
   * @param {import('three').WebGLRenderer} renderer
   * @param {boolean} alpha
   * @param {number} frameBufferType
   */
  initialize(renderer, alpha, frameBufferType) {
    if (frameBufferType !== undefined && !HDR_TYPES.includes(frameBufferType)) {
      throw new RangeError(
        `SubsurfaceScatteringPass: the EffectComposer's frameBufferType is ${typeName(frameBufferType)}; ` +
        'the pass writes linear HDR light, which such buffers clamp and band: create the composer with ' +
        '{ frameBufferType: THREE.HalfFloatType } and tone-map last (e.g. a ToneMappingEffect)');
    }
  }

  /**
   * One frame into `inputBuffer` (or the screen when it is the composer's last pass).
   * @param {import('three').WebGLRenderer} renderer
   * @param {import('three').WebGLRenderTarget|null} inputBuffer
   * @param {import('three').WebGLRenderTarget|null} outputBuffer unused (needsSwap is false)
   * @param {number} [deltaTime]
   * @param {boolean} [stencilTest]
   */
  render(renderer, inputBuffer, outputBuffer, deltaTime, stencilTest) {
    this.pipeline.scene = this.scene;
    this.pipeline.camera = this.camera;
    this.pipeline.renderToScreen = this.renderToScreen;
    this.pipeline.render(renderer, null, inputBuffer);
  }

  /** @param {number} width device pixels @param {number} height device pixels */
  setSize(width, height) {
    this.pipeline.setSize(width, height);
  }

  /** Frees the pipeline's targets and gives its materials back their own shaders. */
  dispose() {
    this.pipeline.dispose();
  }
}

// pmndrs Pass's plain boolean fields take booleans only here (`enabled = 'no'` would count as true).
booleanFields(SubsurfaceScatteringPass.prototype, ['enabled', 'needsSwap', 'needsDepthBlit']);
