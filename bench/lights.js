// `npm run bench:lights [-- --quick]`: the head frame's cost with 0, 1 and 3 transmitting lights
// (thickness maps of our own) beside three's shadow maps of the same lights, in the same
// interleaved rounds (bench/lightsPage.js has the rows). Headless Chromium on SwiftShader
// (dev/browser.js). Writes bench/results/lights.json and its section of docs/BENCH.md (quick:
// bench/results/tmp/lights.json, docs untouched); prints the medians and the ratios.
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../dev/browser.js';
import { LIGHTS_HEADING, lightsSection, withBenchSection } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const quick = process.argv.includes('--quick');
const options = quick ? { width: 320, height: 180, rounds: 2, frames: 3 } : { width: 640, height: 360, rounds: 4, frames: 5 };

const session = await startBrowser({ protocolTimeout: 900_000 });
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/lights.html`, { timeout: 300_000 });
  const result = await page.evaluate((o) => window.bench.run(o), options);
  if (page.problems?.length) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
  if (result.isStandIn) throw new Error('the head scan is missing (npm run assets): these would be the stand-in bust\'s numbers');
  const m = result.medianMs;
  const overNone = Object.fromEntries(Object.entries(m).map(([name, ms]) => [name, ms / m.ours0]));
  const summary = { command: 'npm run bench:lights', ...result, date: new Date().toISOString(), flags: session.flags, overNone };
  const file = join(root, quick ? 'bench/results/tmp/lights.json' : 'bench/results/lights.json');
  await mkdir(dirname(file), { recursive: true });
  await writeFile(file, `${JSON.stringify(summary, null, 1)}\n`);
  console.log(JSON.stringify({ medianMs: m, lightMaps: result.lightMaps, overNone }, null, 1));
  console.log(`wrote ${file}`);
  if (!quick) {
    const docs = join(root, 'docs/BENCH.md');
    await writeFile(docs, withBenchSection(await readFile(docs, 'utf8'), LIGHTS_HEADING, lightsSection(summary)));
    console.log(`wrote ${docs}`);
  }
} finally {
  await session.close();
}
