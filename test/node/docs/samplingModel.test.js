// The blur's sampling model is stated once, numbered, in docs/ARCHITECTURE.md; the other places that
// describe it cite that statement (issue 18: three of five restatements had drifted to version 0.1).
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';

const read = (path) => readFileSync(new URL(`../../../${path}`, import.meta.url), 'utf8');
const TITLE = 'Stage 3: the sampling model';

describe('the sampling model', () => {
  it('is one numbered statement in docs/ARCHITECTURE.md, items 1 to 8, the footprint mode 8.1 to 8.5', () => {
    const doc = read('docs/ARCHITECTURE.md');
    const section = doc.slice(doc.indexOf(`## ${TITLE}`), doc.indexOf('### Why the footprint method is the default'));
    expect(section.length).toBeGreaterThan(1000);
    const items = [...section.matchAll(/^(\d)\. \*\*/gm)].map((m) => Number(m[1]));
    expect(items).toEqual([1, 2, 3, 4, 5, 6, 7, 8]);
    const footprintItems = [...section.slice(section.indexOf('8. **')).matchAll(/^ {3}(\d)\. \*/gm)].map((m) => Number(m[1]));
    expect(footprintItems).toEqual([1, 2, 3, 4, 5]);
  });

  it('is cited, not restated, by the README, src/options.js, the blur shader and the oracle', () => {
    for (const path of ['README.md', 'src/options.js', 'shaders/3-blur/blurTaps.glsl', 'test/oracle/convolution.js']) {
      const text = read(path).replace(/\s+(\/\/|\*)?\s*/g, ' ');
      expect(text, path).toMatch(/ARCHITECTURE\.md/);
      expect(text, path).toMatch(/Stage 3: the sampling model|stage-3-the-sampling-model/);
      // Version 0.1's wording of the footprint mode.
      expect(text, path).not.toMatch(/marginal kernel's footprints (are )?snapped/);
    }
  });
});
