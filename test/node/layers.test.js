// Every test file is in one of the three layers that `npm test` runs (vitest.config.js's projects):
// a file left in another folder (test/unit/, as before the layers) would silently not run.
import { describe, it, expect } from 'vitest';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../', import.meta.url));

describe('the test layers', () => {
  it('hold every test file: test/node/, test/browser/ or test/packaging/', () => {
    const files = execFileSync('git', ['ls-files', '--cached', '--others', '--exclude-standard', '*.test.js', '*.test.ts'], { cwd: root, encoding: 'utf8' })
      .trim().split('\n').filter(Boolean);
    expect(files.length).toBeGreaterThan(30);
    expect(files.filter((f) => !/^test\/(node|browser|packaging)\//.test(f))).toEqual([]);
  });
});
