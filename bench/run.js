// `npm run bench [-- --quick] [-- --gpu] [-- --report]`: the speed-accuracy bench. Renders every setting of the
// plan below in headless Chromium (SwiftShader, or the GPU with --gpu), measures its error against
// the dense 2D reference of the same profile and its time, then writes
//   full:  bench/results/<swiftshader|gpu>.json, the chart (docs/speed-accuracy.png for SwiftShader)
//          and docs/BENCH.md;
//   quick: bench/results/tmp/quick.json and bench/results/tmp/quick.png (not committed);
//   --report: only redraws the chart and rewrites docs/BENCH.md from the results file.
import { readFile, writeFile, mkdir } from 'node:fs/promises';
import { cpus, totalmem, platform, arch } from 'node:os';
import { join, dirname, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { withBenchPage, chromiumFlags } from './browser.js';
import { isDefaultSetting, median } from './analysis.js';
import { benchMarkdown, chartData } from './report.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const gpu = args.includes('--gpu');
const reportOnly = args.includes('--report');

const TAPS = [5, 7, 9, 11, 17, 25];
const separable = (method, samples) => ({ kind: 'separable', method, samples });
const dense = (coverage) => ({ kind: 'dense', coverage });
const DEFAULT = separable('footprint', 17);

const AUTO = separable('footprint', 'auto');

/** Every method × quality of the issue for one profile; the reference kernel and auto: skin only. */
function matrix(profile) {
  const skin = profile === 'skin';
  return [
    ...(skin ? [11, 17, 25].map((n) => separable('reference', n)) : []),
    ...['marginal', 'footprint'].flatMap((method) => TAPS.map((n) => separable(method, n))),
    ...(skin ? [AUTO] : []),
  ];
}

// Timing: each row is measured in `rounds` rounds interleaved with the other rows of its profile
// (a passing load on the machine then touches every row alike), each round timing `frames` whole
// frames and `sssFrames` re-runs of the SSS passes alone; every one gives a timer query, so a row
// has rounds × (frames + sssFrames) of them. The dense reference costs O(radius²) per pixel: its
// rows get one round of DENSE_TIMING (the JSON says how many queries each row has).
const MAIN_TIMING = { rounds: 3, frames: 1, sssFrames: 9 };
const SHORT_TIMING = { rounds: 2, frames: 1, sssFrames: 4 };
const ONE_ROUND_TIMING = { rounds: 1, frames: 1, sssFrames: 9 };
const DENSE_TIMING = { rounds: 1, frames: 1, sssFrames: 4 };
const REFERENCE_17 = separable('reference', 17);
const SYNTHETIC = [REFERENCE_17, separable('marginal', 17), separable('footprint', 9), DEFAULT];

const FULL_PLAN = [
  {
    scene: 'head', width: 1280, height: 720, chart: true, timing: MAIN_TIMING,
    profiles: { skin: [...matrix('skin'), dense(0.9), dense(0.99), dense(0.997)], skinBurley: matrix('skinBurley') },
  },
  // Resolution; the footprint sweeps show where its error stops falling (the auto rule).
  { scene: 'head', width: 640, height: 360, timing: MAIN_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, ...[5, 9, 11].map((n) => separable('footprint', n)), AUTO] } },
  { scene: 'head', width: 1920, height: 1080, timing: ONE_ROUND_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, separable('footprint', 11), separable('footprint', 25)] } },
  // Objects at equal screen coverage.
  { scene: 'heads4', width: 1280, height: 720, timing: SHORT_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17] } },
  { scene: 'heads16', width: 1280, height: 720, timing: SHORT_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17] } },
  { scene: 'slab', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: SYNTHETIC } },
  { scene: 'depthEdge', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: SYNTHETIC } },
  { scene: 'grazing', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: [...SYNTHETIC, AUTO] } },
];

