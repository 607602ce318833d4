// The class as the user knows it, for messages. A production build minifies class names (a
// bundler renames SubsurfaceScattering to `u_`), so `constructor.name` and `Class.name` cannot
// name a class there; each public class states its name as a string instead, as its
// Symbol.toStringTag (what Object.prototype.toString reads), which no minifier renames.

/**
 * Gives `Class`'s instances the name `name` in messages (set at run time, beside the class, so the
 * declarations stay as they are).
 * @template {Function} C
 * @param {C} Class
 * @param {string} name the class's exported name
 * @returns {C}
 */
export function nameClass(Class, name) {
  Object.defineProperty(Class.prototype, Symbol.toStringTag, { value: name, configurable: true });
  return Class;
}

/**
 * The name a class gave itself with nameClass: of an instance, or of a class (its prototype's).
 * @param {*} value
 * @returns {string|undefined}
 */
export function classNameOf(value) {
  const holder = typeof value === 'function' ? value.prototype : value;
  const tag = holder !== null && (typeof holder === 'object' || typeof holder === 'function') ? holder[Symbol.toStringTag] : undefined;
  return typeof tag === 'string' ? tag : undefined;
}
