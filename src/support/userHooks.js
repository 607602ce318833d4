// The user's shader hooks and ours on one material. three calls a material's onBeforeCompile,
// customProgramCacheKey and onBeforeRender; a user (or a library such as
// three-custom-shader-material) sets them, before or after makeSubsurface. Ours are put after the
// user's through accessor properties on the material: a later assignment replaces the user's part
// only, three still calls ours, and the program key holds the user's (three's default key is the
// hook's source, so two materials with two hooks get two programs). Restoring puts back exactly what
// the user holds then. The light's depth pass reads the user's part (userShaderHook) to draw each
// mesh with its own vertex stage.
import { Material } from 'three';

/** The hooks composed, each three's default until set. */
export const HOOKS = Object.freeze(['onBeforeCompile', 'customProgramCacheKey', 'onBeforeRender']);
const DEFAULTS = Object.freeze(Object.fromEntries(HOOKS.map((name) => [name, Material.prototype[name]])));

/** material → the user's hooks while ours are composed with them ({ name: function | undefined: three's }). */
const composed = new WeakMap();

/** A hook as held: undefined for three's default (or none). */
const asUser = (name, value) => (value === undefined || value === null || value === DEFAULTS[name] ? undefined : value);

/**
 * The program key of the user's hooks, as three makes it: their customProgramCacheKey, else their
 * onBeforeCompile's source (three's default key).
 */
function userProgramKey(material, user) {
  if (user.customProgramCacheKey) return String(user.customProgramCacheKey.call(material));
  return String(user.onBeforeCompile ?? DEFAULTS.onBeforeCompile);
}

/**
 * Puts `ours` after the user's hooks on `material`, now and for whatever the user assigns later.
 * A user's hook that calls what it read from the material before (ours: chaining, as libraries do)
 * gets its own part only: ours runs once, after it.
 * @param {import('three').Material} material
 * @param {{ onBeforeCompile(shader: object, renderer: object, userHook: Function|undefined): void,
 *   programKey(): string, onBeforeRender(...args: any[]): void }} ours onBeforeCompile runs the
 *   user's hook itself (`userHook`), to see what it changed
 * @returns {{ restore(): void }} puts the user's hooks back as they are then
 * @throws {TypeError} where the material's hooks cannot be redefined (a frozen material)
 */
export function composeHooks(material, ours) {
  const user = Object.fromEntries(HOOKS.map((name) => [name, asUser(name, material[name])]));
  const running = new Set();
  const guarded = (name, idle, run) => function (...args) {
    if (running.has(name)) return idle;
    running.add(name);
    try {
      return run.apply(this, args);
    } finally {
      running.delete(name);
    }
  };
  const hooks = {
    onBeforeCompile: guarded('onBeforeCompile', undefined, function (shader, renderer) {
      ours.onBeforeCompile.call(this, shader, renderer, user.onBeforeCompile);
    }),
    customProgramCacheKey: guarded('customProgramCacheKey', '', function () {
      return `${userProgramKey(this, user)}|${ours.programKey()}`;
    }),
    onBeforeRender: guarded('onBeforeRender', undefined, function (...args) {
      user.onBeforeRender?.apply(this, args);
      ours.onBeforeRender.apply(this, args);
    }),
  };
  for (const name of HOOKS) {
    const descriptor = Object.getOwnPropertyDescriptor(material, name);
    if (descriptor ? descriptor.configurable === false : !Object.isExtensible(material)) {
      throw new TypeError(`makeSubsurface: material.${name} cannot be redefined (the material is frozen or sealed), so its shader cannot be patched`);
    }
  }
  for (const name of HOOKS) {
    Object.defineProperty(material, name, {
      configurable: true,
      enumerable: false, // a plain copy of the material's fields (for...in) does not take ours
      get: () => hooks[name],
      set: (value) => { user[name] = asUser(name, value); },
    });
  }
  composed.set(material, user);
  return {
    restore() {
      for (const name of HOOKS) {
        delete material[name];
        // What the user holds now, where it is not what the material's class gives it anyway.
        if (user[name] !== undefined && material[name] !== user[name]) material[name] = user[name];
      }
      composed.delete(material);
    },
  };
}

/** The user's hooks on `material`: those held under ours, else the material's own. */
const userHooksOf = (material) => composed.get(material)
  ?? { onBeforeCompile: asUser('onBeforeCompile', material.onBeforeCompile), customProgramCacheKey: asUser('customProgramCacheKey', material.customProgramCacheKey) };

/**
 * The user's own onBeforeCompile on `material`, whether or not ours are composed with it, or null
 * where it has none (three's default).
 * @param {import('three').Material} material
 * @returns {Function|null}
 */
export function userShaderHook(material) {
  return userHooksOf(material).onBeforeCompile ?? null;
}

/**
 * The program key of the user's own hooks on `material` (their customProgramCacheKey, else their
 * onBeforeCompile's source), without ours.
 * @param {import('three').Material} material
 * @returns {string}
 */
export function userProgramKeyOf(material) {
  return userProgramKey(material, userHooksOf(material));
}
