// The bench's conclusions: Pareto front and the default setting, on rows with known answers.
import { describe, it, expect } from 'vitest';
import { dominates, paretoFront, isDefaultSetting, median } from '../../bench/analysis.js';

const row = (name, gpuMs, rmse, extra = {}) => ({ name, gpuMs, rmse, kind: 'separable', ...extra });

describe('bench analysis', () => {
  it('a row is dominated only by one at least as fast and as accurate and better in one', () => {
    expect(dominates(row('a', 1, 1), row('b', 2, 2))).toBe(true);
    expect(dominates(row('a', 1, 2), row('b', 2, 2))).toBe(true);
    expect(dominates(row('a', 2, 2), row('b', 2, 2))).toBe(false); // equal: no
    expect(dominates(row('a', 1, 3), row('b', 2, 2))).toBe(false); // faster but worse
  });

  it('the front keeps the undominated rows, fastest first, and leaves out the reference (error 0)', () => {
    const rows = [
      row('slow exact', 10, 0.1), row('fast rough', 1, 1), row('middle', 5, 0.5),
      row('dominated', 6, 0.6), row('reference', 20, 0), row('tie in time, worse', 5, 0.7),
    ];
    expect(paretoFront(rows).map((r) => r.name)).toEqual(['fast rough', 'middle', 'slow exact']);
  });

  it('the default setting is footprint, skin, 17 taps, not the auto row that chose 17', () => {
    const base = { kind: 'separable', method: 'footprint', profile: 'skin', samples: 17 };
    expect(isDefaultSetting(base)).toBe(true);
    expect(isDefaultSetting({ ...base, auto: true })).toBe(false);
    expect(isDefaultSetting({ ...base, profile: 'skinBurley' })).toBe(false);
    expect(isDefaultSetting({ ...base, samples: 25 })).toBe(false);
  });

  it('median of odd and even counts', () => {
    expect(median([3, 1, 2])).toBe(2);
    expect(median([4, 1, 3, 2])).toBe(2.5);
    expect(median([])).toBeNaN();
  });
});
