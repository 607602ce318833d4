// three-separable-sss/postprocessing: the pipeline as a pmndrs `postprocessing` Pass, in place of
// its RenderPass:
//   const composer = new EffectComposer(renderer, { frameBufferType: HalfFloatType });
//   const sss = new SubsurfaceScatteringPass({ scene, camera, light, worldUnitInMm: 1000 });
//   sss.makeSubsurface(skinMaterial);
//   composer.addPass(sss);
//   composer.addPass(new EffectPass(camera, new ToneMappingEffect()));
// Not an Effect: an Effect is a function over the image, and the pipeline draws the scene itself.
// Like RenderPass it renders into the input buffer and has its depth blitted, so depth-reading
// effects see the scene. The light is linear HDR: 8-bit buffers would clamp it, so initialize()
// refuses them. The work is src/SubsurfaceScattering.js's; this adapts the calling convention.
import { Pass } from 'postprocessing';
import { FloatType, HalfFloatType, UnsignedByteType } from 'three';
import { SubsurfaceScattering } from '../index.js';
import { booleanFields } from '../support/booleanFields.js';
import { nameClass } from '../support/className.js';

/** The frame buffer types whose range holds linear HDR light. */
const HDR_TYPES = Object.freeze([HalfFloatType, FloatType]);

function typeName(type) {
  return type === UnsignedByteType ? 'THREE.UnsignedByteType (8-bit)' : `${type} (not THREE.HalfFloatType or THREE.FloatType)`;
}

export class SubsurfaceScatteringPass extends Pass {
  /** @param {import('../options.js').SubsurfaceScatteringOptions} options as for SubsurfaceScattering */
  constructor(options) {
    // Checked before pmndrs's Pass would substitute a scene and camera of its own for missing ones.
    const pipeline = new SubsurfaceScattering(options);
    super('SubsurfaceScatteringPass', pipeline.scene, pipeline.camera);
    /** The three.js pass doing the work, with every setting. */
    this.pipeline = pipeline;
    this.needsSwap = false;
    this.needsDepthBlit = true;
  }

  /** EffectComposer.setMainScene sets this. @param {import('three').Scene} scene */
  set mainScene(scene) {
    this.scene = this.pipeline.scene = scene;
  }

  /** EffectComposer.setMainCamera sets this. @param {import('three').Camera} camera */
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
   * SubsurfaceScattering.makeSubsurface.
   * @param {import('three').MeshStandardMaterial} material
   * @param {import('../options.js').SubsurfaceMaterialOptions} [options]
   */
  makeSubsurface(material, options) {
    return this.pipeline.makeSubsurface(material, options);
  }

  /** The scene's depth from the last frame. */
  getDepthTexture() {
    return this.pipeline.depthTexture;
  }

  /**
   * Refuses 8-bit buffers.
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

booleanFields(SubsurfaceScatteringPass.prototype, ['enabled', 'needsSwap', 'needsDepthBlit']);

nameClass(SubsurfaceScatteringPass, 'SubsurfaceScatteringPass'); // its name in messages, minified or not
