// Stage 2 for WebGPURenderer: the diffuse/specular split as node materials. TSL has no
// diffuse-only output, so these subclasses of three's MeshStandardNodeMaterial and
// MeshPhysicalNodeMaterial write it: drawn by a pass whose MRT has the subsurface outputs
// (subsurfaceMRT), the colour output keeps the specular and emissive light, `diffuse` receives the
// diffuse light (direct + indirect + the light transmitted through thin parts, when a node with a
// light draws it; a = 1: the mask) and `surface` the linear view depth and the material's width.
// Drawn anywhere else they render exactly as three's own materials do (without transmittance).
// The WebGL path does the same by patching three's GLSL (src/2-scene-split/subsurfaceMaterial.js,
// shaders/2-scene-split/material/split.glsl, transmittedLight.glsl, clearcoat.glsl, output.glsl).
import { MeshPhysicalNodeMaterial, MeshStandardNodeMaterial } from 'three/webgpu';
import {
  F_Schlick, clearcoat, clearcoatNormalView, densityFogFactor, diffuseColor, float, mrt, negateOnBackSide, normalViewGeometry, output,
  positionView, positionViewDirection, rangeFogFactor, reference, renderGroup, select, uniform, vec3, vec4,
} from 'three/tsl';
import { checkOptions } from '../../support/parameterChecks.js';
import { describe, refuseTransmission } from '../../support/rendererSupport.js';
import { MATERIAL_DEFAULTS, MATERIAL_SCHEMA, checkOption } from '../../options.js';
import { MATERIAL_OUTPUTS } from '../../4-compose/debugViews.js';
import { ATTACHMENT_NAMES } from './attachments.js';
import { transmittanceUniformNodes, transmittedLight } from './transmittanceTsl.js';
import { finite3 } from '../common/surfaceTsl.js';

/** What subsurfaceMaterial(material, { ... }) accepts: the WebGL path's material options that apply per material (src/options.js). */
const MATERIAL_OPTIONS = Object.freeze(['widthMm', 'transmittance', 'translucency', 'shrinkMm']);

/**
 * The scene fog's factor (0 clear .. 1 all fog) as three builds it for `scene.fog`
 * (NodeManager.updateFog: rangeFogFactor for a Fog, densityFogFactor for a FogExp2), or null where
 * three draws this material without that fog (no fog, `material.fog` false, or a custom
 * `scene.fogNode`, whose factor is not known here: the node warns about that).
 */
function sceneFogFactor(builder, material) {
  const fog = builder.scene?.fog;
  if (!material.fog || !fog || builder.scene.fogNode || builder.fogNode === null) return null;
  const property = (name) => reference(name, 'float', fog).setGroup(renderGroup);
  if (fog.isFogExp2) return densityFogFactor(property('density'));
  return fog.isFog ? rangeFogFactor(property('near'), property('far')) : null;
}

/**
 * The split, mixed into a node material class: setupLighting returns the light without its diffuse
 * part and the material's mrtNode writes that part to the subsurface outputs.
 * @template {new (...args: any[]) => import('three/webgpu').NodeMaterial} Base
 * @param {Base} Base
 */
