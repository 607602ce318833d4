// `npm run bench:truth`: each method's blurred light against the surface-space truth (the head's
// scattering summed over its own surface in float64, bench/surfaceTruth/scatter.js), at the head
// view and an eye close-up, front-lit and back-lit, per region, beside the truth's convergence, and
// on a flat plane against the exact convolution; writes bench/results/surface-truth.json, heat maps
// and images under docs/surface-truth/ and docs/SURFACE-TRUTH.md (`--report`: the markdown again
// from the JSON). Each truth is 3-6 minutes of float64 in the page on a shared 2-core machine (its
// density check twice that), the whole run about an hour there: `--only`, `--cached` and
// `--checks` (below) run it in parts; `--quick`: the plane and the head front-lit at 320×180.
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../../dev/browser.js';
import { surfaceTruthMarkdown } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const quick = process.argv.includes('--quick');
const resultsPath = join(root, 'bench/results/surface-truth.json');
const markdownPath = join(root, 'docs/SURFACE-TRUTH.md');
const truthDirectory = join(root, 'bench/results/tmp/surface-truth'); // not committed: 1 MB per view
if (process.argv.includes('--report')) { // the markdown again from the last results
  await writeFile(markdownPath, surfaceTruthMarkdown(JSON.parse(await readFile(resultsPath, 'utf8'))));
  process.exit(0);
}

/** The bench's head view (bench/scenes.js), 640x360, widthMm 1 (the scan's scale), float targets. */
const VIEW = { width: 640, height: 360, widthMm: 1 };
/** `--quick`: a quarter of the pixels, while developing (nothing written but the images). */
const QUICK_VIEW = { width: 320, height: 180, widthMm: 1 };
/**
 * The views: the speed-accuracy bench's (the whole head) and a close-up of the right eye from the
 * same side (8° field of view: the lids' creases some 10 pixels across).
 */
export const VIEWS = [
  { name: 'head', key: 'head', view: null },
  { name: 'eye close-up', key: 'eye', view: [-0.4, 1.9, 21, -0.77, 1.72, 1.9, 8] },
];
/** Front: the key light of the speed-accuracy bench; back: behind the head, a little above. */
export const LIGHTS = [
  { name: 'front', lightAzimuthDeg: 30, lightElevationDeg: 25 },
  { name: 'back', lightAzimuthDeg: 180, lightElevationDeg: 20 },
];
/** Name → SubsurfaceScattering options ({ method: 'none' }: scattering off, the effect's size; { denseReference: true }: the dense 2D reference). */
export const SETTINGS = [
  ['default', {}],
  ['marginal17', { method: 'marginal', samples: 17 }],
  ['reference17', { method: 'reference', samples: 17 }],
  ['dense', { denseReference: true }],
  // The default with other depth rules (what crosses a depth step): creases against silhouettes.
  ['default, lerp', { followSurface: 'lerp' }],
  ['default, no depth rule', { followSurface: 'off' }],
  ['default, threshold 12 mm', { depthThresholdMm: 12 }],
  ['default, no transmittance', { transmittance: false }],
  ['none', { method: 'none' }],
];
/** The truth's atlas (texels per side) and the convergence checks: twice the samples per area, twice the atlas's side. */
const ATLAS = 1024;
const CHECKS = [{ name: 'density', density: 2, atlasSize: ATLAS }, { name: 'atlas', density: 1, atlasSize: 2 * ATLAS }];
const QUICK_SETTINGS = ['default', 'dense', 'none'];
/** The SSS stage's time per setting: rounds in which each setting runs in turn, re-runs per round. */
const COST_ROUNDS = { rounds: 3, reruns: 1 };
/**
 * The flat slab (bench/scenes.js): a disc of light on a plane facing the camera, where the truth is
 * the exact convolution; at 320×180 (a pixel of 0.98 mm), where its 230,000 pixels take a minute.
 */
const PLANE_SETTINGS = ['default', 'dense', 'none'];
const PLANE_VIEW = QUICK_VIEW;

