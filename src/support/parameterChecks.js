/**
 * Argument validation. Each message names the parameter, the accepted range and the value, so a
 * wrong call is fixed from the message alone: TypeError for a wrong type, RangeError for a value
 * out of range. Each check returns the value it accepted.
 * @module parameterChecks
 */

/**
 * Formats a value for an error message: strings quoted, arrays listed, objects named by type.
 * @param {*} value
 * @returns {string}
 */
export function describeValue(value) {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number' || typeof value === 'bigint' || typeof value === 'boolean') return String(value);
  if (value === null || value === undefined) return String(value);
  if (Array.isArray(value) || ArrayBuffer.isView(value)) {
    const items = Array.from(value, (v) => describeValue(v));
    return `[${items.join(', ')}]`;
  }
  if (typeof value === 'function') return 'a function';
  return `an object (${Object.prototype.toString.call(value).slice(8, -1)})`;
}

/**
 * "[0, 100]", "(0, 10]", "[0, ∞)".
 * @param {{min?: number, max?: number, minExclusive?: boolean, maxExclusive?: boolean}} range
 * @returns {string}
 */
function describeInterval({ min = -Infinity, max = Infinity, minExclusive = false, maxExclusive = false }) {
  const lo = min === -Infinity ? '(-∞' : `${minExclusive ? '(' : '['}${min}`;
  const hi = max === Infinity ? '∞)' : `${max}${maxExclusive ? ')' : ']'}`;
  return `${lo}, ${hi}`;
}

/**
 * @param {number} value
 * @param {{min?: number, max?: number, minExclusive?: boolean, maxExclusive?: boolean}} range
 * @returns {boolean}
 */
function inInterval(value, { min = -Infinity, max = Infinity, minExclusive = false, maxExclusive = false }) {
  const aboveMin = minExclusive ? value > min : value >= min;
  const belowMax = maxExclusive ? value < max : value <= max;
  return aboveMin && belowMax;
}

/**
 * Checks that `value` is a finite number inside an optional interval.
 * @param {string} name parameter name used in the message, e.g. 'widthMm'
 * @param {*} value
 * @param {{min?: number, max?: number, minExclusive?: boolean, maxExclusive?: boolean, unit?: string}} [range]
 * @returns {number} the value
 * @throws {TypeError} "widthMm must be a finite number, got NaN"
 * @throws {RangeError} "widthMm must be in [0, 100] mm, got -1"
 */
export function checkNumber(name, value, range = {}) {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new TypeError(`${name} must be a finite number, got ${describeValue(value)}`);
  }
  if (!inInterval(value, range)) {
    const unit = range.unit ? ` ${range.unit}` : '';
    throw new RangeError(`${name} must be in ${describeInterval(range)}${unit}, got ${describeValue(value)}`);
  }
  return value;
}

/**
 * Checks that `value` is an integer in min..max (both inclusive).
 * @param {string} name
 * @param {*} value
 * @param {number} min
 * @param {number} max
 * @param {string} [unit] printed after the range, e.g. 'pixels'
 * @returns {number} the value
 * @throws {TypeError} when not a finite number: "size must be an integer in 16..8192 pixels, got NaN"
 * @throws {RangeError} when fractional or out of range: "size must be an integer in 16..8192 pixels, got 10"
 */
export function checkInteger(name, value, min, max, unit) {
  const message = `${name} must be an integer in ${min}..${max}${unit ? ` ${unit}` : ''}, got ${describeValue(value)}`;
  if (typeof value !== 'number' || !Number.isFinite(value)) throw new TypeError(message);
  if (!Number.isInteger(value) || value < min || value > max) throw new RangeError(message);
  return value;
}

/**
 * Checks that `value` is an odd integer in min..max (both inclusive).
 * @param {string} name
 * @param {*} value
 * @param {number} min smallest accepted value (odd)
 * @param {number} max largest accepted value (odd)
 * @returns {number} the value
 * @throws {TypeError} when not a finite number: "samples must be an odd integer in 3..63, got NaN"
 * @throws {RangeError} when even, fractional or out of range: "samples must be an odd integer in 3..63, got 4"
 */
