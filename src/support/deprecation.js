// Names kept for one minor version after they moved or were replaced (CHANGELOG.md lists them):
// each still works and says once per page, on first use, what to use instead. Nothing is said at
// import (importing the package has no side effects).

const warned = new Set();

/**
 * Warns once per name: `name` is deprecated, use `instead`.
 * @param {string} name e.g. "setKernel()" or "import { planFrame } from 'three-separable-sss'"
 * @param {string} instead what to use
 */
export function warnDeprecated(name, instead) {
  if (warned.has(name)) return;
  warned.add(name);
  console.warn(`three-separable-sss: ${name} is deprecated and goes in the next minor version; use ${instead}.`);
}

/** Where moved names are now: the unstable entry. */
const INTERNALS = "three-separable-sss/internals";

/**
 * A function of the main entry that moved to the internals entry: the same function, warning once.
 * @template {(...args: any[]) => any} F
 * @param {string} name @param {F} fn @returns {F}
 */
export function movedFunction(name, fn) {
  return /** @type {F} */ (function moved(...args) {
    warnDeprecated(`import { ${name} } from 'three-separable-sss'`, `import { ${name} } from '${INTERNALS}'`);
    return fn.apply(this, args);
  });
}

/**
 * A class of the main entry that moved to the internals entry: constructing it warns once;
 * instances are instances of the class itself.
 * @template {new (...args: any[]) => any} C
 * @param {string} name @param {C} Class @returns {C}
 */
export function movedClass(name, Class) {
  return new Proxy(Class, {
    construct(target, args, newTarget) {
      warnDeprecated(`import { ${name} } from 'three-separable-sss'`, `import { ${name} } from '${INTERNALS}'`);
      return Reflect.construct(target, args, newTarget);
    },
  });
}

/**
 * A constant (frozen object or array) of the main entry that moved to the internals entry:
 * reading any of its members warns once.
 * @template {object} T
 * @param {string} name @param {T} value @returns {T}
 */
export function movedConstant(name, value) {
  return new Proxy(value, {
    get(target, key, receiver) {
      warnDeprecated(`import { ${name} } from 'three-separable-sss'`, `import { ${name} } from '${INTERNALS}'`);
      return Reflect.get(target, key, receiver);
    },
  });
}
