// The README's usage snippet runs as written: it is cut out of README.md, served as a module
// (the package name resolves to src/ through vite.config.js) and must draw a lit, scattered
// object with no console errors.
import { it, expect } from 'vitest';
import { readFileSync, mkdirSync, writeFileSync } from 'node:fs';
import { openPage } from '../harness/page.js';

const readme = readFileSync(new URL('../../README.md', import.meta.url), 'utf8');

it('the README usage snippet renders a subsurface object', async () => {
  const usage = readme.slice(readme.indexOf('## Usage'));
  const snippet = usage.match(/```js\n([\s\S]*?)```/)?.[1];
  expect(snippet, 'README.md has a ```js block under "## Usage"').toBeTruthy();
  expect(snippet).toContain("from 'three-separable-sss'");
  const dir = new URL('../pages/.generated/', import.meta.url);
  mkdirSync(dir, { recursive: true });
  writeFileSync(new URL('readme-snippet.js', dir), snippet);
  writeFileSync(new URL('readme.html', dir), [
    '<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"></head>',
    '<body style="margin:0;background:#000">',
    '<script type="module">',
    "import './readme-snippet.js';",
    // Two animation frames: the snippet's loop has rendered at least once.
    'requestAnimationFrame(() => requestAnimationFrame(() => { window.testReady = true; }));',
    '</script></body></html>',
  ].join('\n'));

  const page = await openPage('/test/pages/.generated/readme.html', { width: 320, height: 180 });
  // Read the canvas as the user sees it: a screenshot, decoded by the browser.
  const png = await page.screenshot({ encoding: 'base64' });
  const stats = await page.evaluate(async (data) => {
    const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    const { data: px } = ctx.getImageData(0, 0, bitmap.width, bitmap.height);
    let lit = 0;
    let red = 0;
    let blue = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (px[i] + px[i + 1] + px[i + 2] > 60) lit++;
      red += px[i];
      blue += px[i + 2];
    }
    return { lit: lit / (px.length / 4), red, blue };
  }, png);
  expect(stats.lit).toBeGreaterThan(0.02); // the object is there and lit
  expect(stats.red).toBeGreaterThan(stats.blue); // skin-coloured, scattered light
  expect(page.problems).toEqual([]);
  await page.close();
});
