// The footprint measure's pure parts (bench/footprint/surface.js): the package entries read from
// an "exports" map, the names a module namespace exports, a class's public members without its
// base's, the JSDoc tags of members read from source text, line counts, medians, the slider.
import { describe, it, expect } from 'vitest';
import {
  countLines, exportEntries, exportNames, median, memberTags, membersTagged, publicMembers, sliderSweep, specifierOf,
} from '../../../bench/footprint/surface.js';

describe('exportEntries', () => {
  it('every JS subpath, by its import condition (nested too), without package.json and patterns', () => {
    const pkg = {
      name: 'p',
      exports: {
        '.': { types: './d/index.d.ts', import: './dist/p.js', default: './dist/p.cjs' },
        './stages': { types: './d/s.d.ts', default: './dist/stages.js' },
        './webgpu': { import: { types: './d/w.d.ts', default: './dist/webgpu.mjs' } },
        './package.json': './package.json',
        './extra/*': './dist/extra/*.js',
        './gone': null,
      },
    };
    expect(exportEntries(pkg)).toEqual([
      { subpath: '.', target: './dist/p.js' },
      { subpath: './stages', target: './dist/stages.js' },
      { subpath: './webgpu', target: './dist/webgpu.mjs' },
    ]);
  });

  it('a string, a conditions-only object or no "exports" at all: the main entry alone', () => {
    expect(exportEntries({ exports: './index.js' })).toEqual([{ subpath: '.', target: './index.js' }]);
    expect(exportEntries({ exports: { import: './a.js', require: './a.cjs' } })).toEqual([{ subpath: '.', target: './a.js' }]);
    expect(exportEntries({ main: './main.js' })).toEqual([{ subpath: '.', target: './main.js' }]);
  });

  it('the specifier of each subpath', () => {
    expect(specifierOf('three-separable-sss', '.')).toBe('three-separable-sss');
    expect(specifierOf('three-separable-sss', './stages')).toBe('three-separable-sss/stages');
  });
});

describe('exportNames', () => {
  it('counts and sorts the runtime names of a namespace, with their kinds', () => {
    class Pipeline {}
    const namespace = Object.freeze({ __proto__: null, zeta: 3, Pipeline, make() {}, TABLE: Object.freeze([1]), options: {} });
    const out = exportNames(namespace);
    expect(out.count).toBe(5);
    expect(out.names).toEqual(['Pipeline', 'TABLE', 'make', 'options', 'zeta']);
    expect(out.kinds).toEqual({ Pipeline: 'class', TABLE: 'array', make: 'function', options: 'object', zeta: 'number' });
  });

  it('reads a real module namespace (this file\'s helpers)', async () => {
    const namespace = await import('../../../bench/footprint/surface.js');
    const out = exportNames(namespace);
    expect(out.names).toContain('exportNames');
    expect(out.count).toBe(Object.keys(namespace).length);
  });
});

describe('publicMembers', () => {
  class Base {
    constructor() { this.enabled = true; this.needsSwap = true; }
    render() {}
    setSize() {}
  }
  class Effect extends Base {
    static fromJSON() {}
    constructor() {
      super();
      this.needsSwap = false; // the base's: not counted
      this.scenePass = {};
      this._private = 1;
      this.plan = null;
    }
    get samples() { return 1; }
    set samples(v) {}
    render() {} // redefines the base's: not counted
    addTo() {}
    _internalStep() {}
  }

  it('prototype, static and instance names, without _names, constructor and the base\'s', () => {
    const m = publicMembers(Effect, { instance: new Effect(), baseInstance: new Base() });
    expect(m.names).toEqual(['addTo', 'fromJSON', 'plan', 'samples', 'scenePass']);
    expect(m.count).toBe(5);
    expect(m.prototype).toEqual(['addTo', 'samples']);
    expect(m.static).toEqual(['fromJSON']);
    expect(m.instance).toEqual(['plan', 'scenePass']);
  });

  it('without an instance: the prototypes and statics only; without a base instance, the base\'s instance fields count', () => {
    expect(publicMembers(Effect).names).toEqual(['addTo', 'fromJSON', 'samples']);
    expect(publicMembers(Effect, { instance: new Effect() }).names).toContain('needsSwap');
  });

  it('a class without a base stops at Object.prototype', () => {
    class Plain { constructor() { this.a = 1; } b() {} }
    expect(publicMembers(Plain, { instance: new Plain() }).names).toEqual(['a', 'b']);
  });
});

describe('memberTags', () => {
  const source = `
/** @typedef {object} Options */

export class Effect extends Pass {
  constructor(options) {
    super();
    /** @internal The scene pass. */
    this.scenePass = new ScenePass();
    /** What the last frame ran. */
    this.plan = null;
  }

  /** Taps per direction. @type {number} */
  get samples() { return 1; }

  /** @param {number} s */
  set samples(s) {}

  /** @internal */
  get kernel() { return this._k; }

  /**
   * @deprecated assign samples
   * @param {number} n
   */
  setSamples(n) {
    if (n) return;
  }

  /** @internal @deprecated both */
  static old() {}
}`;

  it('gives each JSDoc block to the declaration after it', () => {
    const tags = memberTags(source);
    expect([...tags.get('scenePass')]).toEqual(['internal']);
    expect([...tags.get('plan')]).toEqual([]);
    expect([...tags.get('samples')].sort()).toEqual(['param', 'type']);
    expect([...tags.get('setSamples')].sort()).toEqual(['deprecated', 'param']);
    expect([...tags.get('old')].sort()).toEqual(['deprecated', 'internal']);
    // A block followed by no member (the typedef) is given to nothing: not to the constructor.
    expect(tags.get('constructor')).toBeUndefined();
  });

  it('lists the members carrying @internal and @deprecated', () => {
    const tagged = membersTagged(['kernel', 'old', 'plan', 'samples', 'scenePass', 'setSamples'], memberTags(source));
    expect(tagged).toEqual({ internal: ['kernel', 'old', 'scenePass'], deprecated: ['old', 'setSamples'] });
  });
});

describe('countLines, median, sliderSweep', () => {
  it('counts lines as wc -l, plus an unterminated last line', () => {
    expect(countLines('')).toBe(0);
    expect(countLines('a\nb\n')).toBe(2);
    expect(countLines('a\nb')).toBe(2);
    expect(countLines('\n\n')).toBe(2);
  });

  it('medians of odd and even counts, and of none', () => {
    expect(median([5, 1, 3])).toBe(3);
    expect(median([4, 1, 3, 2])).toBe(2.5);
    expect(median([])).toBeNull();
  });

  it('the slider: every odd count 3..63 up, then back down without repeating the top', () => {
    const { up, down } = sliderSweep(3, 63);
    expect(up).toHaveLength(31);
    expect(up[0]).toBe(3);
    expect(up.at(-1)).toBe(63);
    expect(down).toHaveLength(30);
    expect(down[0]).toBe(61);
    expect(down.at(-1)).toBe(3);
  });
});
