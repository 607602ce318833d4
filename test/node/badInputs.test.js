// The bad-input table's calls (test/reliability/badInputs.js, CALL_CASES) in plain Node: each gives
// the named TypeError or RangeError its line says, before anything is drawn. The browser runs the
// same lines, and the cases that need a frame (test/browser/reliability.test.js).
import { describe, it, expect } from 'vitest';
import * as THREE from 'three';
import * as SSS from '../harness/sss.js';
import { CALL_CASES, FRAME_CASES } from '../reliability/badInputs.js';
import { createFixture } from '../reliability/fixture.js';
import { expectOutcome } from '../reliability/expectError.js';

describe('the bad-input table, in Node', () => {
  it('has one line per case, each with an outcome and (for errors and warnings) a message fragment', () => {
    const inputs = [...CALL_CASES, ...FRAME_CASES].map(([input]) => input);
    expect(new Set(inputs).size).toBe(inputs.length);
    for (const [input, run, expected, fragment] of [...CALL_CASES, ...FRAME_CASES]) {
      expect(typeof run, input).toBe('function');
      expect(['TypeError', 'RangeError', 'warning', 'sane', 'ok'], input).toContain(expected);
      if (expected !== 'sane' && expected !== 'ok') expect(fragment, input).toBeInstanceOf(RegExp);
    }
  });

  for (const [input, run, expected, fragment] of CALL_CASES) {
    it(`${input}: ${expected === 'ok' ? 'works' : `${expected} ${fragment}`}`, () => {
      const t = createFixture(THREE, SSS);
      try {
        expectOutcome(run, t, expected, fragment);
      } finally {
        t.dispose();
      }
    });
  }
});
