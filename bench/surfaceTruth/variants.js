// `node bench/surfaceTruth/variants.js --views=head-front-light,eye-close-up-front-light --settings='[["name", {options}], ...]'`:
// measures settings against truths `npm run bench:truth` computed and kept
// (bench/results/tmp/surface-truth/<view>.json), without computing them again: for variants of the
// library tried on a patched tree (a depth rule in the blur's shader, say), in a few minutes
// instead of the whole bench. Prints each setting's error by region and its bias (mean setting −
// truth over mean truth, per channel) where screen space errs; writes nothing.
import { readFile } from 'node:fs/promises';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../../dev/browser.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const argument = (name) => process.argv.find((a) => a.startsWith(`--${name}=`))?.slice(name.length + 3);
const views = (argument('views') ?? 'head-front-light').split(',');
const settings = JSON.parse(argument('settings') ?? '[["default", {}]]');
if (!Array.isArray(settings) || !settings.every((s) => Array.isArray(s) && typeof s[0] === 'string' && typeof s[1] === 'object')) {
  throw new TypeError('variants: --settings must be a JSON list of [name, SubsurfaceScattering options] pairs');
}

const session = await startBrowser({ protocolTimeout: 1_800_000 });
try {
  for (const view of views) {
    const cached = JSON.parse(await readFile(join(root, 'bench/results/tmp/surface-truth', `${view}.json`), 'utf8'));
    const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/surfaceTruth/index.html`,
      { width: cached.options.width, height: cached.options.height, readyExpr: 'window.surfaceTruthBench' });
    await page.evaluate((o) => window.surfaceTruthBench.open(o), { ...cached.options, truthLight: cached.light, truthIdealBlurs: cached.idealBlurs ?? null });
    console.log(cached.name);
    for (const [name, options] of settings) {
      const { relative, bias } = await page.evaluate((o) => window.surfaceTruthBench.measure(o), options);
      console.log(`  ${name.padEnd(26)} ${Object.entries(relative).map(([k, v]) => `${k} ${v == null ? '—' : v.toFixed(3)}`).join('  ')}`);
      // Too dark or too bright, per channel: mean(setting − truth) / mean(truth).
      console.log(`  ${''.padEnd(26)} bias R G B: ${['creases', 'eyes', 'lips', 'all'].map((k) => `${k} ${bias[k].map((v) => (v == null ? '—' : `${(100 * v).toFixed(1)} %`)).join(' ')}`).join('  ')}`);
    }
    if (page.problems.length) throw new Error(`the page reported problems:\n${page.problems.join('\n')}`);
    await page.close();
  }
} finally {
  await session.close();
}
