// The settings of an entry's object as properties, made from the one schema (src/options.js), so
// the WebGL pipeline and the WebGPU node read, check and document each setting the same way:
// reading gives the value kept; assigning checks it against the schema (a TypeError or RangeError
// naming the property as the user wrote it), keeps it, then lets the object act on it through
// its _applySetting(name, value, previous) (a recompile, a uniform, a rebind), which may refuse it:
// the value is then put back and nothing changed. A setting the schema marks read-only refuses
// every assignment, naming what to do instead.
import { propertiesOf } from '../options.js';

/**
 * `Base` with the properties of `schema`'s settings on its prototype. The object keeps the values
 * in `this._settings` (its constructor fills it with the checked options) and defines
 * `_applySetting(name, value, previous)`.
 * @template {new (...args: any[]) => object} B
 * @param {B} Base
 * @param {Readonly<Record<string, import('../options.js').OptionSpec>>} schema
 * @param {string} owner the class as the user knows it, for the read-only message
 * @returns {B}
 */
export function withSettings(Base, schema, owner) {
  class WithSettings extends Base {}
  for (const { name, assignable } of propertiesOf(schema)) {
    Object.defineProperty(WithSettings.prototype, name, {
      configurable: true,
      enumerable: true,
      get() {
        return this._settings[name];
      },
      set(value) {
        if (!assignable) {
          throw new TypeError(`${owner}.${name} is read-only: it is given to the constructor (make another ${owner} for another ${name})`);
        }
        const checked = schema[name].check(value, name);
        const previous = this._settings[name];
        this._settings[name] = checked;
        try {
          this._applySetting(name, checked, previous);
        } catch (error) {
          this._settings[name] = previous;
          throw error;
        }
      },
    });
  }
  return WithSettings;
}