const QUICK_TIMING = { rounds: 1, frames: 1, sssFrames: 4 };
const QUICK_PLAN = [
  {
    scene: 'head', width: 1280, height: 720, chart: true, timing: QUICK_TIMING,
    profiles: { skin: [DEFAULT, REFERENCE_17, separable('marginal', 17), separable('footprint', 9), AUTO, dense(0.99)] },
  },
  { scene: 'slab', width: 640, height: 360, timing: QUICK_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17] } },
];

const started = Date.now();
const elapsed = () => `${((Date.now() - started) / 1000).toFixed(0).padStart(4)} s`;
const log = (line) => console.log(`${elapsed()}  ${line}`);

/** JSON has no Infinity: an identical image's PSNR is written as null. */
const finite = (row) => Object.fromEntries(Object.entries(row).map(([k, v]) => [k, typeof v === 'number' && !Number.isFinite(v) ? null : v]));

/** Pools a setting's rounds: error from the first, medians of all the times. */
function pool(measured, context) {
  const [first] = measured;
  const all = (key) => measured.flatMap((m) => m.times[key]);
  const { times, ...row } = first;
  return finite({
    ...row,
    ...context,
    ms: median(all('frameMs')),
    gpuMs: median(all('gpuMs')),
    sssWallMs: median(all('sssWallMs')),
    frames: all('frameMs').length,
    timerQueries: all('gpuMs').length,
    rounds: measured.length,
  });
}

async function runPlan(page, plan) {
  const results = [];
  const references = [];
  for (const block of plan) {
    const resolution = `${block.width}x${block.height}`;
    const opened = await page.evaluate((o) => window.bench.open(o), { scene: block.scene, width: block.width, height: block.height });
    log(`${block.scene} ${resolution}${opened.isStandIn ? ' (STAND-IN: the head scan is missing)' : ''}`);
    const context = { scene: block.scene, resolution, chart: block.chart === true, isStandIn: opened.isStandIn };
    for (const [profile, settings] of Object.entries(block.profiles)) {
      const ref = await page.evaluate((p) => window.bench.reference({ profile: p }), profile);
      references.push({ scene: block.scene, resolution, profile, ...ref, isStandIn: opened.isStandIn });
      log(`  dense reference ${profile}: ${ref.ms.toFixed(0)} ms (one frame), radius ${ref.radiusPx.toFixed(1)} px, ${ref.subsurfacePixels} subsurface pixels`);
      const measured = settings.map(() => []);
      const rounds = Math.max(block.timing.rounds, DENSE_TIMING.rounds);
      for (let round = 0; round < rounds; round++) {
        for (const [i, setting] of settings.entries()) {
          const timing = setting.kind === 'dense' ? DENSE_TIMING : block.timing;
          if (round >= timing.rounds) continue;
          const options = { ...setting, profile, frames: timing.frames, sssFrames: timing.sssFrames, errors: round === 0, warmUp: false };
          measured[i].push(await page.evaluate((o) => window.bench.measure(o), options));
        }
      }
      for (const rounds of measured) {
        const row = pool(rounds, context);
        row.default = isDefaultSetting(row);
        results.push(row);
        const name = row.kind === 'dense' ? `dense ${row.coverage}` : `${row.method} ${row.auto ? `auto→${row.samples}` : row.samples}`;
        log(`    ${name.padEnd(18)} SSS ${row.gpuMs.toFixed(0).padStart(5)} ms  frame ${row.ms.toFixed(0).padStart(5)} ms  rmse ${(row.rmse * 100).toFixed(3)} %  ssim ${row.ssim.toFixed(4)}`);
      }
    }
  }
  await page.evaluate(() => window.bench.close());
  return { results, references };
}