const fileName = (text) => text.replace(/[^a-z0-9]+/gi, '-');
if (process.argv.includes('--assemble')) { // the results from the parts' own copies (bench/results/tmp/surface-truth/*.result.json)
  const { readdir } = await import('node:fs/promises');
  const base = JSON.parse(await readFile(resultsPath, 'utf8'));
  const parts = await Promise.all((await readdir(truthDirectory)).filter((f) => f.endsWith('.result.json')).map(async (f) => JSON.parse(await readFile(join(truthDirectory, f), 'utf8'))));
  const order = VIEWS.flatMap((v) => LIGHTS.map((l) => `${v.name}, ${l.name} light`));
  const named = parts.map((c) => (c.viewName ? { ...c, name: `${c.viewName}, ${c.lightName} light` } : c)); // parts written before the name fix
  // A part's convergence checks run apart (<view>.convergence.json: [{ name, density, atlasSize, relative }]) where it ran none.
  for (const c of named) {
    if (c.convergence?.length) continue;
    const apart = JSON.parse(await readFile(join(truthDirectory, `${fileName(c.name)}.convergence.json`), 'utf8').catch(() => 'null'));
    if (apart) c.convergence = apart;
  }
  const byName = new Map([...(base.views ?? []), ...named].map((c) => [c.name, c]));
  const assembled = { ...base, plane: byName.get('plane') ?? base.plane, views: order.filter((n) => byName.has(n)).map((n) => byName.get(n)) };
  await writeFile(resultsPath, `${JSON.stringify(assembled, null, 1)}\n`);
  await writeFile(markdownPath, surfaceTruthMarkdown(assembled));
  console.log(`assembled: the plane ${assembled.plane ? 'and ' : 'missing, '}${assembled.views.map((c) => c.name).join('; ')}`);
  process.exit(0);
}

const session = await startBrowser({ protocolTimeout: 1_800_000 });
const out = join(root, 'docs/surface-truth');
await mkdir(out, { recursive: true });
const png = (name, data) => writeFile(join(out, `${name}.png`), Buffer.from(data, 'base64'));
const view = quick ? QUICK_VIEW : VIEW;
const started = Date.now();
const results = { view, views: [], plane: null, webgl: null, date: new Date().toISOString() };
const line = (relative) => Object.entries(relative).map(([k, v]) => `${k} ${v == null ? '—' : v.toFixed(3)}`).join('  ');

/** Opens one configuration, checks its truth's convergence and measures `settings` against it. */
async function measureConfiguration(page, name, options, settingNames, withCost = false) {
  const cachePath = join(truthDirectory, `${fileName(name)}.json`);
  const cached = useCache ? JSON.parse(await readFile(cachePath, 'utf8').catch(() => 'null')) : null;
  const info = await page.evaluate((o) => window.surfaceTruthBench.open(o), { ...view, atlasSize: ATLAS, ...options, truthLight: cached?.light ?? null, truthIdealBlurs: cached?.idealBlurs ?? null });
  info.view = { width: options.width ?? view.width, height: options.height ?? view.height };
  if (cached) {
    Object.assign(info, cached.info ?? {}, { cachedTruth: true });
    console.log(`${name}: the truth kept from an earlier run (${cachePath})`);
  } else if (!quick) { // kept for measuring other settings against it later (bench/surfaceTruth/variants.js)
    await mkdir(truthDirectory, { recursive: true });
    const { webgl: _, ...kept } = info;
    await writeFile(cachePath, JSON.stringify({ name, options: { ...view, atlasSize: ATLAS, ...options }, info: kept, light: await page.evaluate(() => window.surfaceTruthBench.truthLight()), idealBlurs: await page.evaluate(() => window.surfaceTruthBench.truthIdealBlurs()) }));
  }
  results.webgl ??= info.webgl;
  console.log(`${name}: truth in ${(info.truthMs / 1000).toFixed(1)} s (${info.lightReads} light reads: ${Object.entries(info.readShares).map(([k, v]) => `${k} ${(100 * v).toFixed(1)} %`).join(', ')}); truth / unscattered ${info.truthOverUnscattered.map((v) => v.toFixed(4)).join(', ')}`);
  const convergence = [];
  for (const check of quick ? CHECKS.slice(0, 1) : CHECKS.filter((c) => checks.includes(c.name))) {
    const moved = await page.evaluate((o) => window.surfaceTruthBench.truthUncertainty(o), check);
    convergence.push({ ...check, relative: moved.relative, truthMs: moved.truthMs });
    console.log(`  truth at ${check.name} ×2 against it: ${line(moved.relative)}`);
  }
  // Ideal blurs of what the camera (and the light) sees (bench/surfaceTruth/scatter.js's idealBlursOf).
  const idealBlurs = await page.evaluate(() => window.surfaceTruthBench.idealBlurs());
  for (const [blur, r] of Object.entries(idealBlurs ?? {})) console.log(`  ideal blur of ${blur.padEnd(17)} ${line(r.relative)}`);
  const settings = [];
  for (const [setting, o] of SETTINGS.filter(([n]) => settingNames.includes(n))) {
    const r = await page.evaluate((x) => window.surfaceTruthBench.measure(x), o);
    if (['default', 'dense'].includes(setting)) await png(`heat-${fileName(name)}-${setting}`, r.heatMap);
    settings.push({ name: setting, options: o, relative: r.relative, bias: r.bias });
    console.log(`  ${setting.padEnd(26)} ${line(r.relative)}`);
  }
  let cost = null;
  if (withCost) {
    const timed = SETTINGS.filter(([n]) => settingNames.includes(n) && n !== 'none');
    cost = await page.evaluate((list, o) => window.surfaceTruthBench.costs(list, o), timed, COST_ROUNDS).catch((error) => {
      console.log(`  SSS cost not measured: ${error.message}`);
      return null;
    });
    if (cost) console.log(`  SSS ms (median of ${COST_ROUNDS.rounds} interleaved rounds): ${Object.entries(cost).map(([k, v]) => `${k} ${v.toFixed(1)}`).join(', ')}`);
  }
  const images = await page.evaluate(() => window.surfaceTruthBench.images({}));
  for (const [k, v] of Object.entries(images)) await png(`image-${fileName(name)}-${k}`, v);
  const { webgl: _, ...kept } = info;
  const configuration = { ...options, ...kept, name, convergence, idealBlurs, settings, cost }; // name last: a light's options have one too
  if (!quick) await writeFile(join(truthDirectory, `${fileName(name)}.result.json`), JSON.stringify(configuration)); // the part's own copy
  return configuration;
}

