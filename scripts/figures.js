// `npm run figures`: renders the paper's five before/after figures from the demo page in headless
// Chromium (SwiftShader) and writes docs/figures/figure-N-{before,after}.png and docs/FIGURES.md,
// then screenshots of the whole page (docs/screenshots/: the first view the README shows, the
// narrow layout, figure 2) with its header, panel, divider and timings.
import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../dev/browser.js';
import { FIGURES } from '../demo/figures.js';
import { profiles } from '../src/profiles/presets.js';

const root = fileURLToPath(new URL('..', import.meta.url));
const outDir = join(root, 'docs/figures');
const screenshotDir = join(root, 'docs/screenshots');
const WIDTH = 800;
const HEIGHT = 450;

/** The page as a visitor sees it. */
const SCREENSHOTS = [
  { name: 'first-view.png', width: 1280, height: 720, hash: '' },
  { name: 'narrow.png', width: 400, height: 800, hash: '' },
  { name: 'figure-2.png', width: 1280, height: 720, hash: 'figure=2' },
];
/** `npm run figures -- --screenshots`: the page's screenshots only. */
const onlyScreenshots = process.argv.includes('--screenshots');

/** The passes the timings overlay should show (timed, or skipped by the frame) before a screenshot is taken. */
const STAGES = ['lightDepth', 'scene', 'blurH', 'blurV', 'compose'];
/** Frame times the overlay's plot should have. */
const FRAMES = 8;

