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
import { autoAgainstFixed, isDefaultSetting, median, peerSummary } from './analysis.js';
import { benchMarkdown, chartData } from './report.js';
import { peerRounds } from './peerRun.js';
import { FEATURES, RECOMPILING_FEATURES } from './peerPlan.js';
import { gpuProcessClock } from '../dev/processClock.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const babylonVersion = JSON.parse(await readFile(join(root, 'node_modules/@babylonjs/core/package.json'), 'utf8')).version;
const args = process.argv.slice(2);
const quick = args.includes('--quick');
const gpu = args.includes('--gpu');
const reportOnly = args.includes('--report');
// --peers: only the side-by-side (both resolutions, every feature and switch at each), merged into
// the results file in place of its `peers`; the first replaced keeps its numbers as
// `peersVersion02` (version 0.2's, the issue 19 table's "before" column).
const peersOnly = args.includes('--peers');

const TAPS = [5, 7, 9, 11, 13, 17, 25];
const separable = (method, samples) => ({ kind: 'separable', method, samples });
const dense = (coverage) => ({ kind: 'dense', coverage });
/** The module's default (PIPELINE_DEFAULTS): footprint, samples 'auto'. */
const DEFAULT = separable('footprint', 'auto');
/** The fixed footprint budgets 'auto' is held against on every scene: the cheapest that reaches its error. */
const footprintSweep = (taps) => taps.map((n) => separable('footprint', n));

/** Every method × quality of the issue for one profile; the reference kernel and auto: skin only. */
function matrix(profile) {
  const skin = profile === 'skin';
  return [
    ...(skin ? [11, 17, 25].map((n) => separable('reference', n)) : []),
    ...['marginal', 'footprint'].flatMap((method) => TAPS.map((n) => separable(method, n))),
    ...(skin ? [DEFAULT] : []),
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
const SYNTHETIC = [REFERENCE_17, separable('marginal', 17), ...footprintSweep([5, 7, 9, 11, 13, 17, 25]), DEFAULT];

const FULL_PLAN = [
  {
    scene: 'head', width: 1280, height: 720, chart: true, timing: MAIN_TIMING,
    profiles: { skin: [...matrix('skin'), dense(0.9), dense(0.99), dense(0.997)], skinBurley: matrix('skinBurley') },
  },
  // Resolution; each footprint sweep finds the cheapest fixed budget that reaches 'auto''s error.
  { scene: 'head', width: 640, height: 360, timing: MAIN_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, ...footprintSweep([5, 7, 9, 11, 13, 17])] } },
  { scene: 'head', width: 1920, height: 1080, timing: ONE_ROUND_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, ...footprintSweep([11, 13, 17, 25])] } },
  // Objects at equal screen coverage.
  { scene: 'heads4', width: 1280, height: 720, timing: SHORT_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, separable('footprint', 17)] } },
  { scene: 'heads16', width: 1280, height: 720, timing: SHORT_TIMING, profiles: { skin: [DEFAULT, REFERENCE_17, separable('footprint', 17)] } },
  { scene: 'slab', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: SYNTHETIC } },
  { scene: 'depthEdge', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: SYNTHETIC } },
  { scene: 'grazing', width: 640, height: 360, timing: SHORT_TIMING, profiles: { skin: SYNTHETIC } },
];

// The side-by-side with three.js and Babylon.js (bench/peers.js), head, defaults; `frames` timed
// frames per measure and round; the features block once, at 1280×720; the images at 640×360
// (two 1280×360 PNGs in docs/).
const FULL_PEERS = [
  { width: 1280, height: 720, rounds: 5, frames: 3, features: { rounds: 3, frames: 2 } },
  { width: 640, height: 360, rounds: 7, frames: 3, image: true },
];

// --peers: the four ratios of issue 19 at both resolutions, each of version 0.2's additions once per round.
const PEERS_ONLY = [
  { width: 1280, height: 720, rounds: 3, frames: 2, features: { rounds: 3, frames: 1 } },
  { width: 640, height: 360, rounds: 5, frames: 3, image: true, features: { rounds: 3, frames: 2 } },
];

