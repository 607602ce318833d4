// The bench's conclusions: Pareto front and the default setting, on rows with known answers.
import { describe, it, expect } from 'vitest';
import { dominates, paretoFront, isDefaultSetting, median, spread, peerSummary, autoAgainstFixed } from '../../../bench/analysis.js';

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

  it("the default setting is footprint, skin, samples 'auto' (PIPELINE_DEFAULTS), not a fixed budget", async () => {
    const { PIPELINE_DEFAULTS } = await import('../../../src/options.js');
    expect([PIPELINE_DEFAULTS.method, PIPELINE_DEFAULTS.profile, PIPELINE_DEFAULTS.samples]).toEqual(['footprint', 'skin', 'auto']);
    const auto = { kind: 'separable', method: 'footprint', profile: 'skin', samples: 'auto', auto: true };
    expect(isDefaultSetting(auto)).toBe(true);
    expect(isDefaultSetting({ ...auto, auto: false, samples: 17 })).toBe(false);
    expect(isDefaultSetting({ ...auto, profile: 'skinBurley' })).toBe(false);
    expect(isDefaultSetting({ ...auto, method: 'marginal' })).toBe(false);
  });

  it('the side-by-side: overheads over each plain frame and their ratio per round, then median and range', () => {
    // Two rounds written out by hand. Round 1: ours 300 − 100 = 200 against Babylon 250 − 50 = 200
    // (ratio 1); round 2: 220 − 120 = 100 against 290 − 90 = 200 (ratio 0.5).
    const t = (timerMs, cpuMs = 2 * timerMs) => ({ timerMs, cpuMs });
    const rounds = [
      { threePlain: t(100), ours: t(300), babylonPlain: t(50), babylonSss: t(250), blur: t(90), floor: t(30),
        stages: { lightDepth: NaN, scene: 150, blurH: 45, blurV: 45, compose: 10, transparent: 0 } },
      { threePlain: t(120), ours: t(220), babylonPlain: t(90), babylonSss: t(290), blur: t(60), floor: t(40),
        stages: { lightDepth: 12, scene: 140, blurH: 30, blurV: 30, compose: 8, transparent: 0 } },
    ];
    const s = peerSummary(rounds);
    expect(s.overhead.timer.ours).toEqual({ median: 150, min: 100, max: 200, n: 2 });
    expect(s.overhead.timer.ratio).toEqual({ median: 0.75, min: 0.5, max: 1, n: 2 });
    expect(s.overhead.cpu.ratio.median).toBeCloseTo(0.75, 12); // the CPU times are twice the timer's here
    expect(s.blurOverFloor.timer).toEqual({ median: 2.25, min: 1.5, max: 3, n: 2 });
    // Everything but the blur over the plain frame: (0 + 150 + 10 + 0 − 100) / 100 and (12 + 140 + 8 − 120) / 120.
    expect(s.nonBlurShare.min).toBeCloseTo(1 / 3, 12);
    expect(s.nonBlurShare.max).toBeCloseTo(0.6, 12);
    expect(s.stages.lightDepth).toBe(6); // a stage that did not run counts 0: median of 0 and 12
    // Without the CPU clock the CPU parts are null, not NaN-filled.
    const noClock = peerSummary(rounds.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, k === 'stages' ? v : { ...v, cpuMs: null }]))));
    expect(noClock.overhead.cpu).toBeNull();
    expect(noClock.blurOverFloor.cpu).toBeNull();
    expect(spread([3, NaN, 1, 2])).toEqual({ median: 2, min: 1, max: 3, n: 3 });
  });

  it("'auto' is held against the cheapest fixed budget within 1 % of its error, and the budget the scene needs", () => {
    const r = (samples, rmse, gpuMs, extra = {}) => ({ kind: 'separable', method: 'footprint', profile: 'skin', scene: 'head', resolution: '640x360', samples, rmse, gpuMs, ...extra });
    const rows = [
      r('auto', 0.01, 55, { auto: true, sssCpuMs: 100 }),
      r(5, 0.02, 30, { sssCpuMs: 60 }), // too inaccurate
      r(9, 0.0100999, 50, { sssCpuMs: 90 }), // within 1 % of auto's error: the cheapest that reaches it
      r(17, 0.0098, 80, { sssCpuMs: 150 }), // more accurate, dearer
      r(25, 0.0098, 90, { sssCpuMs: 170 }),
      r(9, 0.5, 1, { scene: 'slab' }), // another scene: not compared with this auto
    ];
    const [c] = autoAgainstFixed(rows);
    expect(c.cheapest.samples).toBe(9);
    expect(c.timeRatio).toBeCloseTo(55 / 50, 12);
    expect(c.needed.samples).toBe(17); // within 2 % of the best (0.0098); 9 is 3 % above it
    expect(autoAgainstFixed(rows, 'sssCpuMs')[0].timeRatio).toBeCloseTo(100 / 90, 12);
    // No fixed budget as accurate: no ratio.
    const [none] = autoAgainstFixed([r('auto', 0.001, 10, { auto: true }), r(9, 0.002, 5)]);
    expect(none.cheapest).toBeNull();
    expect(none.timeRatio).toBeNaN();
  });

  it('median of odd and even counts', () => {
    expect(median([3, 1, 2])).toBe(2);
    expect(median([4, 1, 3, 2])).toBe(2.5);
    expect(median([])).toBeNaN();
  });
});