// `--only a,b`: only the configurations named (plane, head-front, head-back, eye-front, eye-back),
// merged into the results already there: parts can run apart (on a machine shared by others).
const onlyArgument = process.argv.find((a) => a.startsWith('--only='));
const only = onlyArgument ? onlyArgument.slice('--only='.length).split(',') : null;
const wanted = (key) => !only || only.includes(key);
// `--cached`: a configuration's truth from an earlier run where one was kept (its convergence
// checks are computed again); `--checks=density,atlas` (the default): which checks run.
const useCache = process.argv.includes('--cached');
const checksArgument = process.argv.find((a) => a.startsWith('--checks='));
const checks = checksArgument ? checksArgument.slice('--checks='.length).split(',') : CHECKS.map((c) => c.name);
/**
 * Writes the results so far (after each configuration: a part cut short keeps what it measured),
 * merged into those there when only some parts run; the markdown once the plane and a view are in.
 */
async function save() {
  results.seconds = (Date.now() - started) / 1000;
  if (quick) return;
  let merged = results;
  if (only) { // the configurations in the order of a whole run
    const before = JSON.parse(await readFile(resultsPath, 'utf8').catch(() => 'null'));
    if (before?.views) {
      const order = VIEWS.flatMap((v) => LIGHTS.map((l) => `${v.name}, ${l.name} light`));
      const byName = new Map([...before.views, ...results.views].map((c) => [c.name, c]));
      merged = { ...results, views: order.filter((n) => byName.has(n)).map((n) => byName.get(n)), plane: results.plane ?? before.plane };
    }
  }
  await writeFile(resultsPath, `${JSON.stringify(merged, null, 1)}\n`);
  console.log(`  results: the plane ${merged.plane ? 'and ' : 'not yet, '}${merged.views.map((c) => c.name).join('; ')}`);
  if (merged.plane && merged.views.length) await writeFile(markdownPath, surfaceTruthMarkdown(merged));
}

try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/surfaceTruth/index.html`,
    { width: view.width, height: view.height, readyExpr: 'window.surfaceTruthBench' });
  if (wanted('plane')) {
    results.plane = await measureConfiguration(page, 'plane', { scene: 'slab', ...PLANE_VIEW }, PLANE_SETTINGS);
    await save();
  }
  for (const v of quick ? VIEWS.slice(0, 1) : VIEWS) {
    for (const light of quick ? LIGHTS.slice(0, 1) : LIGHTS) {
      if (!wanted(`${v.key}-${light.name}`)) continue;
      const settingNames = quick ? QUICK_SETTINGS : SETTINGS.map(([n]) => n);
      // The cost in the same page and rounds, once per view (the light hardly changes it).
      results.views.push(await measureConfiguration(page, `${v.name}, ${light.name} light`, { view: v.view, viewName: v.name, lightName: light.name, ...light }, settingNames, light === LIGHTS[0]));
      await save();
    }
  }
  if (page.problems.length) throw new Error(`the page reported problems:\n${page.problems.join('\n')}`);
} finally {
  await session.close();
}
console.log(`${results.seconds.toFixed(0)} s${quick ? ' (quick: nothing written but the images)' : ''}`);
