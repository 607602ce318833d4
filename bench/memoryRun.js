// `npm run bench:memory`: the bytes the pipeline allocates (bench/memory.js) for the settings of
// the README's limits: MSAA 0 and 4, no, one and four transmitting lights, one and three profiles,
// kernelGroups 'auto', scattering turned off, on the head at 1280×720. Deterministic (what three asks the GPU for), so
// one run: bench/results/memory.json and its section of docs/BENCH.md.
import { readFile, writeFile } from 'node:fs/promises';
import { join, dirname, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { withBenchPage } from './browser.js';
import { MEMORY_HEADING, memorySection, withBenchSection } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = join(root, 'bench/results/memory.json');

/** The settings measured: [label, options]. */
const MEMORY_CASES = Object.freeze([
  ['no light', { lights: 0 }],
  ['the defaults, one light', {}],
  ['four lights', { lights: 4 }],
  ['MSAA 4, one light', { samples: 4 }],
  ['MSAA 4, four lights', { samples: 4, lights: 4 }],
  ['three profiles', { profiles: 3 }],
  ["kernelGroups 'auto'", { settings: { kernelGroups: 'auto' } }],
  ["MSAA 4, kernelGroups 'auto'", { samples: 4, settings: { kernelGroups: 'auto' } }],
  ['scattering false after frames with it on', { scatteringOff: true }],
]);

const results = await withBenchPage(async (page) => {
  const rows = [];
  for (const [label, options] of MEMORY_CASES) {
    const r = await page.evaluate((o) => window.bench.memory(o), { width: 1280, height: 720, ...options });
    if (page.problems.length > 0) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
    if (r.glError !== 0) throw new Error(`${label}: GL error 0x${r.glError.toString(16)}`);
    if (r.lightMapsDrawn !== (options.lights ?? 1)) throw new Error(`${label}: ${r.lightMapsDrawn} light maps drawn, ${options.lights ?? 1} asked`);
    console.log(`${label.padEnd(30)} ${r.bytesPerPixel.toFixed(1).padStart(6)} B per pixel, light maps ${(r.lightMapBytes / 2 ** 20).toFixed(1)} MiB, tables ${(r.tableBytes / 2 ** 10).toFixed(0)} KiB; composer ${r.plainBytesPerPixel.toFixed(1)} B per pixel`);
    rows.push({ label, ...r });
  }
  return rows;
});
const result = { command: 'npm run bench:memory', date: new Date().toISOString(), results };
await writeFile(out, `${JSON.stringify(result, null, 1)}\n`);
console.log(`wrote ${relative(root, out)}`);
const docs = join(root, 'docs/BENCH.md');
await writeFile(docs, withBenchSection(await readFile(docs, 'utf8'), MEMORY_HEADING, memorySection(result)));
console.log(`wrote ${relative(root, docs)}`);
