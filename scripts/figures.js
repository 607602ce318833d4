// `npm run figures`: renders the paper's five before/after figures from the demo page in headless
// Chromium (SwiftShader) and writes docs/figures/figure-N-{before,after}.png and docs/FIGURES.md.
import { mkdir, writeFile, mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createServer } from 'vite';
import puppeteer from 'puppeteer';
import { findBrowser } from '../test/harness/findBrowser.js';
import { CHROMIUM_FLAGS } from '../test/harness/globalSetup.js';
import { FIGURES } from '../demo/figures.js';

const root = fileURLToPath(new URL('..', import.meta.url));
const outDir = join(root, 'docs/figures');
const WIDTH = 800;
const HEIGHT = 450;

async function main() {
  await mkdir(outDir, { recursive: true });
  const server = await createServer({ root, configFile: join(root, 'vite.config.js'), logLevel: 'error', server: { host: '127.0.0.1', port: 0, hmr: false } });
  const userDataDir = await mkdtemp(join(tmpdir(), 'sss-figures-'));
  let browser;
  try {
    await server.listen();
    const url = `http://127.0.0.1:${server.httpServer.address().port}/?still`;
    browser = await puppeteer.launch({ executablePath: await findBrowser(), headless: true, userDataDir, args: CHROMIUM_FLAGS });
    const page = await browser.newPage();
    const errors = [];
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('pageerror', (e) => errors.push(e.message));
    await page.setViewport({ width: WIDTH, height: HEIGHT, deviceScaleFactor: 1 });
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForFunction('window.testReady !== undefined');
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
    if (errors.length) throw new Error(`the page reported errors:\n${errors.join('\n')}`);
    for (const [name, png] of images) {
      await writeFile(join(outDir, name), png);
      console.log(`wrote docs/figures/${name}`);
    }
    await writeFile(join(root, 'docs/FIGURES.md'), figuresMarkdown());
    console.log('wrote docs/FIGURES.md');
  } finally {
    await browser?.close();
    await server.close();
    await rm(userDataDir, { recursive: true, force: true });
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
