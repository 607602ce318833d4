// three-separable-sss/react: skin scattering in a React Three Fiber app.
//   <Canvas>
//     <SubsurfaceComposer light={light} worldUnitInMm={1000}>      takes over the frame
//       <mesh>
//         <torusKnotGeometry args={[0.08, 0.025, 200, 32]} />
//         <meshStandardMaterial color="#e0b8a0"><Subsurface widthMm={1} /></meshStandardMaterial>
//       </mesh>
//     </SubsurfaceComposer>
//   </Canvas>
//
// <SubsurfaceComposer> owns an EffectComposer with half-float buffers: SubsurfaceScattering in place
// of a RenderPass, then an OutputPass (R3F's tone mapping and colour space), rendered from a
// useFrame of priority 1 (R3F then does not render itself). The camera, scene and size are read
// every frame; a change of renderer, light or option rebuilds the pipeline and rebinds its
// materials. Unmounting disposes all it made. Importing this file touches no DOM.
import { createContext, createElement, useCallback, useContext, useEffect, useRef, useState } from 'react';
import { useFrame, useThree } from '@react-three/fiber';
import { HalfFloatType, WebGLRenderTarget } from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from '../index.js';
import { checkBoolean, checkInteger, checkOptions } from '../support/parameterChecks.js';

/**
 * @typedef {Omit<import('../options.js').SubsurfaceScatteringOptions, 'scene'|'camera'|'light'> & {
 *   light?: import('../options.js').TransmittingLight|{ current: import('../options.js').TransmittingLight|null }
 *     |Array<import('../options.js').TransmittingLight|{ current: import('../options.js').TransmittingLight|null }>|'castShadow'|null,
 *   samples?: number|'auto',
 *   antialias?: number,
 *   enabled?: boolean,
 * }} SubsurfaceComposerOptions
 *   the pipeline's options (scene and camera are R3F's), `light` also as a ref; `antialias`: MSAA
 *   samples of the composer's buffers (default 4); `enabled` false: R3F's plain render instead
 */

/** The pipeline of one <SubsurfaceComposer>, and its materials (they outlive rebuilds). */
class SubsurfaceRegistry {
  constructor() {
    /** @type {SubsurfaceScattering|null} the pipeline, null while none is built */
    this.pass = null;
    /** @type {EffectComposer|null} */
    this.composer = null;
    /** @type {Map<import('three').MeshStandardMaterial, import('../options.js').SubsurfaceMaterialOptions>} */
    this.materials = new Map();
  }

  /**
   * @param {import('three').MeshStandardMaterial} material
   * @param {import('../options.js').SubsurfaceMaterialOptions} [options]
   */
  add(material, options = {}) {
    this.materials.set(material, options);
    this.pass?.makeSubsurface(material, options);
  }

  /** @param {import('three').MeshStandardMaterial} material */
  remove(material) {
    this.materials.delete(material);
    this.pass?.removeSubsurface(material);
  }

  /** @private @param {SubsurfaceScattering} pass @param {EffectComposer} composer */
  _connect(pass, composer) {
    this.pass = pass;
    this.composer = composer;
    for (const [material, options] of this.materials) pass.makeSubsurface(material, options);
  }

  /** @private */
  _disconnect() {
    this.pass = null;
    this.composer = null;
  }
}

const RegistryContext = createContext(/** @type {SubsurfaceRegistry|null} */ (null));

/** The options that, changed, rebuild the pipeline (compared by value; a profile object by identity). */
function rebuildKey(options) {
  return JSON.stringify(options, (key, value) => (key === 'profile' && typeof value === 'object' ? undefined : value));
}

/** A light or a ref to one, a list of them, or 'castShadow', as the pipeline takes it. */
function resolveLight(light) {
  if (!light) return null;
  if (Array.isArray(light)) return light.map(resolveLight); // an unset ref in it is refused by the pipeline, naming it
  return light.isLight || typeof light === 'string' ? light : light.current ?? null;
}

/**
 * Renders R3F's scene through SubsurfaceScattering from now on (a useFrame of priority 1).
 * @param {SubsurfaceComposerOptions} [options]
 * @returns {SubsurfaceRegistry} `pass` (the SubsurfaceScattering, null until built), `composer`,
 *   and add(material, options) / remove(material) for materials made in code (e.g. a loaded model's)
 */
