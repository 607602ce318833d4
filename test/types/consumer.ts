// A strict TypeScript consumer of every export (test/packaging/types.test.js compiles it against the
// declarations generated from the JSDoc, installed as a package). It must compile with no error;
// test/packaging/types.test.js also checks that ALL_EXPORTS names every value the package exports,
// ALL_STAGES every value of three-separable-sss/stages and ALL_INTERNALS every value of the
// unstable three-separable-sss/internals entry.
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import * as SSS from 'three-separable-sss';
import * as STAGES from 'three-separable-sss/stages';
import * as INTERNALS from 'three-separable-sss/internals';
import {
  SubsurfaceScattering,
  type DebugView, type Method, type FollowSurfaceMode, type ProfileName, type SubsurfaceScatteringOptions,
  type SubsurfaceMaterialOptions, type SubsurfaceBinding, type StageName,
} from 'three-separable-sss';
import { makeSubsurface, getSubsurface, LightDepthTarget, ProfileLookup, computeKernel } from 'three-separable-sss/stages';

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(30, 16 / 9, 0.01, 10);
const light = new THREE.SpotLight(0xffffff, 30);
const skin = new THREE.MeshPhysicalMaterial({ color: 0xe0b8a0 });

// The pipeline and its options: every enumerated option is a string-literal union.
const method: Method = 'footprint';
const follow: FollowSurfaceMode = 'drop';
const profile: ProfileName = 'skinBurley';
const options: SubsurfaceScatteringOptions = { scene, camera, light, worldUnitInMm: 1000, profile, method, followSurface: follow, samples: 'auto', multisampling: 4 };
const sss = new SubsurfaceScattering(options);
const materialOptions: SubsurfaceMaterialOptions = { widthMm: 1, widthScale: 0.8, transmittance: true };
const binding: SubsurfaceBinding = sss.makeSubsurface(skin, materialOptions);
const width: number = binding.widthWorld;
// A material of another profile in the same pipeline (up to MAX_PROFILES).
const marbleOptions: SubsurfaceMaterialOptions = { profile: 'marble', widthMm: 1 };
const slot: number = sss.makeSubsurface(new THREE.MeshStandardMaterial(), marbleOptions).profileSlot;
// One setter style: every setting is a property, checked on assignment.
sss.debugView = 'mask';
sss.debugThicknessRangeMm = 5;
sss.debugDepthRange = 2;
const views: readonly DebugView[] = SSS.DEBUG_VIEWS;
const view: DebugView = sss.debugView;
const light0: THREE.Light | readonly THREE.Light[] | 'castShadow' | null = sss.light;
sss.light = [new THREE.SpotLight(), new THREE.PointLight()]; // up to four, each with its own map
sss.light = 'castShadow';
const profileName: string = sss.profile.name;
const kernelPixels: number = sss.plan.kernelPixels;
sss.split = 0.5;
sss.transmittance = true;
sss.profile = 'marble';
sss.method = 'reference';
sss.samples = 25;
sss.samples = 'auto';
sss.strength = [1, 0.5, 0.25];
sss.falloff = [1, 0.37, 0.3];
sss.followSurface = 'lerp';
sss.depthThresholdMm = 4;
sss.foreshortening = false;
const asked: Method = sss.method;
sss.scattering = false;
sss.enabled = true;
sss.clear = false;
sss.clearColor = 0x000000;
sss.clearAlpha = 1;
sss.multisampling = 'auto';
sss.camera = new THREE.OrthographicCamera();
sss.stageTimer = { begin(stage: StageName) { void stage; }, end() {} };
const depth: THREE.DepthTexture = sss.depthTexture;
const removed: boolean = sss.removeSubsurface(skin);
const composer = new EffectComposer(new THREE.WebGLRenderer(), new THREE.WebGLRenderTarget(1, 1, { type: THREE.HalfFloatType }));
composer.addPass(sss);
sss.setSize(640, 360);
sss.dispose();

// The stages on their own.
const lightDepth = new LightDepthTarget(light, { size: 512 });
const lookup = new ProfileLookup('skin');
const kernel: Float32Array = computeKernel({ samples: 17, method: 'reference' });
const hook = makeSubsurface(new THREE.MeshStandardMaterial(), { widthMm: 2, worldUnitInMm: 1000, transmittance: { lightDepth, lookup } });
const bound: SubsurfaceBinding | undefined = getSubsurface(skin);
hook.dispose();

