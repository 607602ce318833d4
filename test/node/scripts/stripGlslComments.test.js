// The builds' shaders without comments (scripts/stripGlslComments.js): the same code, line for line.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { glslCommentsStripped, stripGlslComments } from '../../../scripts/stripGlslComments.js';

const shaders = fileURLToPath(new URL('../../../shaders/', import.meta.url));
const glslFiles = (dir) => readdirSync(dir).flatMap((name) => {
  const path = join(dir, name);
  return statSync(path).isDirectory() ? glslFiles(path) : name.endsWith('.glsl') ? [path] : [];
});

describe('stripGlslComments', () => {
  it('drops line and block comments, blank lines and indentation, and keeps the lines of code apart', () => {
    expect(stripGlslComments('a; // x /* y\n\tb /* c // d */ e;\n  #define X 1 // z\nf /* g\nh */ i;\n\n')).toBe('a;\nb   e;\n#define X 1\nf\ni;');
    expect(stripGlslComments('#if A // a /* not a block\n#endif')).toBe('#if A\n#endif');
    expect(() => stripGlslComments('a; /* open')).toThrow(SyntaxError);
    expect(() => stripGlslComments('#define A 1 \\\n  + 2')).toThrow(/line continuation/);
  });

  it("leaves every shader's code as it is: the same lines, without what follows // (they hold no block comment)", () => {
    const files = glslFiles(shaders);
    expect(files.length).toBeGreaterThanOrEqual(20);
    for (const file of files) {
      const source = readFileSync(file, 'utf8');
      expect(source.includes('/*'), file).toBe(false);
      const expected = source.split('\n').map((line) => line.split('//')[0].trim()).filter(Boolean).join('\n');
      expect(stripGlslComments(source), file).toBe(expected);
    }
  });

  it('is what a build loads for a .glsl?raw import, and nothing else', async () => {
    const plugin = glslCommentsStripped();
    expect(plugin.apply).toBe('build');
    const file = join(shaders, 'common/finite.glsl');
    const module = await plugin.load(`${file}?raw`);
    expect(JSON.parse(module.match(/^export default (.*);\n$/s)[1])).toBe(stripGlslComments(readFileSync(file, 'utf8')));
    expect(await plugin.load(file)).toBeNull();
    expect(await plugin.load(`${fileURLToPath(import.meta.url)}?raw`)).toBeNull();
  });
});
