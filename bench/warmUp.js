// `npm run bench:warm-up [-- --quick]`: the first frame against a steady one, on a fresh browser
// each (no program compiled, no shader cache): warmed up by the pipeline's compileAsync (and then
// the scene's textures uploaded), by three's renderer.compileAsync(scene, camera), or not at all, in
// interleaved rounds (bench/warmUpPage.js).
// Headless Chromium on SwiftShader (dev/browser.js). Writes bench/results/warm-up.json and its
// section of docs/BENCH.md (quick: bench/results/tmp/warm-up.json, docs untouched).
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../dev/browser.js';
import { median } from '../dev/gpuTimer.js';
import { WARM_UP_HEADING, warmUpSection, withBenchSection } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const quick = process.argv.includes('--quick');
const options = quick ? { width: 320, height: 180, frames: 3, rounds: 1 } : { width: 1280, height: 720, frames: 5, rounds: 3 };
const WARM_UPS = ['pipeline', 'uploads', 'three', 'none'];

const runs = [];
for (let round = 0; round < options.rounds; round++) {
  for (const warmUp of WARM_UPS) {
    const session = await startBrowser({ protocolTimeout: 900_000 });
    try {
      const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/warmUp.html`, { timeout: 300_000 });
      const result = await page.evaluate((o) => window.bench.run(o), { warmUp, width: options.width, height: options.height, frames: options.frames });
      if (page.problems?.length) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
      if (result.isStandIn) throw new Error('the head scan is missing (npm run assets): these would be the stand-in bust\'s numbers');
      if (result.glError !== 0) throw new Error(`GL error 0x${result.glError.toString(16)}`);
      console.log(`${warmUp.padEnd(8)} warm-up ${result.warmUpMs.toFixed(0)} ms, first ${result.firstMs.toFixed(0)} ms, second ${result.secondMs.toFixed(0)} ms, steady ${result.steadyMs.toFixed(0)} ms (×${(result.firstMs / result.steadyMs).toFixed(2)}); programs ${result.programsWarmed} + ${result.programsFirstFrame}`);
      runs.push({ round, ...result });
    } finally {
      await session.close();
    }
  }
}
const summary = Object.fromEntries(WARM_UPS.map((warmUp) => {
  const of = runs.filter((r) => r.warmUp === warmUp);
  const m = (key) => median(of.map((r) => r[key]));
  return [warmUp, {
    warmUpMs: m('warmUpMs'), firstMs: m('firstMs'), secondMs: m('secondMs'), steadyMs: m('steadyMs'),
    firstOverSteady: median(of.map((r) => r.firstMs / r.steadyMs)),
    programsWarmed: of[0].programsWarmed, programsFirstFrame: of[0].programsFirstFrame, firstPrograms: of[0].firstPrograms,
  }];
}));
const result = {
  command: 'npm run bench:warm-up', date: new Date().toISOString(), ...options, parallelCompile: runs[0].parallelCompile, lightMap: runs[0].lightMap, summary, runs,
};
const file = join(root, quick ? 'bench/results/tmp/warm-up.json' : 'bench/results/warm-up.json');
await mkdir(dirname(file), { recursive: true });
await writeFile(file, `${JSON.stringify(result, null, 1)}\n`);
console.log(JSON.stringify(summary, null, 1));
console.log(`wrote ${file}`);
if (!quick) {
  const docs = join(root, 'docs/BENCH.md');
  await writeFile(docs, withBenchSection(await readFile(docs, 'utf8'), WARM_UP_HEADING, warmUpSection(result)));
  console.log(`wrote ${docs}`);
}