const QUICK_TIMING = { rounds: 1, frames: 1, sssFrames: 4 };
const QUICK_PLAN = [
  {
    scene: 'head', width: 640, height: 360, chart: true, timing: QUICK_TIMING,
    profiles: { skin: [DEFAULT, REFERENCE_17, separable('marginal', 17), ...footprintSweep([9, 17]), dense(0.99)] },
  },
];
const QUICK_PEERS = [
  { width: 1280, height: 720, rounds: 2, frames: 1 },
  { width: 640, height: 360, rounds: 2, frames: 1, image: true, features: { rounds: 1, frames: 1 } },
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
    sssCpuMs: measured.every((m) => m.times.sssCpuMs[0] !== null) ? median(all('sssCpuMs')) : null,
    frames: all('frameMs').length,
    timerQueries: all('gpuMs').length,
    rounds: measured.length,
  });
}

async function runPlan(page, plan, clock) {
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
          const options = { ...setting, profile, frames: timing.frames, sssFrames: 0, errors: round === 0, warmUp: false };
          const row = await page.evaluate((o) => window.bench.measure(o), options);
          // The SSS re-runs on their own, with the GPU process's CPU clock read around them.
          const before = clock?.nowMs();
          const sss = await page.evaluate((o) => window.bench.timeSss(o), { count: timing.sssFrames });
          const sssCpuMs = clock ? (clock.nowMs() - before) / timing.sssFrames : null;
          row.times.gpuMs.push(...sss.gpuMs);
          row.times.sssWallMs.push(...sss.sssWallMs);
          row.times.sssCpuMs = [sssCpuMs];
          measured[i].push(row);
        }
      }
      for (const rounds of measured) {
        const row = pool(rounds, context);
        row.default = isDefaultSetting(row);
        results.push(row);
        const name = row.kind === 'dense' ? `dense ${row.coverage}`
          : `${row.method} ${row.taps ? `auto ${row.taps.mean.toFixed(1)}/${row.taps.max}` : row.auto ? `auto→${row.samples}` : row.samples}`;
        log(`    ${name.padEnd(18)} SSS ${row.gpuMs.toFixed(0).padStart(5)} ms  CPU ${String(row.sssCpuMs?.toFixed(0) ?? '—').padStart(5)} ms  frame ${row.ms.toFixed(0).padStart(5)} ms  rmse ${(row.rmse * 100).toFixed(3)} %  ssim ${row.ssim.toFixed(4)}`);
      }
    }
  }
  await page.evaluate(() => window.bench.close());
  return { results, references };
}

/**
 * The side-by-side (bench/peers.js, bench/peerRun.js) at each resolution of `plan`: the four
 * frames, the blur against its floor and ours stage by stage, in interleaved rounds; the images of
 * the blocks with `image` (each engine's plain and SSS frame, to `imagePaths.three` and
 * `imagePaths.babylon`); the features block where asked.
 */
