// One bad-input line's check, for the tables' runners (test/node/badInputs.test.js for the WebGL
// pipeline, test/node/webgpu/webgpuBadInputs.test.js for the WebGPURenderer node): `run(t)` works
// ('ok'), or throws the named error class with a message matching the line's fragment.
import { expect } from 'vitest';

/**
 * @param {(t: object) => unknown} run the line's call
 * @param {object} t the fixture
 * @param {'TypeError'|'RangeError'|'ok'} expected
 * @param {RegExp} [fragment]
 */
export function expectOutcome(run, t, expected, fragment) {
  if (expected === 'ok') {
    expect(() => run(t)).not.toThrow();
    return;
  }
  let error = null;
  try { run(t); } catch (e) { error = e; }
  expect(error, 'no error was thrown').not.toBe(null);
  expect(error.constructor.name).toBe(expected);
  expect(error.message).toMatch(fragment);
}
