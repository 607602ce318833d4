// `npm run bench:scene-graph [-- --quick] [-- --label before]`: the pipeline's frame against
// three's plain frame where nothing subsurface is on the screen, with the head in view, and with
// the head among 2,000 ordinary meshes (bench/sceneGraphPage.js has the rows): wall ms, the JS
// time of composer.render(), draw calls; headless Chromium on SwiftShader (dev/browser.js). The
// result goes into bench/results/scene-graph.json under its label ('after' by default; run
// `-- --label before` on the code before a change, in its checkout, and copy the file over), and
// its section of docs/BENCH.md (quick: bench/results/tmp/scene-graph.json, docs untouched).
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { execFileSync } from 'node:child_process';
import { openReadyPage, startBrowser } from '../dev/browser.js';
import { SCENE_GRAPH_HEADING, sceneGraphSection, withBenchSection } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const label = args.includes('--label') ? args[args.indexOf('--label') + 1] : 'after';
const options = quick ? { width: 320, height: 180, rounds: 2, frames: 3 } : { width: 640, height: 360, rounds: 5, frames: 5 };
const file = join(root, quick ? 'bench/results/tmp/scene-graph.json' : 'bench/results/scene-graph.json');

const session = await startBrowser({ protocolTimeout: 900_000 });
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/sceneGraph.html`, { timeout: 300_000 });
  const result = await page.evaluate((o) => window.bench.run(o), options);
  if (page.problems?.length) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
  if (result.isStandIn) throw new Error('the head scan is missing (npm run assets): these would be the stand-in bust\'s numbers');
  const commit = execFileSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: root, encoding: 'utf8' }).trim();
  const previous = JSON.parse(await readFile(file, 'utf8').catch(() => '{}'));
  const summary = { ...previous, command: 'npm run bench:scene-graph', [label]: { ...result, commit, date: new Date().toISOString(), flags: session.flags } };
  await mkdir(dirname(file), { recursive: true });
  await writeFile(file, `${JSON.stringify(summary, null, 1)}\n`);
  console.log(JSON.stringify({ label, medianMs: result.medianMs, medianJsMs: result.medianJsMs, drawCalls: result.drawCalls }, null, 1));
  console.log(`wrote ${file}`);
  if (!quick && summary.after) {
    const docs = join(root, 'docs/BENCH.md');
    await writeFile(docs, withBenchSection(await readFile(docs, 'utf8'), SCENE_GRAPH_HEADING, sceneGraphSection(summary)));
    console.log(`wrote ${docs}`);
  }
} finally {
  await session.close();
}