/** Every value of the unstable internals entry, each used where its type is checked. */
export const ALL_INTERNALS = {
  METHOD_TABLE: INTERNALS.METHOD_TABLE.footprint.blur satisfies 'footprint',
  AUTO_SAMPLES: INTERNALS.AUTO_SAMPLES satisfies readonly number[],
  AUTO_REACH: INTERNALS.AUTO_REACH satisfies number,
  PIPELINE_SCHEMA: INTERNALS.PIPELINE_SCHEMA.worldUnitInMm.doc satisfies string,
  MATERIAL_SCHEMA: INTERNALS.MATERIAL_SCHEMA.widthMm.default,
  NODE_SCHEMA: INTERNALS.NODE_SCHEMA.samples.doc satisfies string,
  PIPELINE_OPTIONS: INTERNALS.PIPELINE_OPTIONS satisfies readonly string[],
  MATERIAL_OPTIONS: INTERNALS.MATERIAL_OPTIONS satisfies readonly string[],
  checkPipelineOptions: INTERNALS.checkPipelineOptions({ scene, camera }),
  checkMaterialOptions: INTERNALS.checkMaterialOptions({ widthMm: 2 }),
  planBlur: INTERNALS.planBlur({ method: 'footprint', samples: 'auto', scattering: true, marginalRadiusMm: 3, denseRadiusMm: 0, kernelReachMm: {} }, 2).samples satisfies number,
  autoSampleCount: INTERNALS.autoSampleCount(4) satisfies number,
  BLUR_MODES: INTERNALS.BLUR_MODES.taps.passes,
  estimatePixelsPerMm: INTERNALS.estimatePixelsPerMm([], camera, { width: 640, height: 360 }, () => 0.001) satisfies number,
  nearestViewDepth: INTERNALS.nearestViewDepth,
  MIN_KERNEL_PIXELS: INTERNALS.MIN_KERNEL_PIXELS satisfies number,
  BlurStage: INTERNALS.BlurStage,
  useDenseReference: INTERNALS.useDenseReference satisfies (pipeline: SubsurfaceScattering, enabled?: boolean) => unknown,
  DenseSubsurfacePass: new INTERNALS.DenseSubsurfacePass({ camera, surfaceTexture: depth, profile: 'skin' }).profile,
  DRAW_PHASES: INTERNALS.DRAW_PHASES.SPLIT satisfies 'split',
  footprintsOf: INTERNALS.footprintsOf(kernel).edgesMm satisfies number[],
  KERNEL_MODES: INTERNALS.KERNEL_MODES,
  FootprintTable: new INTERNALS.FootprintTable(new ProfileLookup('skin')).update('auto') satisfies THREE.DataTexture,
  footprintAllocation: INTERNALS.footprintAllocation((x: number) => [x, x, x], 17, 2).stepError satisfies number,
  footprintTable: INTERNALS.footprintTable((x: number) => [x, x, x], 17).columns satisfies number,
  FOOTPRINT_SCALES: INTERNALS.FOOTPRINT_SCALES.perOctave satisfies number,
  QuadrantEnergyLookup: new INTERNALS.QuadrantEnergyLookup('skin').texture satisfies THREE.DataTexture,
  isPerspective: INTERNALS.isPerspective(camera) satisfies boolean,
  DEBUG_VIEW: INTERNALS.DEBUG_VIEW.MASK satisfies 'mask',
  SUPPORTED_THREE: INTERNALS.SUPPORTED_THREE.oldest satisfies number,
  SUPPORTED_THREE_RANGE: INTERNALS.SUPPORTED_THREE_RANGE satisfies string,
  WEBGPU_THREE: INTERNALS.WEBGPU_THREE.oldest satisfies number,
  WEBGPU_THREE_RANGE: INTERNALS.WEBGPU_THREE_RANGE satisfies string,
};

/** Every value of the stages entry (a pipeline built by hand), each used where its type is checked. */
export const ALL_STAGES = {
  LightDepthTarget: lightDepth.texture satisfies THREE.Texture,
  SubsurfaceScenePass: new STAGES.SubsurfaceScenePass(scene, camera).depthTexture satisfies THREE.DepthTexture,
  makeSubsurface: STAGES.makeSubsurface satisfies typeof makeSubsurface,
  getSubsurface: bound,
  MATERIAL_OUTPUTS: STAGES.MATERIAL_OUTPUTS satisfies readonly ('diffuse' | 'transmittance' | 'thickness')[],
  ATTACHMENTS: STAGES.ATTACHMENTS.DIFFUSE satisfies 1,
  transmittanceChunk: STAGES.transmittanceChunk satisfies string,
  createTransmittanceUniforms: STAGES.createTransmittanceUniforms({ lightDepth, lookup, worldUnitInMm: 1000 }).update(camera),
  transmittanceUniformSlots: STAGES.transmittanceUniformSlots().sssShrinkWorld.value satisfies number,
  SubsurfaceBlurPass: new STAGES.SubsurfaceBlurPass({ direction: 'horizontal', kernel, camera, surfaceTexture: depth }).radiusMm satisfies number,
  computeKernel: kernel,
  kernelRadiusMm: STAGES.kernelRadiusMm(kernel) satisfies number,
  referenceKernel: STAGES.referenceKernel(11) satisfies Float32Array,
  ProfileLookup: lookup.marginalRadiusMm satisfies number,
  pixelsPerMm: STAGES.pixelsPerMm(0.001, 0.6, 2, 720) satisfies number,
  SubsurfaceComposePass: STAGES.SubsurfaceComposePass,
};

/** Every value the package's main entry exports, each used where its type is checked. */
export const ALL_EXPORTS = {
  SubsurfaceScattering: SSS.SubsurfaceScattering satisfies typeof SubsurfaceScattering,
  PIPELINE_DEFAULTS: SSS.PIPELINE_DEFAULTS.method satisfies Method,
  MATERIAL_DEFAULTS: SSS.MATERIAL_DEFAULTS.widthMm satisfies number,
  METHODS: SSS.METHODS satisfies readonly Method[],
  FOLLOW_SURFACE_MODES: SSS.FOLLOW_SURFACE_MODES satisfies readonly FollowSurfaceMode[],
  DEBUG_VIEWS: views,
  MAX_PROFILES: SSS.MAX_PROFILES satisfies number,
  profiles: SSS.profiles.skin,
  getProfile: SSS.getProfile('milk'),
  transmittance: SSS.transmittance(1)[0] satisfies number,
  burleyProfile: SSS.burleyProfile({ scatterDistanceMm: [1, 0.5, 0.25] }),
  dipoleProfile: SSS.dipoleProfile(),
  gaussianSumProfile: SSS.gaussianSumProfile('mine', [{ varianceMm2: 0.1, weights: [1, 1, 1] }]),
  radialProfile: SSS.radialProfile,
};
void [width, slot, removed, asked, view, light0, profileName, kernelPixels];
