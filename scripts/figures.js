// `npm run figures`: renders the paper's five before/after figures from the demo page in headless
// Chromium (SwiftShader) and writes docs/figures/figure-N-{before,after}.png and docs/FIGURES.md.
import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../dev/browser.js';
import { FIGURES } from '../demo/figures.js';

const root = fileURLToPath(new URL('..', import.meta.url));
const outDir = join(root, 'docs/figures');
const WIDTH = 800;
const HEIGHT = 450;

async function main() {
  await mkdir(outDir, { recursive: true });
  const session = await startBrowser();
  try {
    const page = await openReadyPage(session.browser, `${session.baseUrl}/?still`, { width: WIDTH, height: HEIGHT });
    if (!(await page.evaluate('window.testReady'))) throw new Error('the demo did not start');
    const standIn = await page.evaluate(() => {
      window.demo.stop();
      window.demo.panel.gui.hide();
      for (const id of ['attribution', 'notices']) document.getElementById(id).style.display = 'none';
      return window.demo.isStandIn;
    });
    if (standIn) console.warn('The head scan is missing: the figures show the procedural stand-in (run npm run assets).');
    const images = new Map();
    for (const figure of FIGURES) {
      for (const side of ['before', 'after']) {
        await page.evaluate((id, s) => { window.demo.figure(id, s); window.demo.render(); }, figure.id, side);
        images.set(`figure-${figure.id}-${side}.png`, await page.screenshot({ clip: { x: 0, y: 0, width: WIDTH, height: HEIGHT } }));
      }
    }
    // Keep the committed figures unless every new one rendered cleanly.
    if (page.problems.length) throw new Error(`the page reported errors:\n${page.problems.join('\n')}`);
    for (const [name, png] of images) {
      await writeFile(join(outDir, name), png);
      console.log(`wrote docs/figures/${name}`);
    }
    await writeFile(join(root, 'docs/FIGURES.md'), figuresMarkdown());
    console.log('wrote docs/FIGURES.md');
  } finally {
    await session.close();
  }
}

function figuresMarkdown() {
  const sections = FIGURES.map((f) => {
    const [label, before, after] = {
      transmittance: ['transmittance', 'off', 'on'],
      sss: ['scattering', 'off', 'on'],
      followSurface: ['depth consideration', 'off', 'on (drop and renormalise)'],
    }[f.toggle];
    return [
      `## Figure ${f.id}. ${f.title}`,
      '',
      f.caption,
      '',
      `| ${label} ${before} | ${label} ${after} |`,
      '|---|---|',
      `| ![Figure ${f.id}, ${label} ${before}](figures/figure-${f.id}-before.png) | ![Figure ${f.id}, ${label} ${after}](figures/figure-${f.id}-after.png) |`,
      '',
      `Open it in the demo: \`#figure=${f.id}\` (the panel's "The paper's figures" buttons switch between the two).`,
      '',
    ].join('\n');
  });
  return [
    '# The paper\'s figures',
    '',
    'The five before/after comparisons of Tetzlaff\'s *Separable Subsurface Scattering: An OpenGL',
    'Implementation* (2013), rendered by the demo page in headless Chromium (SwiftShader, 800 × 450)',
    'with `npm run figures`. Each pair differs in one setting only.',
    '',
    ...sections,
    'Head: “Infinite, 3D Head Scan” by Lee Perry-Smith (Infinite-Realities), CC BY 3.0, as',
    'distributed with the three.js examples.',
    '',
  ].join('\n');
}

main().catch((error) => {
  console.error(error.message);
  process.exitCode = 1;
});
