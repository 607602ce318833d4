// three's Pass keeps `enabled` and the like as plain fields, so `pass.enabled = 'no'` would read as
// true: these accessors take booleans only. Defined at run time, not in the class body, so the
// declarations keep the base class's `boolean` fields.
import { checkBoolean } from './parameterChecks.js';
import { classNameOf } from './className.js';

const values = new WeakMap();

/**
 * Makes each of `names` a boolean-only accessor on `prototype`.
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
        checkBoolean(`${classNameOf(this) ?? 'Pass'}.${name}`, value); // the class as named by nameClass, minified or not
        let own = values.get(this);
        if (!own) values.set(this, (own = {}));
        own[name] = value;
      },
    });
  }
}

export const PASS_BOOLEANS = Object.freeze(['enabled', 'needsSwap', 'clear', 'renderToScreen']);
