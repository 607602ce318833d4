// `node bench/webgpu/run.js [--quick] [--base <dir>] [--only a,b] [--rounds n] [--frames n]`: the
// WebGPURenderer node's cost beside the WebGL pipeline's (bench/webgpu/page.js has the rows and
// how a frame is timed), in headless Chromium on SwiftShader with WebGPU (dev/browser.js's
// WEBGPU_FLAGS). Prints the medians, the node's overhead over its backend's plain RenderPipeline
// frame and the WebGL pipeline's over a plain composer frame, from the same interleaved rounds,
// and where the node's time goes (the split, the compose, the blur). `--base <dir>`: another
// checkout's library (its src/, e.g. the commit before a change) beside this one's, its rows
// (…Base) in the same rounds: before and after (`--base-name`: what the base is, for the record).
// Writes bench/results/webgpu.json and docs/BENCH.md's section (quick or --only:
// bench/results/tmp/webgpu.json alone).
import { execFileSync } from 'node:child_process';
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { openReadyPage, startBrowser } from '../../dev/browser.js';
import { webgpuOverheads } from './overheads.js';
import { WEBGPU_HEADING, webgpuSection, withBenchSection } from '../report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const { values } = parseArgs({
  options: {
    quick: { type: 'boolean' }, base: { type: 'string' }, 'base-name': { type: 'string' }, only: { type: 'string' }, rounds: { type: 'string' }, frames: { type: 'string' },
  },
});
const options = values.quick ? { width: 320, height: 180, rounds: 3, frames: 3 } : { width: 640, height: 360, rounds: 5, frames: 5 };
if (values.rounds) options.rounds = Number(values.rounds);
if (values.frames) options.frames = Number(values.frames);
// The page serves the base's library under its own names (vite.config.js, SSS_BASE_DIR).
if (values.base) process.env.SSS_BASE_DIR = resolve(values.base);

const session = await startBrowser({ webgpu: true, protocolTimeout: 1_800_000 });
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/webgpu/index.html`, { timeout: 300_000 });
  const all = await page.evaluate(() => window.bench.rows);
  const only = values.only ? values.only.split(',') : all.filter((row) => values.base || !row.endsWith('Base'));
  const result = await page.evaluate((o) => window.bench.run(o), { ...options, only });
  const commit = execFileSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: root, encoding: 'utf8' }).trim();
  const baseName = values.base ? values['base-name'] ?? values.base : null;
  const summary = { ...result, date: new Date().toISOString(), commit, flags: session.flags, baseName, ...webgpuOverheads(result.medianMs) };
  const partial = values.quick || values.only;
  const file = join(root, partial ? 'bench/results/tmp/webgpu.json' : 'bench/results/webgpu.json');
  await mkdir(dirname(file), { recursive: true });
  await writeFile(file, `${JSON.stringify(summary, null, 1)}\n`);
  const { times, flags, ...shown } = summary;
  console.log(JSON.stringify(shown, null, 1));
  console.log(`wrote ${file}`);
  if (!partial) {
    const docs = join(root, 'docs/BENCH.md');
    await writeFile(docs, withBenchSection(await readFile(docs, 'utf8'), WEBGPU_HEADING, webgpuSection(summary)));
    console.log(`wrote ${docs}`);
  }
} finally {
  await session.close();
}
