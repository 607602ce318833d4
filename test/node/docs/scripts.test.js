// The README's table of scripts is package.json's scripts, one for one (the test layers' commands
// among them).
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';

const read = (path) => readFileSync(new URL(`../../../${path}`, import.meta.url), 'utf8');

describe("the README's scripts", () => {
  it("list package.json's scripts, one for one", () => {
    const readme = read('README.md');
    const table = readme.slice(readme.indexOf('## Scripts'), readme.indexOf('## Credits'));
    const listed = [...table.matchAll(/^\| `npm (?:run )?([\w:-]+)` \|/gm)].map((m) => m[1]).sort();
    const { scripts } = JSON.parse(read('package.json'));
    // The build's parts and prepack run inside `npm run build` and `npm pack`; the table names those.
    const internal = ['build:lib', 'build:types', 'prepack'];
    expect(listed).toEqual(Object.keys(scripts).filter((name) => !internal.includes(name)).sort());
  });
});