async function runPeers(page, plan, imagePaths, clock) {
  const out = [];
  for (const block of plan) {
    const resolution = `${block.width}x${block.height}`;
    const opened = await page.evaluate((o) => window.bench.open(o), { scene: 'head', width: block.width, height: block.height });
    const entry = { resolution, isStandIn: opened.isStandIn, rounds: block.rounds, frames: block.frames };
    if (block.image) {
      const images = await page.evaluate(() => window.bench.peerImages());
      for (const engine of ['three', 'babylon']) await writeFile(imagePaths[engine], Buffer.from(images.png[engine].split(',')[1], 'base64'));
      entry.images = { resolution, plain: images.plain, withSss: images.withSss, sssChange: images.sssChange };
      log(`  ${resolution} plain frames: silhouette IoU ${images.plain.silhouetteIoU.toFixed(3)}, luma ratio ${images.plain.lumaRatio.toFixed(3)}; `
        + `SSS moves the luma by ${images.sssChange.three.toFixed(2)} (ours), ${images.sssChange.babylon.toFixed(2)} (Babylon); wrote ${Object.values(imagePaths).map((p) => relative(root, p)).join(', ')}`);
    }
    entry.coverage = await page.evaluate(() => window.bench.peerCoverage()); // the cost model's inputs
    entry.perRound = await peerRounds(page, clock, block);
    entry.summary = peerSummary(entry.perRound);
    const { overhead, blurOverFloor, nonBlurShare } = entry.summary;
    log(`  ${resolution} overhead ours/Babylon ${overhead.timer.ratio.median.toFixed(2)} (${overhead.timer.ratio.min.toFixed(2)}-${overhead.timer.ratio.max.toFixed(2)})`
      + `${overhead.cpu ? `, CPU ${overhead.cpu.ratio.median.toFixed(2)}` : ''}; blur/floor ${blurOverFloor.timer.median.toFixed(2)}; non-blur/plain ${nonBlurShare.median.toFixed(2)}`);
    if (block.features) entry.features = await runFeatures(page, clock, block.features);
    out.push(entry);
  }
  await page.evaluate(() => window.bench.close());
  return out;
}

/**
 * What version 0.2's additions cost (FEATURES), ours stage by stage, in interleaved rounds; the
 * plain frame with each addition too.
 */
async function runFeatures(page, clock, { rounds, frames }) {
  const measures = [null, ...FEATURES].flatMap((feature) => [{ measure: 'stages', feature }, { measure: 'threePlain', feature }]);
  const perRound = [];
  for (let round = 0; round < rounds; round++) {
    const entry = {};
    for (let k = 0; k < measures.length; k++) {
      const { measure, feature } = measures[(k + round) % measures.length];
      // A feature that recompiles is warmed up in the timed call (it is switched off between calls).
      const recompiles = RECOMPILING_FEATURES.includes(feature);
      if (!recompiles) await page.evaluate((o) => window.bench.peerMeasure(o), { measure, feature, frames: 0, warmUp: 1 });
      const before = clock?.nowMs();
      const times = await page.evaluate((o) => window.bench.peerMeasure(o), { measure, feature, frames, warmUp: recompiles ? 2 : 0 });
      const cpuMs = clock && !recompiles ? (clock.nowMs() - before) / frames : null;
      const key = feature ?? 'none';
      entry[key] ??= {};
      if (measure === 'stages') {
        entry[key].stages = Object.fromEntries(Object.entries(times).map(([stage, ms]) => [stage, median(ms)]));
        entry[key].cpuMs = cpuMs; // the GPU process's CPU time per frame of ours (less swollen by other load)
      }
      else entry[key].threePlain = { timerMs: median(times.threePlain), cpuMs };
    }
    perRound.push(entry);
  }
  log(`  features: ${FEATURES.join(', ')} (${rounds} rounds)`);
  return perRound;
}