function withSubsurface(Base) {
  return class extends Base {
    // A rest parameter: TypeScript's mixin pattern (its declarations stay one constructor type).
    constructor(...args) {
      super(...args);
      /** Scales the profile: 1 is its physical size (the width uniform the surface output writes). */
      this.subsurfaceWidth = uniform(MATERIAL_DEFAULTS.widthMm);
      this._subsurface = { transmittance: MATERIAL_DEFAULTS.transmittance, translucency: MATERIAL_DEFAULTS.translucency, shrinkMm: MATERIAL_DEFAULTS.shrinkMm };
      /** The transmittance uniforms (transmittanceUniformNodes), made by the first node with a light that draws this material. */
      this.transmittanceNodes = null;
      this.isSubsurfaceNodeMaterial = true;
    }

    /** The profile's scale on this material: 1 is its physical size (profile mm per mm). @type {number} */
    get widthMm() {
      return this.subsurfaceWidth.value;
    }

    set widthMm(widthMm) {
      this.subsurfaceWidth.value = checkOption(MATERIAL_SCHEMA, 'widthMm', widthMm);
    }

    /**
     * Light through thin parts, with the drawing node's light. A uniform of the frame; three keys a
     * node material by its settings, so a change rebuilds its node graph once.
     * @type {boolean}
     */
    get transmittance() { return this._subsurface.transmittance; }

    set transmittance(enabled) { this._subsurface.transmittance = checkOption(MATERIAL_SCHEMA, 'transmittance', enabled); }

    /** 0..1 (exclusive): light through regardless of thickness (shortens it by 1 − translucency). @type {number} */
    get translucency() { return this._subsurface.translucency; }

    set translucency(translucency) { this._subsurface.translucency = checkOption(MATERIAL_SCHEMA, 'translucency', translucency); }

    /** How far the light depth lookup moves inwards along the vertex normal, mm (against acne). @type {number} */
    get shrinkMm() { return this._subsurface.shrinkMm; }

    set shrinkMm(mm) { this._subsurface.shrinkMm = checkOption(MATERIAL_SCHEMA, 'shrinkMm', mm); }

    /**
     * The transmittance uniforms a node with lights writes each frame, one set per light map
     * (the writer points each at its map): made on the first call and again when the number of
     * maps changes (the material is rebuilt once to read them: the number of lights recompiles it).
     * @param {{ lightDepthMaps: import('three').Texture[], profileLookup: import('three').Texture }} textures
     */
    useTransmittance(textures) {
      if (this.transmittanceNodes?.lights.length !== textures.lightDepthMaps.length) {
        this.transmittanceNodes = transmittanceUniformNodes(textures);
        this.needsUpdate = true;
      }
      return this.transmittanceNodes;
    }

    setupLightingModel(builder) {
      this._subsurfaceLit = true; // three lights this material in this build (see setupLighting)
      return super.setupLightingModel(builder);
    }

    setupLighting(builder) {
      this._subsurfaceLit = false;
      const outgoing = super.setupLighting(builder);
      const mrtNode = builder.renderTarget !== null ? builder.renderer.getMRT() : null;
      if (!mrtNode?.has(ATTACHMENT_NAMES.DIFFUSE)) {
        this.mrtNode = null;
        return outgoing; // not drawn into a subsurface pass: three's own result
      }
      // three's totalDiffuse (LightsNode), assigned by the lighting built just above; 0 unlit.
      const lightsNode = this.lightsNode || builder.lightsNode;
      let diffuse = this._subsurfaceLit ? lightsNode.totalDiffuseNode : vec3(0);
      // The light through thin parts joins the diffuse light before the blur (transmittedLight.glsl).
      const t = this.transmittanceNodes && this._subsurfaceLit
        // nonPerturbedNormal as three's GLSL has it: flat shading's derivative normal already faces
        // the camera (normal_fragment_begin does not flip it); a smooth one flips on back faces.
        ? transmittedLight(this.transmittanceNodes, { position: positionView, normal: builder.isFlatShading() ? normalViewGeometry : negateOnBackSide(normalViewGeometry), albedo: diffuseColor.rgb })
        : null;
      let lit = t ? diffuse.add(t.transmitted) : diffuse;
      // The clear coat dims everything under it, the diffuse light included (PhysicalLightingModel.finish).
      if (this.useClearcoat) {
        const Fcc = F_Schlick({ dotVH: clearcoatNormalView.dot(positionViewDirection).clamp(), f0: vec3(0.04), f90: float(1) });
        const dimmed = clearcoat.mul(Fcc).oneMinus();
        diffuse = diffuse.mul(dimmed);
        lit = lit.mul(dimmed);
      }
      // No toVar: a variable would be assigned where TSL first builds it, before the lighting code;
      // the property is read where each output needs it, after the lighting has assigned it.
      const kept = vec3(diffuse); // three's own diffuse light: what the colour output gives up
      let light = vec3(lit);
      // Fog blends the colour output towards the fog colour; the diffuse light fades by the same
      // factor, so that diffuse + colour equals three's own fogged result (output.glsl).
      const fogFactor = sceneFogFactor(builder, this);
      if (fogFactor) light = light.mul(fogFactor.oneMinus());
      if (t) {
        // The thickness and transmittance views write that ingredient instead (output.glsl).
        const output = this.transmittanceNodes.sssDebugOutput;
        light = select(output.equal(MATERIAL_OUTPUTS.indexOf('transmittance')), t.transmitted,
          select(output.equal(MATERIAL_OUTPUTS.indexOf('thickness')), vec3(t.thicknessMm), light));
      }
      // A non-finite value would spread through the blur: keep it out (shaders/common/finite.glsl).
      const written = select(finite3(light), light.max(0), vec3(0));
      this.mrtNode = mrt({
        [ATTACHMENT_NAMES.DIFFUSE]: vec4(written, 1),
        [ATTACHMENT_NAMES.SURFACE]: vec4(positionView.z.negate(), this.subsurfaceWidth, 0, 1),
      });
      return outgoing.sub(kept);
    }

    copy(source) {
      super.copy(source);
      // NodeMaterial.copy assigns the source's objects: a copy gets uniforms of its own (the
      // options below set their values).
      this.subsurfaceWidth = uniform(MATERIAL_DEFAULTS.widthMm);
      this.transmittanceNodes = null;
      this.needsUpdate = true;
      if (source.isSubsurfaceNodeMaterial) {
        for (const name of MATERIAL_OPTIONS) this[name] = source[name];
      }
      return this;
    }
  };
}

/** MeshStandardNodeMaterial with the subsurface split (see the file's header). */
export class SubsurfaceStandardNodeMaterial extends withSubsurface(MeshStandardNodeMaterial) {
  static get type() {
    return 'SubsurfaceStandardNodeMaterial';
  }
}

