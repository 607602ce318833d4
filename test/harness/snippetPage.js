// For the tests that run the README's snippets as written: a generated page that imports the
// snippet and says it is ready after some animation frames, and the plain statistics they check on
// what it drew.
import { mkdirSync, writeFileSync } from 'node:fs';

/**
 * Writes test/pages/.generated/<name>-snippet.js and <name>.html (git-ignored).
 * @param {string} name
 * @param {string} source the module
 * @param {number} [frames=2] animation frames before `window.testReady` (the snippet's loop has rendered)
 * @returns {string} the page's path on the server
 */
export function writeSnippetPage(name, source, frames = 2) {
  const dir = new URL('../pages/.generated/', import.meta.url);
  mkdirSync(dir, { recursive: true });
  writeFileSync(new URL(`${name}-snippet.js`, dir), source);
  writeFileSync(new URL(`${name}.html`, dir), [
    '<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"></head>',
    '<body style="margin:0;background:#000">',
    '<script type="module">',
    `import './${name}-snippet.js';`,
    `let frames = 0; const tick = () => (++frames >= ${frames} ? (window.testReady = true) : requestAnimationFrame(tick)); requestAnimationFrame(tick);`,
    '</script></body></html>',
  ].join('\n'));
  return `/test/pages/.generated/${name}.html`;
}

/**
 * The share of RGBA pixels whose r + g + b exceeds `threshold`, and the sums of red and blue.
 * @param {ArrayLike<number>} pixels
 * @param {number} threshold
 */
export function litAndTint(pixels, threshold) {
  let lit = 0;
  let red = 0;
  let blue = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    if (pixels[i] + pixels[i + 1] + pixels[i + 2] > threshold) lit++;
    red += pixels[i];
    blue += pixels[i + 2];
  }
  return { lit: lit / (pixels.length / 4), red, blue };
}
