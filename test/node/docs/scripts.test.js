// CONTRIBUTING.md's table of scripts is package.json's scripts, one for one (the test layers'
// commands among them).
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';

const read = (path) => readFileSync(new URL(`../../../${path}`, import.meta.url), 'utf8');

describe("CONTRIBUTING.md's scripts", () => {
  it("list package.json's scripts, one for one", () => {
    const doc = read('CONTRIBUTING.md');
    const start = doc.indexOf('## Scripts');
    expect(start).toBeGreaterThan(0);
    const table = doc.slice(start, doc.indexOf('\n## ', start + 1));
    const listed = [...table.matchAll(/^\| `npm (?:run )?([\w:-]+)` \|/gm)].map((m) => m[1]).sort();
    const { scripts } = JSON.parse(read('package.json'));
    // The build's parts and prepack run inside `npm run build` and `npm pack`; the table names those.
    const internal = ['build:lib', 'build:types', 'prepack'];
    expect(listed).toEqual(Object.keys(scripts).filter((name) => !internal.includes(name)).sort());
  });
});
