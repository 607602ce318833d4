// The reliability suite, in headless Chromium (test/pages/reliability.js does the work in the page):
// - the bad-input table (test/reliability/badInputs.js): every line gives the error, the warning or
//   the sane frame it says, and no line leaves a GL error or a NaN pixel;
// - create/dispose cycles: live WebGL objects (counted by wrapping the context's create*/delete*
//   before the page runs) and renderer.info back at their baseline;
// - a soak: frames with option changes and a moving camera and light; no GL error, no NaN pixel,
//   and after each full cycle of changes the same live objects and a flat JS heap;
// - a WebGL context loss and restore: the same pixels after it.
// `npm run soak -- --minutes N` runs the soak for longer (scripts/soak.js).
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage } from '../harness/page.js';
import { ALL_CASES, CALL_CASES, FRAME_CASES } from '../reliability/badInputs.js';

let page;
beforeAll(async () => { page = await openPage('/test/pages/reliability.html'); });
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

/** The JS heap after a full garbage collection, with the array buffers' backing stores (outside V8's heap), bytes. */
async function heapAfterGc(client) {
  await client.send('HeapProfiler.collectGarbage');
  await client.send('HeapProfiler.collectGarbage');
  const { usedSize, backingStorageSize = 0 } = await client.send('Runtime.getHeapUsage');
  return usedSize + backingStorageSize;
}

describe('the bad-input table', () => {
  let results;
  beforeAll(async () => {
    results = await page.evaluate(() => window.reliability.badInputs());
  });

  it(`has ${ALL_CASES.length} cases (${CALL_CASES.length} calls, ${FRAME_CASES.length} frames), all run`, () => {
    expect(ALL_CASES.length).toBeGreaterThanOrEqual(120);
    expect(results.map((r) => r.input)).toEqual(ALL_CASES.map(([input]) => input));
  });

  ALL_CASES.forEach(([input, , expected, fragment], i) => {
    it(`${input}: ${expected}${fragment ? ` ${fragment}` : ''}`, () => {
      const r = results[i];
      expect(r.disposeError).toBeUndefined();
      expect(r.glError, 'a GL error').toBe(0);
      if (expected === 'TypeError' || expected === 'RangeError') {
        expect(r.error, 'no error was thrown').toBeDefined();
        expect(r.error.name).toBe(expected);
        expect(r.error.message).toMatch(fragment);
        return;
      }
      expect(r.error, r.error?.message).toBeUndefined();
      if (expected === 'ok') return;
      expect(r.frame.nonFinite, 'NaN pixels').toBe(0);
      if (expected === 'warning') {
        expect(r.warnings.filter((w) => fragment.test(w)), r.warnings.join('\n')).toHaveLength(1);
      } else {
        expect(r.warnings).toEqual([]);
        expect(r.frame.black, 'a black frame').toBeLessThan(0.5);
        expect(r.frame.mean).toBeGreaterThan(0.05);
      }
    });
  });
});

describe('under load', () => {
  it('create → render → dispose cycles leave no WebGL object, texture, geometry or program behind', async () => {
    const r = await page.evaluate(() => window.reliability.cycles({ count: 12 }));
    expect(r.errors).toEqual([]);
    expect(r.baseline.total).toBeGreaterThan(0);
    expect(r.after.gl).toEqual(r.baseline.gl);
    expect(r.after.memory).toEqual(r.baseline.memory);
    expect(r.after.programs).toBe(r.baseline.programs);
  });

  it('a soak of 1,000 frames with option changes and a moving camera and light: no GL error, no NaN, flat heap and objects', async () => {
    const client = await page.createCDPSession();
    const { cycleFrames, changes } = await page.evaluate(() => window.reliability.soakStart({ every: 25 }));
    expect(cycleFrames).toBe(500);
    const warm = await page.evaluate((n) => window.reliability.soakRun(n), cycleFrames);
    const heapWarm = await heapAfterGc(client);
    const end = await page.evaluate((n) => window.reliability.soakRun(n), cycleFrames);
    const heapEnd = await heapAfterGc(client);
    await page.evaluate(() => window.reliability.soakStop());
    await client.detach();
    expect(end.frames).toBe(1000);
    expect(end.changes).toBe(2 * changes - 1);
    expect(end.glErrors).toEqual([]);
    expect(end.reads).toBe(20);
    expect(end.nonFinite).toBe(0);
    expect(end.problems).toEqual([]);
    // After each full cycle of changes the pipeline is in the same state: it holds the same.
    expect(end.gl).toEqual(warm.gl);
    expect(end.memory).toEqual(warm.memory);
    expect(end.programs).toBe(warm.programs);
    expect(heapEnd - heapWarm, `heap ${heapWarm} → ${heapEnd} bytes`).toBeLessThan(512 * 1024);
  });

  it('gives the same pixels after a WebGL context loss and restore', async () => {
    const r = await page.evaluate(() => window.reliability.contextLoss());
    expect(r.lostFlag).toBe(true);
    expect(r.values).toBeGreaterThan(0);
    expect(r.litPixels).toBeGreaterThan(100);
    expect(r.nonFinite).toBe(0);
    expect(r.differing).toBe(0);
    expect(r.glError).toBe(0);
  });
});
