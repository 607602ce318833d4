import { describe, it, expect } from 'vitest';
import { Color, Vector3 } from 'three';
import { checkNumber, checkInteger, checkOddInteger, checkRgb, checkOneOf, describeValue } from '../../../src/support/parameterChecks.js';

describe('checkNumber', () => {
  it('returns accepted values', () => {
    expect(checkNumber('widthMm', 3, { min: 0, max: 100 })).toBe(3);
    expect(checkNumber('x', 0, { min: 0 })).toBe(0);
    expect(checkNumber('x', -1e300)).toBe(-1e300);
  });
  it('throws TypeError naming the parameter for non-finite or non-numbers', () => {
    expect(() => checkNumber('widthMm', NaN)).toThrow(new TypeError('widthMm must be a finite number, got NaN'));
    expect(() => checkNumber('widthMm', Infinity)).toThrow(TypeError);
    expect(() => checkNumber('widthMm', '3')).toThrow(/widthMm must be a finite number, got "3"/);
    expect(() => checkNumber('widthMm', undefined)).toThrow(TypeError);
  });
  it('throws RangeError with the interval and unit', () => {
    expect(() => checkNumber('widthMm', -1, { min: 0, max: 100, unit: 'mm' })).toThrow(
      new RangeError('widthMm must be in [0, 100] mm, got -1'),
    );
    expect(() => checkNumber('falloff', 0, { min: 0, max: 10, minExclusive: true })).toThrow(
      new RangeError('falloff must be in (0, 10], got 0'),
    );
    expect(() => checkNumber('f', 1, { min: 0, max: 1, maxExclusive: true })).toThrow(/\[0, 1\)/);
    expect(() => checkNumber('f', -2, { min: 0 })).toThrow(/\[0, ∞\)/);
  });
});

describe('checkInteger', () => {
  it('accepts integers in range and names the range and unit otherwise', () => {
    expect(checkInteger('size', 1024, 16, 8192, 'pixels')).toBe(1024);
    expect(() => checkInteger('size', 10, 16, 8192, 'pixels')).toThrow(new RangeError('size must be an integer in 16..8192 pixels, got 10'));
    expect(() => checkInteger('size', 16.5, 16, 8192)).toThrow(new RangeError('size must be an integer in 16..8192, got 16.5'));
    expect(() => checkInteger('size', '16', 16, 8192)).toThrow(TypeError);
  });
});

describe('checkOddInteger', () => {
  it('accepts odd integers in range', () => {
    for (const n of [3, 5, 17, 63]) expect(checkOddInteger('samples', n, 3, 63)).toBe(n);
  });
  it('rejects even, fractional, out of range (RangeError) and non-numbers (TypeError) with the range', () => {
    const cases = [
      [4, RangeError],
      [2, RangeError],
      [1, RangeError],
      [65, RangeError],
      [17.5, RangeError],
      [-3, RangeError],
      [NaN, TypeError],
      ['17', TypeError],
      [null, TypeError],
    ];
    for (const [value, type] of cases) {
      expect(() => checkOddInteger('samples', value, 3, 63)).toThrow(type);
      expect(() => checkOddInteger('samples', value, 3, 63)).toThrow(/samples must be an odd integer in 3\.\.63, got /);
    }
    expect(() => checkOddInteger('samples', 4, 3, 63)).toThrow('samples must be an odd integer in 3..63, got 4');
  });
});

describe('checkRgb', () => {
  it('returns a plain copy', () => {
    const input = new Float32Array([0.5, 0.25, 1]);
    const out = checkRgb('strength', input, { min: 0, max: 1 });
    expect(out).toEqual([0.5, 0.25, 1]);
    expect(Array.isArray(out)).toBe(true);
  });
  it('throws TypeError for wrong shapes, RangeError naming the component', () => {
    expect(() => checkRgb('strength', [1, 2])).toThrow(/strength must be an array of 3 finite numbers, got \[1, 2\]/);
    // three's own RGB types read as [r, g, b] (and a Color or Vector3 out of range is refused the same).
    expect(checkRgb('strength', new Color(1, 0.5, 0.25))).toEqual([1, 0.5, 0.25]);
    expect(checkRgb('strength', new Vector3(0.2, 0.4, 0.6))).toEqual([0.2, 0.4, 0.6]);
    expect(() => checkRgb('strength', new Color(2, 0, 0), { min: 0, max: 1 })).toThrow(/strength\[0\] must be in \[0, 1\], got 2/);
    expect(() => checkRgb('strength', [1, NaN, 2])).toThrow(TypeError);
    expect(() => checkRgb('strength', 0.5)).toThrow(TypeError);
    expect(() => checkRgb('strength', [0, 2, 0], { min: 0, max: 1 })).toThrow(new RangeError('strength[1] must be in [0, 1], got 2'));
  });
});

describe('checkOneOf', () => {
  it('accepts members and names the list otherwise', () => {
    expect(checkOneOf('method', 'marginal', ['reference', 'marginal'])).toBe('marginal');
    expect(() => checkOneOf('method', 'foo', ['reference', 'marginal'])).toThrow(
      new RangeError(`method must be one of 'reference', 'marginal', got "foo"`),
    );
    expect(() => checkOneOf('method', 3, ['reference', 'marginal'])).toThrow(TypeError);
  });
  it('describes values readably', () => {
    expect(describeValue([1, 'a'])).toBe('[1, "a"]');
    expect(describeValue({})).toBe('an object (Object)');
    expect(describeValue(undefined)).toBe('undefined');
  });
});
