// The README's usage snippet runs as written: it is cut out of README.md, served as a module
// (the package name resolves to src/ through vite.config.js) and must draw a lit, scattered
// object with no console errors.
import { it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { openPage, screenshotPixels } from '../harness/page.js';
import { litAndTint, writeSnippetPage } from '../harness/snippetPage.js';

const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8');

it('the README usage snippet renders a subsurface object', async () => {
  const usage = readme.slice(readme.indexOf('## Usage'));
  const snippet = usage.match(/```js\n([\s\S]*?)```/)?.[1];
  expect(snippet, 'README.md has a ```js block under "## Usage"').toBeTruthy();
  expect(snippet).toContain("from 'three-separable-sss'");
  const path = writeSnippetPage('readme', snippet);

  const page = await openPage(path, { width: 320, height: 180 });
  // Read the canvas as the user sees it: a screenshot, decoded by the browser.
  const stats = litAndTint((await screenshotPixels(page)).data, 60);
  expect(stats.lit).toBeGreaterThan(0.02); // the object is there and lit
  expect(stats.red).toBeGreaterThan(stats.blue); // skin-coloured, scattered light
  expect(page.problems).toEqual([]);
  await page.close();
});