export function useSubsurfaceScattering(options = {}) {
  const { light = null, antialias = 4, enabled = true, profile, ...rest } = checkOptions('useSubsurfaceScattering options', options);
  checkInteger('useSubsurfaceScattering: antialias', antialias, 0, 16, 'MSAA samples');
  checkBoolean('useSubsurfaceScattering: enabled', enabled);
  const gl = useThree((state) => state.gl);
  const getState = useThree((state) => state.get); // R3F's store accessor: stable
  const [registry] = useState(() => new SubsurfaceRegistry());
  const key = rebuildKey(rest);
  const enabledRef = useRef(enabled);
  enabledRef.current = enabled;
  const size = useRef({ width: 0, height: 0, dpr: 0 });

  // Built after the commit, when a light's ref is set.
  useEffect(() => {
    const { scene, camera } = getState();
    const pass = new SubsurfaceScattering({ ...JSON.parse(key), ...(profile !== undefined && { profile }), scene, camera, light: resolveLight(light) });
    const buffer = new WebGLRenderTarget(1, 1, { type: HalfFloatType, samples: antialias });
    const composer = new EffectComposer(gl, buffer);
    const output = new OutputPass();
    composer.addPass(pass);
    composer.addPass(output);
    size.current = { width: 0, height: 0, dpr: 0 }; // sized on its first frame
    registry._connect(pass, composer);
    return () => {
      registry._disconnect();
      pass.dispose();
      output.dispose();
      composer.dispose(); // both of its buffers
    };
  }, [gl, getState, registry, light, profile, key, antialias]);

  useFrame((state, deltaSeconds) => {
    const { pass, composer } = registry;
    if (!pass || !enabledRef.current) {
      state.gl.render(state.scene, state.camera); // priority 1 turned R3F's own render off
      return;
    }
    pass.scene = state.scene;
    pass.camera = state.camera;
    const { width, height } = state.size;
    const { dpr } = state.viewport;
    const last = size.current;
    if (last.width !== width || last.height !== height || last.dpr !== dpr) {
      composer.setPixelRatio(dpr);
      composer.setSize(width, height); // every pass, in device pixels
      size.current = { width, height, dpr };
    }
    composer.render(deltaSeconds);
  }, 1);

  return registry;
}

/**
 * Renders its children's scene with subsurface scattering; <Subsurface> inside it marks materials.
 * @param {SubsurfaceComposerOptions & { children?: import('react').ReactNode }} props
 * @returns {import('react').ReactElement}
 */
export function SubsurfaceComposer({ children, ...options }) {
  const registry = useSubsurfaceScattering(options);
  return createElement(RegistryContext.Provider, { value: registry }, children);
}

function useRegistry(name) {
  const registry = useContext(RegistryContext);
  if (!registry) throw new Error(`${name} must be used inside <SubsurfaceComposer>`);
  return registry;
}

/**
 * The enclosing <SubsurfaceComposer>'s registry: `pass` (null until built) and `composer`.
 * @returns {SubsurfaceRegistry}
 */
export function useSubsurfaceComposer() {
  return useRegistry('useSubsurfaceComposer');
}

/**
 * Makes `material` scatter in the enclosing <SubsurfaceComposer> while the calling component is
 * mounted (for materials made in code, e.g. a loaded model's). null: nothing.
 * @param {import('three').MeshStandardMaterial|null|undefined} material
 * @param {import('../options.js').SubsurfaceMaterialOptions} [options]
 */
export function useSubsurface(material, options = {}) {
  const registry = useRegistry('useSubsurface');
  const key = JSON.stringify(options);
  useEffect(() => {
    if (!material) return undefined;
    registry.add(material, JSON.parse(key));
    return () => registry.remove(material);
  }, [registry, material, key]);
}

/**
 * As a child of <meshStandardMaterial> or <meshPhysicalMaterial>: makes that material scatter in
 * the enclosing <SubsurfaceComposer> while mounted.
 * @param {import('../options.js').SubsurfaceMaterialOptions} props
 * @returns {import('react').ReactElement}
 */
export function Subsurface(props) {
  const registry = useRegistry('<Subsurface>');
  const material = useRef(/** @type {import('three').MeshStandardMaterial|null} */ (null));
  const live = useRef(false); // between this component's effect and its cleanup
  const options = useRef(props);
  options.current = props;
  // R3F may call `attach` while rendering, before effects run, and keeps the first one it is given.
  const attach = useCallback((parent) => {
    if (!parent?.isMeshStandardMaterial) {
      throw new TypeError(`<Subsurface> must be a child of <meshStandardMaterial> or <meshPhysicalMaterial>, got ${parent?.type ?? parent}`);
    }
    material.current = parent;
    if (live.current) registry.add(parent, options.current); // a parent rebuilt by R3F
    return () => {
      if (material.current === parent) material.current = null;
      registry.remove(parent);
    };
  }, [registry]);
  const key = JSON.stringify(props);
  useEffect(() => {
    live.current = true;
    const current = material.current;
    if (current) registry.add(current, JSON.parse(key));
    return () => {
      live.current = false;
      if (current) registry.remove(current);
    };
  }, [registry, key]);
  const [token] = useState(() => ({})); // the primitive R3F attaches: a placeholder object
  return createElement('primitive', { object: token, attach, dispose: null });
}