/** Measures the plan; returns the results file's content. */
async function measure(page, plan, { name, info, peersPlan, imagePaths }) {
  const { userAgent, hardwareConcurrency, autoSamples, autoStepError, ...webgl } = info;
  const clock = gpuProcessClock(page.browser());
  log(`GPU process CPU clock: ${clock ? `pid ${clock.pid}` : 'not readable (timer queries only)'}`);
  const peers = await runPeers(page, peersPlan, imagePaths, clock);
  const { results, references } = await runPlan(page, plan, clock);
  return {
    name,
    mode: quick ? 'quick' : 'full',
    command: `npm run bench${quick ? ' -- --quick' : ''}${gpu ? ' -- --gpu' : ''}`,
    createdAt: new Date().toISOString(),
    durationS: Math.round((Date.now() - started) / 1000),
    machine: { platform: platform(), arch: arch(), cpu: cpus()[0]?.model, cores: cpus().length, memoryGiB: +(totalmem() / 2 ** 30).toFixed(1), node: process.version },
    browser: { chromium: await page.browser().version(), userAgent, flags: chromiumFlags({ gpu }), hardwareConcurrency },
    babylon: babylonVersion,
    webgl,
    module: { autoSamples, autoStepError },
    timing: {
      sssCpuMs: 'the GPU process\'s CPU time per re-run of the SSS passes (dev/processClock.js), median over the rounds: what SwiftShader spent, less swollen by other load than the timer queries',
      gpuMs: 'median of EXT_disjoint_timer_query_webgl2 TIME_ELAPSED around the SSS passes only (both blurs, or the dense pass); '
        + 'timerQueries of them per row, over `rounds` rounds interleaved with the other rows of the same profile: `frames` from whole frames, '
        + 'the rest from re-running only the SSS passes over the same frame\'s scene targets',
      ms: 'median wall time of a whole composer.render() (scene pass with shadow and light depth maps, SSS passes, compose; no OutputPass) closed by a 1-pixel readPixels fence',
      dense: `dense rows are timed over ${DENSE_TIMING.frames + DENSE_TIMING.sssFrames} timer queries (${DENSE_TIMING.frames} whole frame, one round); the error reference is rendered once per scene, resolution and profile (references[].ms: one frame incl. read-back)`,
      peers: 'side-by-side (bench/peers.js): per measure and round, the median of `frames` timer queries around whole frames (or the stages, the blur, the floor), '
        + 'and the GPU process\'s CPU time per frame (Linux /proc schedstat of its threads, dev/processClock.js); the ratios per round, then their median and range over the rounds',
      swiftShader: /swiftshader/i.test(webgl.renderer) ? 'SwiftShader renders on the CPU: its times are CPU times on this machine; compare them as ratios within one run' : null,
    },
    errors: 'against the dense 2D reference (coverage 0.997) of the same profile, same scene and resolution, over subsurface pixels; '
      + 'rmse: relative RMSE of linear radiance; maxError: max |difference| (linear radiance); psnr: dB with peak = max reference value (null = identical); '
      + 'ssim: SSIM (ssim.js) of the ACES-filmic tone-mapped 8-bit outputs, mean over windows centred on subsurface pixels',
    references,
    results,
    peers,
  };
}

/**
 * --peers: the side-by-side measured again (PEERS_ONLY) into `previous` (the results file), the
 * rest of it kept; the first side-by-side replaced stays as `peersVersion02`.
 */
async function remeasurePeers(page, previous, imagePaths) {
  const info = await page.evaluate(() => window.bench.info());
  log(`${info.renderer}: the side-by-side only, into the results of ${previous.createdAt.slice(0, 10)}`);
  const clock = gpuProcessClock(page.browser());
  const peers = await runPeers(page, PEERS_ONLY, imagePaths, clock);
  return {
    ...previous,
    peersVersion02: previous.peersVersion02 ?? { createdAt: previous.createdAt, peers: previous.peers },
    peers,
    peersRun: { command: 'npm run bench -- --peers', createdAt: new Date().toISOString(), durationS: Math.round((Date.now() - started) / 1000) },
  };
}

