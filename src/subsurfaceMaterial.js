// Stage 2: the material hook. Patches a MeshStandardMaterial or MeshPhysicalMaterial through
// onBeforeCompile so that, when drawn into the subsurface multi-target (SubsurfaceScenePass), it
// writes the diffuse light (direct + indirect, plus transmittance) to location 1, linear view
// depth and scattering width to location 2, and keeps specular + emissive at location 0.
// Drawn anywhere else it renders exactly as before, plus transmittance when enabled.
import { LessEqualDepth, Matrix4, Vector3 } from 'three';
import parsGlsl from '../shaders/subsurfaceMaterial/pars.glsl?raw';
import depthOnlyGlsl from '../shaders/subsurfaceMaterial/depthOnly.glsl?raw';
import transmittedLightGlsl from '../shaders/subsurfaceMaterial/transmittedLight.glsl?raw';
import splitGlsl from '../shaders/subsurfaceMaterial/split.glsl?raw';
import clearcoatGlsl from '../shaders/subsurfaceMaterial/clearcoat.glsl?raw';
import outputGlsl from '../shaders/subsurfaceMaterial/output.glsl?raw';
import finiteGlsl from '../shaders/finite.glsl?raw';
import profileLookupGlsl from '../shaders/profileLookup.glsl?raw';
import transmittanceGlsl from '../shaders/transmittance.glsl?raw';
import { checkNumber, checkOneOf } from './parameterChecks.js';
import { describe } from './rendererSupport.js';
import { LightDepthTarget } from './LightDepthTarget.js';
import { ProfileLookup } from './ProfileLookup.js';

/**
 * The GLSL chunk computing transmittance from a LightDepthTarget and a ProfileLookup
 * (shaders/profileLookup.glsl + shaders/transmittance.glsl); its uniforms come from
 * createTransmittanceUniforms.
 */
export const transmittanceChunk = `${profileLookupGlsl}\n${transmittanceGlsl}`;

/**
 * Render targets carrying this flag are the subsurface multi-target; their `subsurfacePhase` tells
 * hooked materials what to write: 'depth' (depth only), 'split' (diffuse / specular / surface) or
 * 'plain' (their usual colour, e.g. when transparent).
 */
export const SUBSURFACE_TARGET_FLAG = 'isSubsurfaceTarget';

const hooks = new WeakMap();
const DEBUG_OUTPUTS = ['diffuse', 'transmittance', 'thickness'];

const _position = new Vector3();
const _direction = new Vector3();

/** Replaces `needle` in `source`, failing loudly if three's shader no longer has it. */
function inject(source, needle, replacement) {
  if (!source.includes(needle)) {
    throw new Error(`makeSubsurface: "${needle}" not found in the material's shader; this three.js version is not supported`);
  }
  return source.replace(needle, replacement);
}

/**
 * The uniform objects `transmittanceChunk` reads, with neutral values. A hooked material owns one
 * set for its whole life: three keeps the uniform objects of a program's first compile when it
 * switches back to that program, so they must never be replaced.
 */
export function transmittanceUniformSlots() {
  return {
    sssLightDepthMap: { value: null },
    sssViewToLightView: { value: new Matrix4() },
    sssLightProjection: { value: new Matrix4() },
    sssShrinkWorld: { value: 0 },
    sssProfileLookup: { value: null },
    sssTransmittanceRangeMm: { value: 1 },
    sssThicknessToProfileMm: { value: 1 },
  };
}

/**
 * Creates the uniforms of `transmittanceChunk` and a function that refreshes them for a camera.
 * Use it for a custom ShaderMaterial that includes the chunk.
 * @param {object} options
 * @param {LightDepthTarget} options.lightDepth
 * @param {ProfileLookup} options.lookup the profile's tables (row 0: T(d))
 * @param {number} options.worldUnitInMm millimetres per world unit (> 0)
 * @param {number} [options.widthMm=1] profile scale: millimetres of material per profile millimetre
 * @param {number} [options.translucency=0] 0..<1, shortens the thickness by (1 - translucency)
 * @param {number} [options.shrinkMm=0.6] inward shrink along the vertex normal, mm (against acne)
 * @param {object} [uniforms] existing uniform objects to fill (see transmittanceUniformSlots); new ones by default
 * @returns {{ uniforms: object, update(camera: import('three').Camera): void, set(options: object): void }}
 */
