// Stage 2: the material hook. Patches a MeshStandardMaterial or MeshPhysicalMaterial through
// onBeforeCompile so that, drawn into the multi-target (src/2-scene-split/subsurfaceTarget.js) in
// the SPLIT phase, it writes its diffuse light (direct + indirect, plus transmittance) to the
// diffuse attachment, linear view depth and scattering width to the surface attachment, and keeps
// specular + emissive in the colour attachment. Drawn anywhere else it renders exactly as before,
// plus transmittance when enabled.
//
// Our GLSL goes in at fixed points of three's MeshStandard/MeshPhysical fragment shader (`inject`,
// which fails loudly when three's shader no longer has the point); the declarations are assembled
// with the library's include resolver like every other shader.
import { LessEqualDepth } from 'three';
import parsGlsl from '../../shaders/2-scene-split/material/pars.glsl?raw';
import depthOnlyGlsl from '../../shaders/2-scene-split/material/depthOnly.glsl?raw';
import transmittedLightGlsl from '../../shaders/2-scene-split/material/transmittedLight.glsl?raw';
import splitGlsl from '../../shaders/2-scene-split/material/split.glsl?raw';
import clearcoatGlsl from '../../shaders/2-scene-split/material/clearcoat.glsl?raw';
import outputGlsl from '../../shaders/2-scene-split/material/output.glsl?raw';
import finiteGlsl from '../../shaders/common/finite.glsl?raw';
import { assembleGlsl, enumDefines } from '../support/glsl.js';
import { checkNumber, checkOneOf } from '../support/parameterChecks.js';
import { describe } from '../support/rendererSupport.js';
import { MATERIAL_DEFAULTS } from '../options.js';
import { ATTACHMENT_DEFINES, DRAW_PHASES, drawPhaseOf } from './subsurfaceTarget.js';
import {
  TRANSMITTANCE_CHUNKS, createTransmittanceUniforms, lightUniformSlots, transmittanceUniformSlots, updateLightUniforms,
} from './transmittance.js';

/** What the diffuse attachment receives: the diffuse light, or one ingredient for a debug view. */
export const MATERIAL_OUTPUTS = Object.freeze(['diffuse', 'transmittance', 'thickness']);

/** The kinds of light transmittance is shaded with (a define: a different program each). */
const LIGHT_TYPES = Object.freeze(['directional', 'spot']);

/** The declarations before main(), with the finiteness check and (behind #ifdef) transmittance. */
const declarations = assembleGlsl('makeSubsurface', parsGlsl, { 'common/finite.glsl': finiteGlsl, ...TRANSMITTANCE_CHUNKS });

const hooks = new WeakMap();

/** Replaces `needle` in `source`, failing loudly if three's shader no longer has it. */
function inject(source, needle, replacement) {
  if (!source.includes(needle)) {
    throw new Error(`makeSubsurface: "${needle}" not found in the material's shader; this three.js version is not supported`);
  }
  return source.replace(needle, replacement);
}

/**
 * The material options with the old name `strength` read as `widthScale` (the name says what it
 * does; `strength` on the pipeline is Jimenez's RGB mix).
 */
function withWidthScale(options) {
  if (options.strength === undefined) return options;
  const { strength, ...rest } = options;
  checkNumber('strength', strength, { min: 0, max: 1 });
  return { widthScale: strength, ...rest };
}

/**
 * Makes a MeshStandardMaterial or MeshPhysicalMaterial subsurface-scattering (idempotent: a second
 * call updates the options). The material keeps rendering normally outside SubsurfaceScattering.
 * @param {import('three').MeshStandardMaterial} material
 * @param {object} [options]
 * @param {number} [options.widthMm=1] scattering width: millimetres of material per profile
 *   millimetre (1 = the profile's physical size; 0 < widthMm ≤ 1000)
 * @param {number} [options.widthScale=1] 0..1, scales the width (0 = no scattering, the light kept);
 *   `strength` is its old name, still accepted
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
    sssWidthScale: { value: 1 },
    sssDebugOutput: { value: 0 },
    ...lightUniformSlots(),
    ...transmittanceUniformSlots(),
  };
  let transmittanceUniforms = null; // filled once, kept while transmittance is off: see transmittanceUniformSlots
  const hook = {
    material,
    uniforms,
    options: { widthMm: MATERIAL_DEFAULTS.widthMm, widthScale: MATERIAL_DEFAULTS.widthScale, worldUnitInMm: 1000, transmittance: null },
    /** What the diffuse attachment receives: one of MATERIAL_OUTPUTS ('diffuse' normally; the others for debug views). */
    set debugOutput(mode) {
      uniforms.sssDebugOutput.value = MATERIAL_OUTPUTS.indexOf(checkOneOf('debugOutput', mode, MATERIAL_OUTPUTS));
    },
    get debugOutput() {
      return MATERIAL_OUTPUTS[uniforms.sssDebugOutput.value];
    },
    transmittance: null,
    update,
    dispose,
  };

  function update(next = {}) {
    const o = { ...hook.options, ...withWidthScale(next) };
    checkNumber('widthMm', o.widthMm, { min: 0, minExclusive: true, max: 1000, unit: 'mm' });
    checkNumber('widthScale', o.widthScale, { min: 0, max: 1 });
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
      hook.transmittance.lightType = t.lightDepth.light.isSpotLight ? 'spot' : 'directional';
    } else {
      hook.transmittance = null;
    }
    uniforms.sssWidthWorld.value = o.widthMm / o.worldUnitInMm;
    uniforms.sssWidthScale.value = o.widthScale;
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
    shader.defines = { ...shader.defines, ...ATTACHMENT_DEFINES, ...enumDefines('SSS_OUTPUT', MATERIAL_OUTPUTS, 'diffuse') };
    if (hook.transmittance) {
      shader.defines = { ...shader.defines, SSS_TRANSMITTANCE: '', ...enumDefines('SSS_LIGHT_TYPE', LIGHT_TYPES, hook.transmittance.lightType) };
    }
    let fs = shader.fragmentShader;
    fs = inject(fs, 'void main() {', `${declarations}\nvoid main() {`);
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

  // Per draw: split only in the multi-target's SPLIT call, and refresh the view-dependent
  // uniforms. Three uploads them once per material per render call, which is all they change at.
  material.onBeforeRender = function (renderer, scene, camera, geometry, object, group) {
    previous.onBeforeRender.call(this, renderer, scene, camera, geometry, object, group);
    const phase = drawPhaseOf(renderer.getRenderTarget());
    uniforms.sssSplit.value = phase === DRAW_PHASES.SPLIT;
    uniforms.sssDepthOnly.value = phase === DRAW_PHASES.DEPTH;
    if (hook.transmittance) {
      hook.transmittance.update(camera);
      updateLightUniforms(uniforms, hook.transmittance.lightDepth.light, camera);
    }
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

/**
 * The hook of a material made subsurface, or undefined.
 * @param {import('three').Material} material
 */
export function getSubsurface(material) {
  return hooks.get(material);
}
