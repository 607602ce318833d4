// `npm run bench:truth`: each method's blurred light against the surface-space truth (the head's
// scattering summed over its own surface in float64, bench/surfaceTruth/scatter.js), front-lit and
// back-lit, per region; writes bench/results/surface-truth.json, heat maps and images under
// docs/surface-truth/ and docs/SURFACE-TRUTH.md (`--report`: the markdown again from the JSON). About 2 minutes per light on SwiftShader (the
// truth itself is ~20 s of float64 in the page); `--quick`: the front light and three settings.
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../../dev/browser.js';
import { surfaceTruthMarkdown } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const quick = process.argv.includes('--quick');
const resultsPath = join(root, 'bench/results/surface-truth.json');
const markdownPath = join(root, 'docs/SURFACE-TRUTH.md');
if (process.argv.includes('--report')) { // the markdown again from the last results
  await writeFile(markdownPath, surfaceTruthMarkdown(JSON.parse(await readFile(resultsPath, 'utf8'))));
  process.exit(0);
}

/** The bench's head view (bench/scenes.js), 640x360, widthMm 1 (the scan's scale), float targets. */
const VIEW = { width: 640, height: 360, widthMm: 1 };
/** Front: the key light of the speed-accuracy bench; back: behind the head, a little above. */
export const LIGHTS = [
  { name: 'front', lightAzimuthDeg: 30, lightElevationDeg: 25 },
  { name: 'back', lightAzimuthDeg: 180, lightElevationDeg: 20 },
];
/** Name → SubsurfaceScattering options ({ method: 'none' }: scattering off, the effect's size). */
export const SETTINGS = [
  ['default', {}],
  ['footprint17', { method: 'footprint', samples: 17 }],
  ['marginal17', { method: 'marginal', samples: 17 }],
  ['reference17', { method: 'reference', samples: 17 }],
  ['dense', { method: 'dense' }],
  // The default with other depth rules (what crosses a depth step): creases against silhouettes.
  ['default, lerp', { followSurface: 'lerp' }],
  ['default, no depth rule', { followSurface: 'off' }],
  ['default, threshold 12 mm', { depthThresholdMm: 12 }],
  ['none', { method: 'none' }],
];
/** The finer atlas (texels per side) whose truth measures the truth's own uncertainty (the truth uses 2048). */
const UNCERTAINTY_ATLAS = 2560;
const QUICK_SETTINGS = ['default', 'dense', 'none'];

const session = await startBrowser({ protocolTimeout: 900_000 });
const out = join(root, 'docs/surface-truth');
await mkdir(out, { recursive: true });
const png = (name, data) => writeFile(join(out, `${name}.png`), Buffer.from(data, 'base64'));
const started = Date.now();
const results = { view: VIEW, lights: [], webgl: null, date: new Date().toISOString() };
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/surfaceTruth/index.html`,
    { width: VIEW.width, height: VIEW.height, readyExpr: 'window.surfaceTruthBench' });
  for (const light of quick ? LIGHTS.slice(0, 1) : LIGHTS) {
    const info = await page.evaluate((o) => window.surfaceTruthBench.open(o), { ...VIEW, ...light });
    results.webgl ??= info.webgl;
    console.log(`${light.name}: truth over ${info.atlasTexels} atlas texels in ${(info.truthMs / 1000).toFixed(1)} s; truth / unscattered light ${info.truthOverUnscattered.map((v) => v.toFixed(4)).join(', ')}`);
    // The truth's own uncertainty: the same truth from a finer atlas, in the settings' measure.
    const uncertainty = await page.evaluate((size) => window.surfaceTruthBench.truthUncertainty(size), UNCERTAINTY_ATLAS);
    console.log(`  truth from a ${UNCERTAINTY_ATLAS}² atlas against it: ${Object.entries(uncertainty.relative).map(([k, v]) => `${k} ${v == null ? '—' : v.toFixed(3)}`).join('  ')}`);
    const settings = [];
    for (const [name, options] of SETTINGS.filter(([n]) => !quick || QUICK_SETTINGS.includes(n))) {
      const r = await page.evaluate((o) => window.surfaceTruthBench.measure(o), options);
      if (!name.includes(',')) await png(`heat-${light.name}-${name}`, r.heatMap);
      settings.push({ name, options, relative: r.relative });
      console.log(`  ${name.padEnd(12)} ${Object.entries(r.relative).map(([k, v]) => `${k} ${v == null ? '—' : v.toFixed(3)}`).join('  ')}`);
    }
    const images = await page.evaluate(() => window.surfaceTruthBench.images({}));
    for (const [k, v] of Object.entries(images)) await png(`image-${light.name}-${k}`, v);
    const { webgl: _, ...kept } = info;
    results.lights.push({ ...light, ...kept, uncertainty, settings });
  }
  if (page.problems.length) throw new Error(`the page reported problems:\n${page.problems.join('\n')}`);
} finally {
  await session.close();
}
results.seconds = (Date.now() - started) / 1000;
if (!quick) {
  await writeFile(resultsPath, `${JSON.stringify(results, null, 1)}\n`);
  await writeFile(markdownPath, surfaceTruthMarkdown(results));
}
console.log(`${results.seconds.toFixed(0)} s${quick ? ' (quick: nothing written but the images)' : ''}`);