export function createTransmittanceUniforms(options, uniforms = transmittanceUniformSlots()) {
  const state = { widthMm: 1, translucency: 0, shrinkMm: 0.6 };
  function set(next) {
    Object.assign(state, Object.fromEntries(Object.entries(next).filter(([, v]) => v !== undefined)));
    if (!(state.lightDepth instanceof LightDepthTarget)) {
      throw new TypeError(`transmittance: lightDepth must be a LightDepthTarget, got ${describe(state.lightDepth)}`);
    }
    if (!(state.lookup instanceof ProfileLookup)) {
      throw new TypeError(`transmittance: lookup must be a ProfileLookup, got ${describe(state.lookup)}`);
    }
    checkNumber('worldUnitInMm', state.worldUnitInMm, { min: 0, minExclusive: true, max: 1e9, unit: 'mm' });
    checkNumber('widthMm', state.widthMm, { min: 0, minExclusive: true, max: 1000, unit: 'mm' });
    checkNumber('translucency', state.translucency, { min: 0, max: 1, maxExclusive: true });
    checkNumber('shrinkMm', state.shrinkMm, { min: 0, max: 1000, unit: 'mm' });
    uniforms.sssLightDepthMap.value = state.lightDepth.texture;
    uniforms.sssProfileLookup.value = state.lookup.texture;
    uniforms.sssShrinkWorld.value = state.shrinkMm / state.worldUnitInMm;
    uniforms.sssThicknessToProfileMm.value = (state.worldUnitInMm * (1 - state.translucency)) / state.widthMm;
  }
  set(options);
  return {
    uniforms,
    set,
    update(camera) {
      const { lightDepth, lookup } = state;
      uniforms.sssViewToLightView.value.multiplyMatrices(lightDepth.camera.matrixWorldInverse, camera.matrixWorld);
      uniforms.sssLightProjection.value.copy(lightDepth.camera.projectionMatrix);
      uniforms.sssTransmittanceRangeMm.value = lookup.transmittanceRangeMm;
    },
  };
}

/**
 * Makes a MeshStandardMaterial or MeshPhysicalMaterial subsurface-scattering (idempotent: a second
 * call updates the options). The material keeps rendering normally outside SubsurfaceScattering.
 * @param {import('three').MeshStandardMaterial} material
 * @param {object} [options]
 * @param {number} [options.widthMm=1] scattering width: millimetres of material per profile
 *   millimetre (1 = the profile's physical size; 0 < widthMm ≤ 1000)
 * @param {number} [options.strength=1] 0..1, scales the width per material (0 = no scattering)
 * @param {number} [options.worldUnitInMm=1000] millimetres per world unit (three.js: metres)
 * @param {object|null} [options.transmittance=null] light through thin parts:
 *   `{ lightDepth: LightDepthTarget, lookup: ProfileLookup, translucency?, shrinkMm? }`
 * @returns {{ uniforms: object, options: object, update(options: object): void, dispose(): void }}
 */
