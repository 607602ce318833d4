// The pure parts of the footprint measure (bench/footprint/run.js): which package entries there
// are, the runtime names a module namespace exports, a class's public members, the JSDoc tags of
// a source's members, line counts and medians. No I/O here: test/node/bench/footprint.test.js.

/**
 * The JavaScript entries of package.json's "exports": { subpath, target } for each subpath whose
 * target (its "import", else "default", else "node" condition, nested conditions followed) is a
 * .js/.mjs file; "./package.json", patterns ("./x/*") and null targets are left out. A string
 * "exports" is the main entry alone.
 * @param {object} pkg package.json, parsed
 * @returns {{ subpath: string, target: string }[]} in the order package.json lists them
 */
export function exportEntries(pkg) {
  let exports = pkg.exports;
  if (exports === undefined) exports = pkg.module ?? pkg.main;
  if (typeof exports === 'string' || Array.isArray(exports)) exports = { '.': exports };
  if (exports === null || typeof exports !== 'object') return [];
  // Conditions only at the top ({ import, default }): the main entry alone.
  if (Object.keys(exports).length > 0 && Object.keys(exports).every((key) => !key.startsWith('.'))) exports = { '.': exports };
  const entries = [];
  for (const [subpath, value] of Object.entries(exports)) {
    if (subpath.includes('*')) continue;
    const target = conditionTarget(value);
    if (target && /\.m?js$/.test(target)) entries.push({ subpath, target });
  }
  return entries;
}

/** The file a conditional export target resolves to for `import` in Node, or null. */
function conditionTarget(value) {
  if (typeof value === 'string') return value;
  if (Array.isArray(value)) {
    for (const item of value) { const t = conditionTarget(item); if (t) return t; }
    return null;
  }
  if (value === null || typeof value !== 'object') return null;
  for (const condition of ['import', 'node', 'default']) {
    if (condition in value) { const t = conditionTarget(value[condition]); if (t) return t; }
  }
  return null;
}

/** The specifier that imports `subpath` of package `name`: '.' → name, './x' → name/x. */
export function specifierOf(name, subpath) {
  return subpath === '.' ? name : `${name}/${subpath.replace(/^\.\//, '')}`;
}

/**
 * The runtime export names of a module namespace, sorted, each with its kind (class, function,
 * object, number, ...).
 * @param {object} namespace what `await import(...)` gave
 * @returns {{ count: number, names: string[], kinds: Record<string, string> }}
 */
export function exportNames(namespace) {
  const names = Object.keys(namespace).sort();
  const kinds = {};
  for (const name of names) kinds[name] = kindOf(namespace[name]);
  return { count: names.length, names, kinds };
}

function kindOf(value) {
  if (typeof value === 'function') {
    return /^class[\s{]/.test(Function.prototype.toString.call(value)) ? 'class' : 'function';
  }
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'array';
  return typeof value;
}

const BUILTIN_STATICS = new Set(['length', 'name', 'prototype', 'caller', 'arguments']);

/**
 * A class's public members: the names on its prototypes (up to, not including, its base class's
 * prototype or Object.prototype), its static names, and the own names of an instance; without
 * 'constructor', names starting with '_' and the names the base class has (on its prototypes or an
 * instance of it: for a three.js Pass, enabled, needsSwap, clear, renderToScreen, isPass, setSize,
 * render, dispose).
 * @param {Function} klass
 * @param {{ instance?: object|null, base?: Function|null, baseInstance?: object|null }} [options]
 *   `base` defaults to klass's parent class; `baseInstance` to null (only the base's prototype names
 *   are excluded then)
 * @returns {{ count: number, names: string[], prototype: string[], static: string[], instance: string[] }}
 *   `instance`: the instance's own names not already on the prototypes
 */
export function publicMembers(klass, { instance = null, base, baseInstance = null } = {}) {
  if (base === undefined) {
    const parent = Object.getPrototypeOf(klass);
    base = parent && parent !== Function.prototype ? parent : null;
  }
  const stop = base ? base.prototype : Object.prototype;
  const baseNames = new Set(base ? namesAlongChain(base.prototype, Object.prototype) : []);
  if (baseInstance) for (const name of Object.getOwnPropertyNames(baseInstance)) baseNames.add(name);
  const keep = (name) => name !== 'constructor' && !name.startsWith('_') && !baseNames.has(name);

  const prototype = namesAlongChain(klass.prototype, stop).filter(keep).sort();
  const statics = Object.getOwnPropertyNames(klass).filter((name) => !BUILTIN_STATICS.has(name) && keep(name)).sort();
  const onPrototype = new Set(prototype);
  const own = instance ? Object.getOwnPropertyNames(instance).filter((name) => keep(name) && !onPrototype.has(name)).sort() : [];
  const names = [...new Set([...prototype, ...statics, ...own])].sort();
  return { count: names.length, names, prototype, static: statics, instance: own };
}

/** The own string names of `object` and of its prototypes, up to (not including) `stop`. */
function namesAlongChain(object, stop) {
  const names = new Set();
  for (let o = object; o && o !== stop && o !== Object.prototype; o = Object.getPrototypeOf(o)) {
    for (const name of Object.getOwnPropertyNames(o)) names.add(name);
  }
  return [...names];
}

/**
 * The JSDoc tags of a class's members, read from its source (best effort: a regex reading, not a
 * parser): each `/** ... *\/` block is given to the declaration that follows it, a method, an
 * accessor (`get name()`, `set name(...)`), a static or an assignment `this.name =` in the
 * constructor. A member declared twice (getter and setter) has the tags of both.
 * @param {string} source the class's file
 * @returns {Map<string, Set<string>>} member name → its tags ('internal', 'deprecated', ...)
 */
export function memberTags(source) {
  const tags = new Map();
  const block = /\/\*\*((?:(?!\*\/)[\s\S])*)\*\/\s*(?:(?:static|async|get|set)\s+)*(?:this\.([A-Za-z_$][\w$]*)\s*=|([A-Za-z_$][\w$]*)\s*\()/g;
  for (const m of source.matchAll(block)) {
    const name = m[2] ?? m[3];
    if (['if', 'for', 'while', 'switch', 'function', 'return', 'catch'].includes(name)) continue;
    const found = [...m[1].matchAll(/@([A-Za-z]+)/g)].map((t) => t[1]);
    if (!tags.has(name)) tags.set(name, new Set());
    for (const tag of found) tags.get(name).add(tag);
  }
  return tags;
}

/**
 * The members among `names` that carry each of `wanted` tags.
 * @param {string[]} names
 * @param {Map<string, Set<string>>} tags from memberTags
 * @param {string[]} [wanted]
 * @returns {Record<string, string[]>}
 */
export function membersTagged(names, tags, wanted = ['internal', 'deprecated']) {
  const out = {};
  for (const tag of wanted) out[tag] = names.filter((name) => tags.get(name)?.has(tag)).sort();
  return out;
}

/** Lines of a text file as `wc -l` counts them, plus a last line without its newline. */
export function countLines(text) {
  if (text.length === 0) return 0;
  const newlines = text.split('\n').length - 1;
  return text.endsWith('\n') ? newlines : newlines + 1;
}

/** The median of a list of numbers (the mean of the middle two for an even count), or null. */
export function median(values) {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/** The odd sample counts of a slider from `low` to `high` and back down: [3, 5, ..., 63, 61, ..., 3]. */
export function sliderSweep(low = 3, high = 63) {
  const up = [];
  for (let s = low; s <= high; s += 2) up.push(s);
  return { up, down: up.slice(0, -1).reverse() };
}