async function main() {
  await mkdir(outDir, { recursive: true });
  await mkdir(screenshotDir, { recursive: true });
  const session = await startBrowser();
  try {
    const page = await openReadyPage(session.browser, `${session.baseUrl}/?still`, { width: WIDTH, height: HEIGHT });
    if (!(await page.evaluate('window.testReady'))) throw new Error('the demo did not start');
    const standIn = await page.evaluate(() => {
      window.demo.stop();
      window.demo.chrome(false);
      return window.demo.isStandIn;
    });
    if (standIn) console.warn('The head scan is missing: the figures show the procedural stand-in (run npm run assets).');
    const images = new Map();
    for (const figure of onlyScreenshots ? [] : FIGURES) {
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
    if (!onlyScreenshots) {
      await writeFile(join(root, 'docs/FIGURES.md'), figuresMarkdown());
      console.log('wrote docs/FIGURES.md');
    }
    await page.close();
    for (const shot of SCREENSHOTS) {
      // The page animating as for a visitor, so the frame rate and the pass times are real
      // (SwiftShader's: CPU times); stopped once every pass has been timed.
      const view = await openReadyPage(session.browser, `${session.baseUrl}/${shot.hash ? `#${shot.hash}` : ''}`, shot);
      await view.waitForFunction((stages, frames) => {
        const t = window.demo.timings;
        const s = t.summary();
        return stages.every((stage) => Number.isFinite(s[stage]) || s.skipped.includes(stage)) && t.history.length >= frames;
      }, { timeout: 300_000, polling: 500 }, STAGES, FRAMES);
      await view.evaluate(() => {
        window.demo.stop();
        window.demo.updateTimings();
      });
      const png = await view.screenshot();
      if (view.problems.length) throw new Error(`the page reported errors:\n${view.problems.join('\n')}`);
      await writeFile(join(screenshotDir, shot.name), png);
      console.log(`wrote docs/screenshots/${shot.name}`);
      await view.close();
    }
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
      `Open it in the demo: \`#figure=${f.id}\` (the panel's presets, "without" and "with", switch between the two).`,
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
    ...calibrationMarkdown(),
    'Head: “Infinite, 3D Head Scan” by Lee Perry-Smith (Infinite-Realities), CC BY 3.0, as',
    'distributed with the three.js examples.',
    '',
  ].join('\n');
}

/** How figure 2's preset was calibrated against the profile (the numbers are computed here). */
function calibrationMarkdown() {
  const albedo = 0.5; // the ear's albedo green/red, measured in the page (test/browser/demo/demoFirstView.test.js)
  const rows = [0.3, 0.44, 0.6, 0.8, 1, 2.4].map((d) => {
    const t = profiles.skin.transmittance(d);
    const rgb = [1, (albedo * t[1]) / t[0], (albedo * 0.9 * t[2]) / t[0]].map((v) => v * 0.45);
    const shown = acesSrgb(rgb);
    return `| ${d} | ${(t[1] / t[0]).toFixed(3)} | ${(albedo * t[1] / t[0]).toFixed(3)} | rgb(${shown.join(', ')}), hue ${hue(shown).toFixed(0)}° |`;
  });
  return [
    '## Calibrating figure 2',
    '',
    'Light that crossed the ear is shaded T(d) × the entry cosine × albedo × light, with d = thickness ×',
    'worldUnitInMm × (1 − translucency) / widthMm in profile millimetres and T the skin profile\'s',
    'transmittance (`profiles.skin.transmittance`); the entry cosine, the same in every channel, leaves',
    'the colour as it is. Measured in the page at figure 2: the light crosses a median of',
    'about 8 mm of ear (it goes through obliquely; the thickness view), and the ear\'s albedo has',
    'green/red ≈ 0.5 (transmitted light divided by T(d), per pixel). What that light looks like after',
    'three\'s ACES Filmic tone mapping and sRGB, at the ear\'s brightness (linear red 0.45):',
    '',
    '| d (profile mm) | T green/red | transmitted green/red | on screen |',
    '|---|---|---|---|',
    ...rows,
    '',
    'Beyond about 0.6 mm T\'s green is so small that ACES\'s output matrix takes it to zero: the ear',
    'shows pure red (the old preset, translucency 0.7, put 8 mm at 2.4 mm). Red-orange (hue ≥ 10°) needs',
    'd ≤ 0.6 mm, i.e. transmitted green/red ≥ albedo × T_g/T_r(0.6 mm) ≈ 0.08: the floor the browser',
    'test (test/browser/demo/demoFirstView.test.js) derives from the profile and the albedo it measures,',
    'and checks the ear against (the ear measures about 0.14; the old preset 0.003). Translucency',
    '0.945 puts the median at 0.44 mm (the thin rim is more orange, the folds redder); intensity 8',
    'keeps the red below clipping, so the ear keeps its shading.',
    '',
    '## The page',
    '',
    'Screenshots of the demo page as a visitor sees it (`npm run figures` renders them too):',
    '',
    '| first view (1280 × 720) | 400 px wide |',
    '|---|---|',
    '| ![The first view: the face split by the divider](screenshots/first-view.png) | ![The narrow layout, the panel folded](screenshots/narrow.png) |',
    '',
    '![Figure 2 in the page](screenshots/figure-2.png)',
    '',
  ];
}

/** three.js's ACESFilmicToneMapping (exposure 1), then sRGB, to 8 bits. */
function acesSrgb([r, g, b]) {
  const s = 1 / 0.6;
  const v = [r * s, g * s, b * s];
  const m1 = [[0.59719, 0.35458, 0.04823], [0.076, 0.90834, 0.01566], [0.0284, 0.13383, 0.83777]];
  const m2 = [[1.60475, -0.53108, -0.07367], [-0.10208, 1.10813, -0.00605], [-0.00327, -0.07276, 1.07602]];
  const mul = (m, x) => m.map((row) => row[0] * x[0] + row[1] * x[1] + row[2] * x[2]);
  const fit = (x) => (x * (x + 0.0245786) - 0.000090537) / (x * (0.983729 * x + 0.432951) + 0.238081);
  const out = mul(m2, mul(m1, v).map(fit));
  return out.map((x) => {
    const c = Math.min(1, Math.max(0, x));
    return Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055));
  });
}

function hue([r, g, b]) {
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  if (max === min) return 0;
  const h = max === r ? 60 * ((g - b) / (max - min)) : max === g ? 60 * (2 + (b - r) / (max - min)) : 60 * (4 + (r - g) / (max - min));
  return h > 180 ? h - 360 : h;
}

main().catch((error) => {
  console.error(error.message);
  process.exitCode = 1;
});