export function makeSubsurface(material, options = {}) {
  if (!material || material.isMeshStandardMaterial !== true) {
    throw new TypeError(`makeSubsurface: material must be a THREE.MeshStandardMaterial or MeshPhysicalMaterial, got ${describe(material)}`);
  }
  // The scene pass draws subsurface materials twice (depth, then everything) and relies on the
  // second draw passing the depth test at equal depth.
  if (material.depthFunc !== LessEqualDepth) {
    throw new RangeError('makeSubsurface: material.depthFunc must be THREE.LessEqualDepth (the default) for the split draw');
  }
  const existing = hooks.get(material);
  if (existing) {
    existing.update(options);
    return existing;
  }

  const uniforms = {
    sssSplit: { value: false },
    sssDepthOnly: { value: false },
    sssWidthWorld: { value: 0 },
    sssStrength: { value: 1 },
    sssDebugOutput: { value: 0 },
    sssLightColor: { value: new Vector3() },
    sssLightPositionView: { value: new Vector3() },
    sssLightDirectionView: { value: new Vector3() },
    sssLightCutoffDistance: { value: 0 },
    sssLightDecay: { value: 2 },
    sssSpotConeCos: { value: 0 },
    sssSpotPenumbraCos: { value: 1 },
    ...transmittanceUniformSlots(),
  };
  let transmittanceUniforms = null; // filled once, kept while transmittance is off: see transmittanceUniformSlots
  const hook = {
    material,
    uniforms,
    options: { widthMm: 1, strength: 1, worldUnitInMm: 1000, transmittance: null },
    /** What the diffuse target receives: 'diffuse' (normal), 'transmittance' or 'thickness' (debug views). */
    set debugOutput(mode) {
      uniforms.sssDebugOutput.value = DEBUG_OUTPUTS.indexOf(checkOneOf('debugOutput', mode, DEBUG_OUTPUTS));
    },
    get debugOutput() {
      return DEBUG_OUTPUTS[uniforms.sssDebugOutput.value];
    },
    transmittance: null,
    update,
    dispose,
  };

  function update(next = {}) {
    const o = { ...hook.options, ...next };
    checkNumber('widthMm', o.widthMm, { min: 0, minExclusive: true, max: 1000, unit: 'mm' });
    checkNumber('strength', o.strength, { min: 0, max: 1 });
    checkNumber('worldUnitInMm', o.worldUnitInMm, { min: 0, minExclusive: true, max: 1e9, unit: 'mm' });
    const hadTransmittance = hook.transmittance !== null;
    const lightType = hook.transmittance?.lightType;
    if (o.transmittance) {
      const t = o.transmittance;
      const settings = { ...t, worldUnitInMm: o.worldUnitInMm, widthMm: o.widthMm };
      if (transmittanceUniforms) transmittanceUniforms.set(settings);
      else transmittanceUniforms = createTransmittanceUniforms(settings, uniforms);
      hook.transmittance = transmittanceUniforms;
      hook.transmittance.lightDepth = t.lightDepth;
      hook.transmittance.lightType = t.lightDepth.light.isSpotLight ? 1 : 0;
    } else {
      hook.transmittance = null;
    }
    uniforms.sssWidthWorld.value = o.widthMm / o.worldUnitInMm;
    uniforms.sssStrength.value = o.strength;
    hook.options = o;
    if (hadTransmittance !== (hook.transmittance !== null) || lightType !== hook.transmittance?.lightType) {
      material.needsUpdate = true; // a different program
    }
  }

  const previous = {
    onBeforeCompile: material.onBeforeCompile,
    customProgramCacheKey: material.customProgramCacheKey,
    onBeforeRender: material.onBeforeRender,
  };

  material.onBeforeCompile = function (shader, renderer) {
    previous.onBeforeCompile.call(this, shader, renderer);
    Object.assign(shader.uniforms, uniforms);
    if (hook.transmittance) {
      shader.defines = { ...shader.defines, SSS_TRANSMITTANCE: '', SSS_LIGHT_TYPE: hook.transmittance.lightType };
    }
    let fs = shader.fragmentShader;
    fs = inject(fs, 'void main() {', `${parsGlsl}\n${finiteGlsl}\n${hook.transmittance ? transmittanceChunk : ''}\nvoid main() {`);
    fs = inject(fs, '#include <alphahash_fragment>', `#include <alphahash_fragment>\n${depthOnlyGlsl}`);
    fs = inject(fs, '#include <lights_fragment_end>', `#include <lights_fragment_end>\n${transmittedLightGlsl}`);
    fs = inject(fs, 'vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;', splitGlsl);
    fs = inject(fs, '#include <opaque_fragment>', `${clearcoatGlsl}\n#include <opaque_fragment>`);
    fs = inject(fs, '#include <dithering_fragment>', `#include <dithering_fragment>\n${outputGlsl}`);
    shader.fragmentShader = fs;
  };

  material.customProgramCacheKey = function () {
    const t = hook.transmittance ? `T${hook.transmittance.lightType}` : '';
    return `${previous.customProgramCacheKey.call(this)}|subsurface${t}`;
  };

  // Per draw: split only inside the subsurface target, and refresh the view-dependent uniforms.
  // Three uploads them once per material per render call, which is all they change at.
  material.onBeforeRender = function (renderer, scene, camera, geometry, object, group) {
    previous.onBeforeRender.call(this, renderer, scene, camera, geometry, object, group);
    const target = renderer.getRenderTarget();
    const phase = target?.[SUBSURFACE_TARGET_FLAG] === true ? target.subsurfacePhase : 'plain';
    uniforms.sssSplit.value = phase === 'split';
    uniforms.sssDepthOnly.value = phase === 'depth';
    if (hook.transmittance) updateLightUniforms(hook, camera);
  };

  hooks.set(material, hook);
  update(options);
  material.needsUpdate = true;

  function dispose() {
    material.onBeforeCompile = previous.onBeforeCompile;
    material.customProgramCacheKey = previous.customProgramCacheKey;
    material.onBeforeRender = previous.onBeforeRender;
    hooks.delete(material);
    material.needsUpdate = true;
  }
  return hook;
}

function updateLightUniforms(hook, camera) {
  const { uniforms } = hook;
  const { lightDepth } = hook.transmittance;
  const light = lightDepth.light;
  hook.transmittance.update(camera);
  const view = camera.matrixWorldInverse;
  // Like three's own lights: a hidden light (or one under a hidden parent) sends nothing.
  let shining = true;
  light.traverseAncestors((a) => { if (!a.visible) shining = false; });
  uniforms.sssLightColor.value.set(light.color.r, light.color.g, light.color.b)
    .multiplyScalar(shining && light.visible ? light.intensity : 0);
  _position.setFromMatrixPosition(light.matrixWorld);
  _direction.setFromMatrixPosition(light.target.matrixWorld);
  // Unit vector from the target towards the light, in view space (three's convention).
  _direction.subVectors(_position, _direction).transformDirection(view);
  uniforms.sssLightDirectionView.value.copy(_direction);
  uniforms.sssLightPositionView.value.copy(_position.applyMatrix4(view));
  if (light.isSpotLight) {
    uniforms.sssLightCutoffDistance.value = light.distance;
    uniforms.sssLightDecay.value = light.decay;
    uniforms.sssSpotConeCos.value = Math.cos(light.angle);
    uniforms.sssSpotPenumbraCos.value = Math.cos(light.angle * (1 - light.penumbra));
  }
}

/**
 * The hook of a material made subsurface, or undefined.
 * @param {import('three').Material} material
 */
export function getSubsurface(material) {
  return hooks.get(material);
}
