// The settings as properties made from the one schema (src/options.js), so the WebGL pipeline and
// the WebGPU node check each setting the same way. An assignment is checked, kept, then applied by
// the object's _applySetting (a recompile, a uniform, a rebind); if that throws, the value is put back.
import { propertiesOf } from '../options.js';

/**
 * `Base` with `schema`'s settings as properties; the values live in `this._settings`.
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
        // A setting without a default takes undefined back (the method's own: strength, falloff).
        const spec = schema[name];
        const checked = value === undefined && spec.default === undefined && !spec.required ? undefined : spec.check(value, name);
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
