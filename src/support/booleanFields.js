// Boolean-only fields for the library's passes. three's Pass (and pmndrs's) keeps `enabled`,
// `needsSwap`, `clear` and `renderToScreen` as plain fields, so `pass.enabled = 'no'` would be
// kept and read as true. These accessors, on the class's prototype, take booleans only (a TypeError
// naming the class and the field otherwise) and read back the boolean, as EffectComposer expects.
// Defined at runtime, not in the class body: the declarations keep the base class's `boolean` fields.
import { checkBoolean } from './parameterChecks.js';

const values = new WeakMap();

/**
 * Makes each of `names` a boolean-only accessor on `prototype` (instances keep their values privately).
 * @param {object} prototype a class's prototype
 * @param {ReadonlyArray<string>} names
 */
export function booleanFields(prototype, names) {
  for (const name of names) {
    Object.defineProperty(prototype, name, {
      configurable: true,
      enumerable: false,
      get() {
        return values.get(this)?.[name];
      },
      set(value) {
        checkBoolean(`${this.constructor.name}.${name}`, value);
        let own = values.get(this);
        if (!own) values.set(this, (own = {}));
        own[name] = value;
      },
    });
  }
}

/** The fields of three's Pass that are booleans. */
export const PASS_BOOLEANS = Object.freeze(['enabled', 'needsSwap', 'clear', 'renderToScreen']);