/** MeshPhysicalNodeMaterial with the subsurface split; the clear coat dims the diffuse light too. */
export class SubsurfacePhysicalNodeMaterial extends withSubsurface(MeshPhysicalNodeMaterial) {
  static get type() {
    return 'SubsurfacePhysicalNodeMaterial';
  }
}

/** Own properties not carried over from the material converted (three's NodeLibrary copies the rest too). */
const NOT_COPIED = new Set(['uuid', 'type', 'isSubsurfaceNodeMaterial', 'subsurfaceWidth', '_subsurface', 'transmittanceNodes']);

/**
 * @overload
 * @param {import('three').MeshPhysicalMaterial | import('three/webgpu').MeshPhysicalNodeMaterial} material
 * @param {SubsurfaceMaterialOptions} [options]
 * @returns {SubsurfacePhysicalNodeMaterial & import('three').MeshPhysicalMaterial}
 */
/**
 * @overload
 * @param {import('three').MeshStandardMaterial | import('three/webgpu').MeshStandardNodeMaterial} material
 * @param {SubsurfaceMaterialOptions} [options]
 * @returns {SubsurfaceStandardNodeMaterial & import('three').MeshStandardMaterial}
 */
/**
 * A subsurface node material made from `material`: a MeshStandardMaterial or MeshPhysicalMaterial
 * (or their node versions), its settings carried over as WebGPURenderer itself converts a classic
 * material (NodeLibrary.fromMaterial copies every own property, the class flags too). The material
 * given is left as it is. Typed as the node material and three's material of its kind (not a
 * subclass of it: methods are not copied), so that it takes the place of that material where the
 * mesh's type names it (`mesh.material = subsurfaceMaterial(mesh.material)`).
 * @typedef {{ widthMm?: number, transmittance?: boolean, translucency?: number, shrinkMm?: number }} SubsurfaceMaterialOptions
 *   widthMm: the profile's scale, 1 its physical size; the others as the WebGL path's makeSubsurface
 *   (src/options.js's MATERIAL_SCHEMA), also properties of the material
 * @param {import('three').MeshStandardMaterial | import('three/webgpu').MeshStandardNodeMaterial} material
 * @param {SubsurfaceMaterialOptions} [options]
 * @returns {SubsurfaceStandardNodeMaterial | SubsurfacePhysicalNodeMaterial}
 */
export function subsurfaceMaterial(material, options) {
  const given = checkOptions('subsurfaceMaterial options', options, MATERIAL_OPTIONS);
  if (!material || !(material.isMeshStandardMaterial || material.isMeshStandardNodeMaterial)) {
    throw new TypeError(`subsurfaceMaterial: material must be a THREE.MeshStandardMaterial or MeshPhysicalMaterial (or its node version), got ${describe(material)}`);
  }
  refuseTransmission(material, 'subsurfaceMaterial');
  const settings = Object.fromEntries(MATERIAL_OPTIONS.map((name) => [name, checkOption(MATERIAL_SCHEMA, name, given[name] === undefined ? MATERIAL_DEFAULTS[name] : given[name])]));
  const physical = material.isMeshPhysicalMaterial || material.isMeshPhysicalNodeMaterial;
  const result = physical ? new SubsurfacePhysicalNodeMaterial() : new SubsurfaceStandardNodeMaterial();
  for (const key in material) {
    if (!NOT_COPIED.has(key) && typeof material[key] !== 'function') result[key] = material[key];
  }
  result.name = material.name;
  Object.assign(result, settings);
  result.needsUpdate = true;
  return result;
}

/**
 * The MRT a subsurface pass needs: three's `output` (the colour), `diffuse` and `surface`, the last
 * two written 0 by every other material and cleared to 0 (alpha 0: off the mask, where nothing was
 * drawn; three clears extra attachments to alpha 1 otherwise). Merge your own outputs into it with
 * `subsurfaceMRT().merge(mrt({ ... }))`.
 * @returns {import('three/webgpu').MRTNode}
 */
export function subsurfaceMRT() {
  const node = mrt({ output, [ATTACHMENT_NAMES.DIFFUSE]: vec4(0), [ATTACHMENT_NAMES.SURFACE]: vec4(0) });
  node.setClearColor(ATTACHMENT_NAMES.DIFFUSE, 0x000000, 0);
  node.setClearColor(ATTACHMENT_NAMES.SURFACE, 0x000000, 0);
  return node;
}

/** Whether `material` is a subsurface node material (subsurfaceMaterial's). */
export const isSubsurfaceNodeMaterial = (material) => material?.isSubsurfaceNodeMaterial === true;

/**
 * The subsurface node materials of `meshes` (the frame's on the screen: FrameMeshes.onScreen), to
 * hand transmittance uniforms to.
 * @param {Iterable<import('three').Mesh>} meshes
 * @returns {Set<import('three/webgpu').NodeMaterial>}
 */
export function subsurfaceMaterialsOf(meshes) {
  const materials = new Set();
  for (const mesh of meshes) {
    for (const m of Array.isArray(mesh.material) ? mesh.material : [mesh.material]) if (isSubsurfaceNodeMaterial(m)) materials.add(m);
  }
  return materials;
}