export function checkOddInteger(name, value, min, max) {
  const message = `${name} must be an odd integer in ${min}..${max}, got ${describeValue(value)}`;
  if (typeof value !== 'number' || !Number.isFinite(value)) throw new TypeError(message);
  if (!Number.isInteger(value) || Math.abs(value % 2) !== 1 || value < min || value > max) {
    throw new RangeError(message);
  }
  return value;
}

/**
 * Checks that `value` is an array (or typed array) of 3 finite numbers, or a THREE.Color or
 * THREE.Vector3 (three's own RGB types, read as their r, g, b or x, y, z), each inside an optional
 * interval.
 * @param {string} name
 * @param {*} value
 * @param {{min?: number, max?: number, minExclusive?: boolean, maxExclusive?: boolean, unit?: string}} [range]
 * @returns {number[]} a plain copy [r, g, b]
 * @throws {TypeError} "strength must be an array of 3 finite numbers, got [1, 2]"
 * @throws {RangeError} "strength[1] must be in [0, 1], got 2"
 */
export function checkRgb(name, value, range = {}) {
  if (value?.isColor === true) value = [value.r, value.g, value.b];
  else if (value?.isVector3 === true) value = [value.x, value.y, value.z];
  const isList = Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView));
  if (!isList || value.length !== 3 || !Array.from(value).every((v) => typeof v === 'number' && Number.isFinite(v))) {
    throw new TypeError(`${name} must be an array of 3 finite numbers, got ${describeValue(value)}`);
  }
  const rgb = Array.from(value);
  rgb.forEach((v, i) => checkNumber(`${name}[${i}]`, v, range));
  return rgb;
}

/**
 * Checks that `value` is one of a fixed list (compared with ===).
 * @param {string} name
 * @param {*} value
 * @param {ReadonlyArray<*>} list accepted values
 * @returns {*} the value
 * @throws {TypeError} when the value's type matches none of the list's types
 * @throws {RangeError} "method must be one of 'reference', 'marginal', got \"foo\""
 */
export function checkOneOf(name, value, list) {
  if (list.includes(value)) return value;
  const accepted = list.map((v) => (typeof v === 'string' ? `'${v}'` : String(v))).join(', ');
  const message = `${name} must be one of ${accepted}, got ${describeValue(value)}`;
  const sameType = list.some((v) => typeof v === typeof value);
  throw sameType ? new RangeError(message) : new TypeError(message);
}

/**
 * Checks that `value` is a boolean: a string such as 'no' or a number is refused, not read as truthy.
 * @param {string} name
 * @param {*} value
 * @returns {boolean} the value
 * @throws {TypeError} "transmittance must be a boolean (true or false), got \"no\""
 */
export function checkBoolean(name, value) {
  if (typeof value !== 'boolean') throw new TypeError(`${name} must be a boolean (true or false), got ${describeValue(value)}`);
  return value;
}

/**
 * Checks an options argument: undefined or a plain object whose keys are all in `accepted`, so a
 * misspelt option is named instead of ignored.
 * @param {string} name e.g. 'SubsurfaceScattering options'
 * @param {*} value
 * @param {ReadonlyArray<string>} [accepted] the option names; omitted: any keys
 * @returns {object} the value, or {} for undefined
 * @throws {TypeError} "makeSubsurface options must be an object, got null";
 *   "makeSubsurface options: unknown option \"widthmm\" (accepted: widthMm, widthScale, ...)"
 */
export function checkOptions(name, value, accepted) {
  if (value === undefined) return {};
  if (value === null || typeof value !== 'object' || Array.isArray(value)) {
    throw new TypeError(`${name} must be an object, got ${describeValue(value)}`);
  }
  if (accepted) {
    for (const key of Object.keys(value)) {
      if (!accepted.includes(key)) {
        throw new TypeError(`${name}: unknown option ${JSON.stringify(key)} (accepted: ${accepted.join(', ')})`);
      }
    }
  }
  return value;
}