async function main() {
  const name = quick ? 'quick' : gpu ? 'gpu' : 'swiftshader';
  const outDir = quick ? join(root, 'bench/results/tmp') : join(root, 'bench/results');
  const jsonPath = join(outDir, `${name}.json`);
  const chartPath = quick || gpu ? join(outDir, `${name}.png`) : join(root, 'docs/speed-accuracy.png');
  // Each engine's plain and SSS frame (docs/BENCH.md shows the full run's).
  const imagePaths = Object.fromEntries(['three', 'babylon'].map((engine) => [engine, quick || gpu ? join(outDir, `${name}-${engine}.png`) : join(root, `docs/bench-${engine}.png`)]));
  await mkdir(outDir, { recursive: true });

  // --report: redraw the chart and rewrite docs/BENCH.md from the results already there.
  const json = await withBenchPage(async (page) => {
    let out;
    if (reportOnly) {
      out = JSON.parse(await readFile(jsonPath, 'utf8'));
    } else if (peersOnly) {
      out = await remeasurePeers(page, JSON.parse(await readFile(jsonPath, 'utf8')), imagePaths);
      await writeFile(jsonPath, `${JSON.stringify(out, null, 2)}\n`);
    } else {
      const info = await page.evaluate(() => window.bench.info());
      log(`${info.renderer} (timer query: ${info.timerQuery})`);
      if (!info.timerQuery) throw new Error('EXT_disjoint_timer_query_webgl2 is missing: the SSS times cannot be measured');
      if (gpu && /swiftshader/i.test(info.renderer)) log('WARNING: --gpu asked, but Chromium fell back to SwiftShader');
      out = await measure(page, quick ? QUICK_PLAN : FULL_PLAN, { name, info, peersPlan: quick ? QUICK_PEERS : FULL_PEERS, imagePaths });
      // Version 0.2's side-by-side (the issue 19 table's "before" column) outlives every run.
      const baseline = JSON.parse(await readFile(jsonPath, 'utf8').catch(() => 'null'))?.peersVersion02;
      if (baseline) out = { ...out, peersVersion02: baseline };
      await writeFile(jsonPath, `${JSON.stringify(out, null, 2)}\n`);
    }
    const png = await page.evaluate((o) => window.bench.drawChart(o), chartData(out.results.filter((r) => r.chart), out.webgl));
    await writeFile(chartPath, Buffer.from(png.split(',')[1], 'base64'));
    if (page.problems.length > 0) throw new Error(`the bench page reported errors:\n${page.problems.join('\n')}`);
    return out;
  }, { gpu });
  log(`wrote ${reportOnly ? '' : `${relative(root, jsonPath)} and `}${relative(root, chartPath)}`);
  // The full run's report is docs/BENCH.md; a quick or GPU run's goes beside its results.
  const markdownPath = quick || gpu ? join(outDir, `${name}.md`) : join(root, 'docs/BENCH.md');
  const resultOf = async (file) => JSON.parse(await readFile(join(root, 'bench/results', file), 'utf8').catch(() => 'null'));
  await writeFile(markdownPath, benchMarkdown(json, { transfer: await resultOf('transfer.json'), surfaceTruth: await resultOf('surface-truth.json'), webgpu: await resultOf('webgpu.json'), lights: await resultOf('lights.json'), sceneGraph: await resultOf('scene-graph.json'), warmUp: await resultOf('warm-up.json'), memory: await resultOf('memory.json') }));
  log(`wrote ${relative(root, markdownPath)}`);
  for (const p of json.peers ?? []) {
    const { overhead } = p.summary;
    log(`${p.resolution}: overhead ours/Babylon ${overhead.timer.ratio.median.toFixed(2)} (${overhead.timer.ratio.min.toFixed(2)}-${overhead.timer.ratio.max.toFixed(2)}) by timer queries`
      + `${overhead.cpu ? `, ${overhead.cpu.ratio.median.toFixed(2)} (${overhead.cpu.ratio.min.toFixed(2)}-${overhead.cpu.ratio.max.toFixed(2)}) by CPU time` : ''}`);
  }
  for (const c of autoAgainstFixed(json.results, json.results.every((r) => r.kind !== 'separable' || r.sssCpuMs > 0) ? 'sssCpuMs' : 'gpuMs')) {
    log(`${c.scene} ${c.resolution}: auto ${(c.auto.rmse * 100).toFixed(3)} %, cheapest fixed at its error ${c.cheapest ? `${c.cheapest.samples} taps, auto/it ${c.timeRatio.toFixed(2)}` : 'none'}`);
  }
  log(`done in ${Math.round((Date.now() - started) / 1000)} s`);
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