/** Measures the plan; returns the results file's content. */
async function measure(page, plan, { name, info }) {
  const { userAgent, hardwareConcurrency, autoSamples, autoReach, ...webgl } = info;
  const { results, references } = await runPlan(page, plan);
  return {
    name,
    mode: quick ? 'quick' : 'full',
    command: `npm run bench${quick ? ' -- --quick' : ''}${gpu ? ' -- --gpu' : ''}`,
    createdAt: new Date().toISOString(),
    durationS: Math.round((Date.now() - started) / 1000),
    machine: { platform: platform(), arch: arch(), cpu: cpus()[0]?.model, cores: cpus().length, memoryGiB: +(totalmem() / 2 ** 30).toFixed(1), node: process.version },
    browser: { chromium: await page.browser().version(), userAgent, flags: chromiumFlags({ gpu }), hardwareConcurrency },
    webgl,
    module: { autoSamples, autoReach },
    timing: {
      gpuMs: 'median of EXT_disjoint_timer_query_webgl2 TIME_ELAPSED around the SSS passes only (both blurs, or the dense pass); '
        + 'timerQueries of them per row, over `rounds` rounds interleaved with the other rows of the same profile: `frames` from whole frames, '
        + 'the rest from re-running only the SSS passes over the same frame\'s scene targets',
      ms: 'median wall time of a whole composer.render() (scene pass with shadow and light depth maps, SSS passes, compose; no OutputPass) closed by a 1-pixel readPixels fence',
      dense: `dense rows are timed over ${DENSE_TIMING.frames + DENSE_TIMING.sssFrames} timer queries (${DENSE_TIMING.frames} whole frame, one round); the error reference is rendered once per scene, resolution and profile (references[].ms: one frame incl. read-back)`,
      swiftShader: /swiftshader/i.test(webgl.renderer) ? 'SwiftShader renders on the CPU: its times are CPU times on this machine; compare them as ratios within one run' : null,
    },
    errors: 'against the dense 2D reference (coverage 0.997) of the same profile, same scene and resolution, over subsurface pixels; '
      + 'rmse: relative RMSE of linear radiance; maxError: max |difference| (linear radiance); psnr: dB with peak = max reference value (null = identical); '
      + 'ssim: SSIM (ssim.js) of the ACES-filmic tone-mapped 8-bit outputs, mean over windows centred on subsurface pixels',
    references,
    results,
  };
}

async function main() {
  const name = quick ? 'quick' : gpu ? 'gpu' : 'swiftshader';
  const outDir = quick ? join(root, 'bench/results/tmp') : join(root, 'bench/results');
  const jsonPath = join(outDir, `${name}.json`);
  const chartPath = quick || gpu ? join(outDir, `${name}.png`) : join(root, 'docs/speed-accuracy.png');
  await mkdir(outDir, { recursive: true });

  // --report: redraw the chart and rewrite docs/BENCH.md from the results already there.
  const json = await withBenchPage(async (page) => {
    let out;
    if (reportOnly) {
      out = JSON.parse(await readFile(jsonPath, 'utf8'));
    } else {
      const info = await page.evaluate(() => window.bench.info());
      log(`${info.renderer} (timer query: ${info.timerQuery})`);
      if (!info.timerQuery) throw new Error('EXT_disjoint_timer_query_webgl2 is missing: the SSS times cannot be measured');
      if (gpu && /swiftshader/i.test(info.renderer)) log('WARNING: --gpu asked, but Chromium fell back to SwiftShader');
      out = await measure(page, quick ? QUICK_PLAN : FULL_PLAN, { name, info });
      await writeFile(jsonPath, `${JSON.stringify(out, null, 2)}\n`);
    }
    const png = await page.evaluate((o) => window.bench.drawChart(o), chartData(out.results.filter((r) => r.chart), out.webgl));
    await writeFile(chartPath, Buffer.from(png.split(',')[1], 'base64'));
    if (page.problems.length > 0) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
    return out;
  }, { gpu });
  log(`wrote ${reportOnly ? '' : `${relative(root, jsonPath)} and `}${relative(root, chartPath)}`);
  if (!quick && !gpu) {
    await writeFile(join(root, 'docs/BENCH.md'), benchMarkdown(json));
    log('wrote docs/BENCH.md');
  }
  log(`done in ${Math.round((Date.now() - started) / 1000)} s`);
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
