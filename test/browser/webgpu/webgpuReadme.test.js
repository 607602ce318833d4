// The README's WebGPURenderer snippet runs as written, in the WebGPU browser: it is cut out of
// README.md, put after the usage snippet's scene (its lines from `const scene` to
// `scene.add(disc);`, which the snippet says it uses), served as a module (the package names
// resolve to src/ through vite.config.js) and must draw a lit, skin-coloured object with no console
// errors.
import { it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { screenshotPixels } from '../../harness/page.js';
import { litAndTint, writeSnippetPage } from '../../harness/snippetPage.js';
import { openWebgpuPage } from '../../harness/webgpuBrowser.js';

const readme = readFileSync(new URL('../../../README.md', import.meta.url), 'utf8');
const blockAfter = (heading) => readme.slice(readme.indexOf(heading)).match(/```js\n([\s\S]*?)```/)?.[1];

it('the README WebGPURenderer snippet renders a subsurface object', async () => {
  const usage = blockAfter('## Usage');
  const snippet = blockAfter('### WebGPURenderer');
  expect(snippet, 'README.md has a ```js block under "### WebGPURenderer"').toContain("from 'three-separable-sss/webgpu'");
  const scene = usage.slice(usage.indexOf('const scene'), usage.indexOf('scene.add(disc);') + 'scene.add(disc);'.length);
  expect(scene).toContain('const skin');
  // A few animation frames: the snippet's loop has rendered (WebGPURenderer initialises first).
  const path = writeSnippetPage('webgpu-readme', `${scene}\n${snippet}\n`, 10); // the scene first: imports are hoisted, statements are not

  const page = await openWebgpuPage(path, { width: 320, height: 180 });
  const { data } = await screenshotPixels(page);
  const { lit, red, blue } = litAndTint(data, 60);
  expect(lit).toBeGreaterThan(0.02); // the object is there and lit
  expect(red).toBeGreaterThan(blue); // skin-coloured, scattered light
  expect(page.problems).toEqual([]);
  await page.close();
});
