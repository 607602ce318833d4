// Turns the bench's JSON into the chart's data and docs/BENCH.md (whose first section is meant to
// be pasted into the README). Every number comes from the results; nothing is typed in by hand.
import { costModelSection, issueTableSection, verdict } from './costReport.js';
import { surfaceTruthSummary } from './surfaceTruth/report.js';
import {
  autoAgainstFixed, deviceName, dominates, isDefaultSetting, median, paretoFront, percent as pct, ratio, rowsOf, SAME_ERROR, SATURATION, settingName, spread, table,
} from './analysis.js';
const MAIN = { scene: 'head', resolution: '1280x720' };

/** The series a row belongs to on the chart. */
function seriesOf(row) {
  const method = row.kind === 'dense' ? 'dense' : row.auto ? 'auto' : row.method;
  return `${method} ${row.profile}`;
}

function pointLabel(row) {
  if (row.kind === 'dense') return `${(row.coverage * 100).toFixed(1)} %`;
  if (row.taps) return `auto, ${row.taps.mean.toFixed(1)} taps/pixel`;
  return row.auto ? `auto→${row.samples}` : String(row.samples);
}

/** What 'auto' costs and saves at the chart's scene: the cheapest fixed budget with its error. */
function autoNote(rows) {
  const time = robustTime(rows.filter((r) => r.kind === 'separable'));
  const [c] = autoAgainstFixed(rows, time);
  if (!c) return '';
  return c.cheapest
    ? `: ×${ratio(c.auto[time], c.cheapest[time])} the ${time === 'sssCpuMs' ? 'CPU time' : 'time'} of ${c.cheapest.samples} fixed taps, the cheapest at its error`
    : ': no fixed budget measured reaches its error';
}


/** The Pareto front of each profile's rows: errors of different profiles are against different references. */
export function frontsByProfile(rows) {
  const profiles = [...new Set(rows.map((r) => r.profile))];
  return profiles.map((profile) => ({ profile, rows: paretoFront(rows.filter((r) => r.profile === profile)) }));
}

/**
 * The arguments of bench/chart.js's drawChart for the chart rows (the head at 720p).
 * @param {object[]} rows
 * @param {{ renderer: string }} webgl
 */
export function chartData(rows, webgl) {
  const shown = rows.filter((r) => r.rmse > 0);
  const toPoint = (r) => ({ x: r.gpuMs, y: r.rmse * 100 });
  const main = rows.find(isDefaultSetting);
  const [width, height] = (rows[0]?.resolution ?? 'x').split('x');
  return {
    points: shown.map((r) => ({ series: seriesOf(r), label: pointLabel(r), ...toPoint(r) })),
    fronts: frontsByProfile(rows).map(({ profile, rows: front }) => ({ label: `Pareto front, ${profile}`, points: front.map(toPoint) })),
    highlight: main ? { ...toPoint(main), label: `default: footprint, skin, samples 'auto'${autoNote(rows)}` } : { x: NaN, y: NaN, label: 'default: not measured' },
    title: `Speed vs accuracy of the SSS passes: head, ${width}×${height}, ${deviceName(webgl)}`,
    subtitle: 'error: relative RMSE of linear radiance against the dense 2D reference of the same profile, subsurface pixels; labels: taps per direction or the dense radius\'s energy',
    xTitle: 'SSS passes, ms (median of timer queries; on SwiftShader these are CPU times)',
    yTitle: 'relative RMSE, % (log)',
  };
}

const ms = (v) => `${v.toFixed(0)} ms`;
const find = (rows, method, samples, profile = 'skin') => rows.find((r) => r.kind === 'separable' && !r.auto && r.method === method && r.samples === samples && r.profile === profile);

/** The Pareto paragraph: on the front, or who dominates the default and by how much. */
function paretoParagraph(rows, main) {
  if (!main) return 'The default setting was not measured.';
  const better = rows.filter((r) => dominates(r, main));
  if (better.length === 0) {
    const front = paretoFront(rows);
    const faster = front[front.indexOf(main) - 1];
    const next = faster
      ? ` The next faster setting on the front, ${settingName(faster)}, saves ${((1 - faster.gpuMs / main.gpuMs) * 100).toFixed(0)} % of the SSS time for ${((faster.rmse / main.rmse - 1) * 100).toFixed(0)} % more error.`
      : '';
    return `**The default is on the Pareto front**: no measured skin setting is both faster and more accurate (error against SSS time, ${rows.length} settings; settings of another profile are measured against another reference).${next}`;
  }
  const list = better.map((r) => `${settingName(r)} (${ms(r.gpuMs)}, ${pct(r.rmse)})`).join('; ');
  return `**The default is NOT on the Pareto front**: ${list} ${better.length === 1 ? 'is' : 'are'} both faster and more accurate than the default (${ms(main.gpuMs)}, ${pct(main.rmse)}).`;
}

/** The default's row (samples 'auto') or the reference kernel's at 17 taps, of one scene and resolution. */
const settingAt = (results, scene, resolution, which) => {
  const rows = rowsOf(results, scene, resolution);
  return which === 'default' ? rows.find(isDefaultSetting) : find(rows, 'reference', 17);
};
const SCALING_SETTINGS = [['default', "footprint, samples 'auto' (default)"], ['reference', 'reference, 17 taps']];

function scalingSection(results) {
  const lines = ['## Scaling (ratios within this run)', ''];
  // Resolution.
  const resolutions = ['640x360', '1280x720', '1920x1080'];
  lines.push('**Resolution** (head; SSS time relative to 1280×720; the pixel count ratios are 0.25, 1, 2.25):', '');
  lines.push('| setting | 640×360 | 1280×720 | 1920×1080 |', '|---|---|---|---|');
  for (const [which, name] of SCALING_SETTINGS) {
    const base = settingAt(results, 'head', '1280x720', which);
    const cells = resolutions.map((res) => {
      const r = settingAt(results, 'head', res, which);
      return r && base ? `${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)})` : '—';
    });
    lines.push(`| ${name} | ${cells.join(' | ')} |`);
  }
  // Objects.
  lines.push('', '**Objects at equal screen coverage** (1280×720, 1, 4 and 16 heads in a grid, each scaled to 1/√n; same on-screen kernel):', '');
  lines.push('| setting | 1 head | 4 heads | 16 heads |', '|---|---|---|---|');
  for (const [which, name] of SCALING_SETTINGS) {
    const rows = ['head', 'heads4', 'heads16'].map((scene) => settingAt(results, scene, '1280x720', which));
    const base = rows[0];
    const cells = rows.map((r) => (r && base ? `SSS ${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)}), frame ${ms(r.ms)}` : '—'));
    lines.push(`| ${name} | ${cells.join(' | ')} |`);
  }
  // Taps.
  const main = rowsOf(results, MAIN.scene, MAIN.resolution);
  lines.push('', '**Taps** (head, 1280×720, skin; SSS time relative to 5 taps):', '');
  const taps = [...new Set(main.filter((r) => r.kind === 'separable' && !r.auto && r.method !== 'reference').map((r) => r.samples))].sort((a, b) => a - b);
  lines.push(`| method | ${taps.join(' | ')} |`, `|---|${taps.map(() => '---').join('|')}|`);
  for (const method of ['marginal', 'footprint']) {
    const base = find(main, method, taps[0]);
    const cells = taps.map((n) => {
      const r = find(main, method, n);
      return r && base ? `${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)})` : '—';
    });
    lines.push(`| ${method} | ${cells.join(' | ')} |`);
  }
  const base = find(main, 'reference', 11);
  if (base) lines.push(`| reference (relative to 11) | ${taps.map((n) => { const r = find(main, 'reference', n); return r ? `${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)})` : '—'; }).join(' | ')} |`);
  return lines.join('\n');
}

function syntheticSection(results) {
  const lines = ['## Synthetic scenes', ''];
  const scenes = {
    slab: 'a white slab with the hard edge of a spot light (edges in every direction)',
    depthEdge: 'a textured slab 3 cm in front of a dim one (depth edge)',
    grazing: 'a textured plane tilted 75° away from the camera (grazing angle)',
  };
  for (const [scene, what] of Object.entries(scenes)) {
    const rows = results.filter((r) => r.scene === scene);
    if (rows.length === 0) continue;
    lines.push(`**${scene}** (${rows[0].resolution.replace('x', '×')}): ${what}.`, '', table(rows, { frame: false }), '');
  }
  return lines.join('\n');
}

/** The clock the comparisons of close times use: the GPU process's CPU time where every row has it. */
const robustTime = (rows) => (rows.length > 0 && rows.every((r) => r.sssCpuMs > 0) ? 'sssCpuMs' : 'gpuMs');
const clockName = (time) => (time === 'sssCpuMs' ? 'CPU time' : 'timer queries');

/** samples 'auto' against the fixed budgets of every scene (the goal: within 1.2 × the cheapest of equal error). */
function autoSection(results, moduleInfo) {
  const time = robustTime(results.filter((r) => r.kind === 'separable'));
  const comparisons = autoAgainstFixed(results, time);
  if (comparisons.length === 0) return '';
  const other = time === 'sssCpuMs' ? 'gpuMs' : null;
  const lines = [
    "## samples 'auto' against fixed budgets",
    '',
    `The default's \`samples: 'auto'\` takes per pixel, from the footprint table, the fewest taps whose worst step-edge error is within ${pct(moduleInfo?.autoStepError ?? NaN)} at that pixel's on-screen scale. ` +
      `Against it, on every scene: the cheapest fixed footprint budget whose error is at most ${SAME_ERROR * 100} % above auto's ("cheapest at its error", by ${clockName(time)}; goal: auto within 1.2× its time), ` +
      `and the budget the scene needs (the fewest fixed taps within ${SATURATION * 100} % of the best error measured there; goal: auto's taps per pixel never above it). ` +
      "Taps per pixel: the table's count for the pixel's scale, per direction, over the subsurface pixels and both axes (an upper bound: the grazing-angle correction only lowers the scale).",
    '',
    `| scene | resolution | auto: rel. RMSE | auto: SSS ms (CPU ms) | auto: taps per pixel, mean / max | cheapest fixed at its error | auto / it by ${clockName(time)} (goal ≤ 1.2)${other ? ' | by timer queries' : ''} | the scene needs | fixed budgets (rel. RMSE, SSS ms) |`,
    `|---|---|---|---|---|---|---|${other ? '---|' : ''}---|---|`,
  ];
  const cpu = (r) => (r.sssCpuMs > 0 ? ` (${ms(r.sssCpuMs)})` : '');
  for (const c of comparisons) {
    const fixedText = c.fixed.map((r) => `${r.samples}: ${pct(r.rmse)}, ${ms(r.gpuMs)}${cpu(r)}`).join('; ');
    const cheapest = c.cheapest ? `${c.cheapest.samples} taps (${pct(c.cheapest.rmse)}, ${ms(c.cheapest.gpuMs)}${cpu(c.cheapest)})` : 'none reaches it';
    const verdict = Number.isFinite(c.timeRatio) ? `${c.timeRatio.toFixed(2)}${c.timeRatio <= 1.2 ? '' : ' **(over)**'}` : '—';
    const taps = c.auto.taps ? `${c.auto.taps.mean.toFixed(1)} / ${c.auto.taps.max}` : '—';
    const byTimer = other ? ` | ${c.cheapest ? ratio(c.auto.gpuMs, c.cheapest.gpuMs) : '—'}` : '';
    lines.push(`| ${c.scene} | ${c.resolution} | ${pct(c.auto.rmse)} | ${ms(c.auto.gpuMs)}${cpu(c.auto)} | ${taps} | ${cheapest} | ${verdict}${byTimer} | ${c.needed.samples} taps (${pct(c.needed.rmse)}) | ${fixedText} |`);
  }
  const over = comparisons.filter((c) => c.timeRatio > 1.2);
  const above = comparisons.filter((c) => c.auto.taps && c.auto.taps.mean > c.needed.samples);
  lines.push('', over.length === 0
    ? `By ${clockName(time)}, on every scene 'auto' is within 1.2× the time of the cheapest fixed budget at its error (${comparisons.map((c) => `${c.scene} ${c.resolution}: ×${Number.isFinite(c.timeRatio) ? c.timeRatio.toFixed(2) : '—'}`).join(', ')}).`
    : `By ${clockName(time)}, 'auto' is over 1.2× the cheapest fixed budget at its error on ${over.map((c) => `${c.scene} ${c.resolution} (×${c.timeRatio.toFixed(2)})`).join(', ')}.`);
  lines.push('', above.length === 0
    ? "On average per pixel 'auto' uses no more taps than each scene needs."
    : `On average per pixel 'auto' uses more taps than the scene needs on ${above.map((c) => `${c.scene} ${c.resolution} (${c.auto.taps.mean.toFixed(1)} against ${c.needed.samples})`).join(', ')}.`);
  return lines.join('\n');
}

const spreadText = (x, digits = 2) => (x && Number.isFinite(x.median) ? `${x.median.toFixed(digits)} (${x.min.toFixed(digits)}–${x.max.toFixed(digits)})` : '—');
const goal = (x, limit) => verdict(x, limit) || '—';

/** The side-by-side with three.js and Babylon.js (bench/peers.js), per resolution. */
function peersSection(json) {
  const peers = json.peers ?? [];
  if (peers.length === 0) return '';
  const images = peers.find((p) => p.images);
  const lines = ['## Against a plain three.js frame and Babylon.js', ''];
  lines.push("The head with the module's defaults (three.js + three-separable-sss), a plain three.js frame (a `RenderPass` in the same composer), and Babylon.js " +
    `${json.babylon ? `${json.babylon} ` : ''}on the same scan file, maps, camera, lights and resolution, plain and with its prepass subsurface scattering ` +
    '(`scene.enableSubSurfaceForPrePass()`, `material.subSurface.isScatteringEnabled`, a Burley profile with the skinBurley preset\'s scatter distances: the same 99.7 % radius as d\'Eon skin), ' +
    'in one Chromium and one page (bench/peers.js, bench/babylonHead.js).');
  if (images) {
    const { plain } = images.images;
    lines.push('', '![three.js: the head plain and with three-separable-sss at its defaults](bench-three.png)', '',
      '![Babylon.js: the head plain and with its prepass subsurface scattering](bench-babylon.png)', '',
      `The two plain frames agree (${images.images.resolution.replace('x', '×')}): their silhouettes overlap with intersection over union ${plain.silhouetteIoU.toFixed(3)}, ` +
      `the mean 8-bit luma over the head differs by ${((plain.lumaRatio - 1) * 100).toFixed(1)} % (Babylon against three.js).` +
      (images.images.sssChange ? ` Each engine's SSS moves the mean luma over the head by ${images.images.sssChange.three.toFixed(2)} (ours) and ${images.images.sssChange.babylon.toFixed(2)} (Babylon.js) steps of 8 bits. ` : ' ') +
      "Babylon's image is much blurrier: its shader reads the profile's colour as the scatter distance where it places its samples (out to the 99.7 % radius) but as the Burley shape parameter (1 / distance) where it weights them, so with distances below 1 mm the weights are nearly flat; its prepass composition also puts the clear colour through its image processing (the lifted background). " +
      'Its cost does not hang on the profile: it takes π (radius in pixels)² / 4 samples per pixel up to its budget of 40, and the head reaches the budget at both resolutions.');
  }
  lines.push('', "Each round times every measure a few frames (after an untimed one), in an order rotated every round; the ratios are taken within each round, then their median and range (min–max) over the rounds. " +
    'Frame: one EXT_disjoint_timer_query_webgl2 query around the whole frame; CPU: the CPU time of the GPU process (SwiftShader renders there) per frame, which a load elsewhere on the machine swells less.', '');
  lines.push('| resolution | rounds | plain three.js | ours | plain Babylon.js | Babylon.js SSS | overhead ours / Babylon (goal ≤ 0.5) | by CPU time | blur / its floor (goal ≤ 1.5) | everything but the blur / plain frame (goal ≤ 0.3) |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|');
  for (const p of peers) {
    const f = p.summary.frames;
    const { overhead, blurOverFloor, nonBlurShare } = p.summary;
    lines.push(`| ${p.resolution.replace('x', '×')} | ${p.summary.rounds} | ${ms(f.threePlain.timerMs.median)} | ${ms(f.ours.timerMs.median)} | ${ms(f.babylonPlain.timerMs.median)} | ${ms(f.babylonSss.timerMs.median)} | ` +
      `${spreadText(overhead.timer.ratio)}: ${goal(overhead.timer.ratio, 0.5)} | ${spreadText(overhead.cpu?.ratio)} | ${spreadText(blurOverFloor.timer)}: ${goal(blurOverFloor.timer, 1.5)} | ${spreadText(nonBlurShare)}: ${goal(nonBlurShare, 0.3)} |`);
  }
  lines.push('', 'Overheads (frame minus its plain frame, median over rounds): ' + peers.map((p) => {
    const { overhead, frames } = p.summary;
    return `${p.resolution.replace('x', '×')}: ours ${ms(overhead.timer.ours.median)}, Babylon.js ${ms(overhead.timer.babylon.median)}; blur ${ms(frames.blur.timerMs.median)} against the floor's ${ms(frames.floor.timerMs.median)}`;
  }).join('; ') + '. The floor: two 17-tap passes over the same subsurface pixels that only fetch (bench/floorPass.js).');
  // Per stage.
  const stages = Object.keys(peers[0].summary.stages);
  lines.push('', '**Ours, stage by stage** (stage timer, median over rounds; a stage that did not run reads 0):', '');
  lines.push(`| resolution | plain three.js frame | ${stages.join(' | ')} | sum |`, `|---|---|${stages.map(() => '---').join('|')}|---|`);
  for (const p of peers) {
    const st = p.summary.stages;
    lines.push(`| ${p.resolution.replace('x', '×')} | ${ms(p.summary.frames.threePlain.timerMs.median)} | ${stages.map((k) => (st[k] < 0.5 ? '0' : ms(st[k]))).join(' | ')} | ${ms(stages.reduce((sum, k) => sum + st[k], 0))} |`);
  }
  return lines.join('\n');
}

const stageSum = (st) => Object.values(st).reduce((sum, v) => sum + (Number.isFinite(v) ? v : 0), 0);

/** What the features beyond the default frame cost (bench/peerPlan.js's ADDITIONS), at the resolution measured. */
function featuresSection(json) {
  const block = (json.peers ?? []).find((p) => p.features);
  if (!block) return '';
  const rounds = block.features;
  const of = (feature, f) => median(rounds.map((r) => f(r[feature])));
  const base = (f) => of('none', f);
  const rows = [
    ['MSAA 4 (`multisampling: 4`; the plain frame into a 4-sample buffer)', 'msaa4', ['scene', 'blurH', 'blurV', 'compose']],
    ['a transparent pane over the chin (drawn after the compose)', 'transparent', ['transparent']],
    ['a marble and a milk ball beside the head, in the head\'s skin profile (one profile)', 'threeObjects', ['scene', 'blurH', 'blurV', 'compose']],
    ['the same balls in their own profiles (three profiles on screen)', 'threeProfiles', ['scene', 'blurH', 'blurV', 'compose']],
    ["the isotropic blur (`kernelGroups: 'auto'`; the default blurs with one kernel)", 'isotropic', ['blurH', 'blurV']],
  ].filter(([, feature]) => rounds.every((r) => r[feature]));
  const lines = [`## What the features cost (head, ${block.resolution.replace('x', '×')}, ${rounds.length} rounds)`, ''];
  lines.push('| addition | ours: frame (sum of stages) with it − without | stages it touches, with / without | plain three.js frame with it − without |', '|---|---|---|---|');
  for (const [name, feature, stages] of rows) {
    const ours = of(feature, (x) => stageSum(x.stages)) - base((x) => stageSum(x.stages));
    const plain = of(feature, (x) => x.threePlain.timerMs) - base((x) => x.threePlain.timerMs);
    const touched = stages.map((k) => `${k} ${of(feature, (x) => x.stages[k] ?? 0).toFixed(1)} / ${base((x) => x.stages[k] ?? 0).toFixed(1)}`).join(', ');
    const plainCell = feature === 'isotropic' ? '— (no blur)' : `${plain >= 0 ? '+' : ''}${ms(plain)}`;
    lines.push(`| ${name} | ${ours >= 0 ? '+' : ''}${ms(ours)} | ${touched} | ${plainCell} |`);
  }
  if (rounds.every((r) => r.threeProfiles && r.threeObjects)) {
    // The profiles' own cost: the same pixels, three profiles against one, per round.
    const blur = (x) => (x.stages.blurH ?? 0) + (x.stages.blurV ?? 0);
    const d = spread(rounds.map((r) => blur(r.threeProfiles) - blur(r.threeObjects)));
    const ratio = spread(rounds.map((r) => blur(r.threeProfiles) / blur(r.threeObjects)));
    lines.push('', `Three profiles against one on the same pixels (the last two rows, per round): both blurs ${d.median >= 0 ? '+' : ''}${ms(d.median)} (${ms(d.min)} to ${ms(d.max)}), ×${ratio.median.toFixed(2)} (${ratio.min.toFixed(2)}–${ratio.max.toFixed(2)}); a frame of one profile runs the blur compiled as before several profiles existed (PROFILE_COUNT 1).`);
  }
  if (rounds.every((r) => r.isotropic)) {
    // Issue 20's budget: the isotropic blur against the same release's one-kernel blur, per round.
    const blur = (x) => (x.stages.blurH ?? 0) + (x.stages.blurV ?? 0);
    const ratio = spread(rounds.map((r) => blur(r.isotropic) / blur(r.none)));
    lines.push('', `The isotropic blur against one kernel on the same frame (the budget: ≤ 1.3×), per round: both blurs ×${ratio.median.toFixed(2)} (${ratio.min.toFixed(2)}–${ratio.max.toFixed(2)}).`);
  }
  lines.push('', 'Stage times in ms (stage timer, median over rounds); "with − without" from the same rounds. Noise: timer queries of identical frames spread by about ±25 % on this shared machine, so differences under a tenth of the frame are not resolved.');
  return lines.join('\n');
}

/**
 * docs/BENCH.md from the bench's JSON.
 * @param {object} json the results file's content
 * @returns {string}
 */
/**
 * The two measures beyond the dense reference, from their own runs' results when present:
 * bench/transfer/run.js (gratings against the analytic transfer) and bench/surfaceTruth/run.js.
 */
function beyondDenseSection({ transfer, surfaceTruth } = {}) {
  if (!transfer && !surfaceTruth) return '';
  const parts = ['## Beyond the dense reference', ''];
  if (transfer) {
    const worst = (profile) => Math.max(...transfer.measurements.filter((m) => m.profile === profile).map((m) => m.worst));
    const profiles = [...new Set(transfer.measurements.map((m) => m.profile))];
    const scales = [...new Set(transfer.measurements.map((m) => m.pxPerMm))];
    parts.push(`**Transfer** (\`npm run bench:transfer\`, ${transfer.date.slice(0, 10)}): cosine gratings of albedo on a flat plane at ${scales.join(', ')} px/mm, the default's measured modulation transfer against the analytic one (the profile marginal's Fourier transform), per channel; worst difference ${profiles.map((p) => `${p} ${worst(p).toFixed(3)}`).join(', ')}.`,
      '', '![Measured against analytic transfer per channel](transfer.svg)', '');
  }
  if (surfaceTruth) {
    parts.push(`**Surface-space truth** (\`npm run bench:truth\`, ${surfaceTruth.date.slice(0, 10)}; details, heat maps and the depth-rule variants in [SURFACE-TRUTH.md](SURFACE-TRUTH.md)): the head's light summed over its own surface in float64 at ${surfaceTruth.view.width}×${surfaceTruth.view.height}; error ‖setting − truth‖ / ‖no scattering − truth‖ (0: the truth, 1: no better than no scattering).`,
      '', surfaceTruthSummary(surfaceTruth), '');
  }
  return parts.join('\n');
}

/** The heading bench/webgpu/run.js finds its section by in docs/BENCH.md. */
export const WEBGPU_HEADING = '## The WebGPURenderer node';

/**
 * The WebGPURenderer node beside the composer path (bench/webgpu/run.js's results): each frame's
 * median and each subsurface frame over the same renderer's plain frame, from the same rounds.
 * @param {object|null} webgpu bench/results/webgpu.json
 */
export function webgpuSection(webgpu) {
  if (!webgpu?.medianMs) return '';
  const m = webgpu.medianMs;
  // [label, median, the same renderer's plain frame (null: a plain frame itself)]; rows a run left out are left out.
  const rows = [
    ['three.js `WebGLRenderer` + `EffectComposer`, plain (`RenderPass`, `OutputPass`)', m.composerPlain, null],
    ['the same, the pipeline (`SubsurfaceScattering`) in place of `RenderPass`', m.composer, m.composerPlain],
    ['`WebGPURenderer` on WebGPU, plain (`pass(scene, camera)` alone)', m.webgpuPlain, null],
    ['`WebGPURenderer` on WebGPU, the node (`subsurfaceScattering(scenePass)`)', m.webgpuNode, m.webgpuPlain],
    ['`WebGPURenderer` on its WebGL 2 backend (`forceWebGL`), plain', m.webglPlain, null],
    ['`WebGPURenderer` on its WebGL 2 backend, the node', m.webglNode, m.webglPlain],
    ['WebGPU, plain, the camera turned to the head\'s side (nothing subsurface on the screen)', m.webgpuPlainAway, null],
    ['WebGPU, the node, the same view', m.webgpuNodeAway, m.webgpuPlainAway],
    ['WebGL 2 backend, plain, the same view', m.webglPlainAway, null],
    ['WebGL 2 backend, the node, the same view', m.webglNodeAway, m.webglPlainAway],
    // With a base (run.js --base): its library's subsurface frames in the same rounds, over the same plain frames.
    ['before: the pipeline', m.composerBase, m.composerPlain],
    ['before: the node on WebGPU', m.webgpuNodeBase, m.webgpuPlain],
    ['before: the node on the WebGL 2 backend', m.webglNodeBase, m.webglPlain],
    ['before: the node on WebGPU, the camera turned', m.webgpuNodeAwayBase, m.webgpuPlainAway],
    ['before: the node on the WebGL 2 backend, the camera turned', m.webglNodeAwayBase, m.webglPlainAway],
  ].filter(([, t, plain]) => t !== undefined && plain !== undefined);
  // The isotropic blur (kernelGroups 'auto') on each path, against the same path with one kernel.
  const isotropic = m.composerIsotropic === undefined ? [] : [
    ['the pipeline with `kernelGroups: \'auto\'`', m.composerIsotropic, m.composerIsotropic / m.composer],
    ['the node on WebGPU with `kernelGroups: \'auto\'`', m.webgpuNodeIsotropic, m.webgpuNodeIsotropic / m.webgpuNode],
    ['the node on the WebGL 2 backend with `kernelGroups: \'auto\'`', m.webglNodeIsotropic, m.webglNodeIsotropic / m.webglNode],
  ];
  return [`${WEBGPU_HEADING} (\`npm run bench:webgpu\`, ${webgpu.date.slice(0, 10)})`, '',
    `The head at ${webgpu.width}×${webgpu.height} with the module's defaults, each frame closed by a read-back, in ${webgpu.rounds} interleaved rounds of ${webgpu.frames} frames (bench/webgpu/page.js), on SwiftShader (WebGPU on its Vulkan, WebGL 2 on ANGLE): wall times of software rendering, to compare as ratios within the run only.${webgpu.baseName ? ` After: ${webgpu.commit}; before: ${webgpu.baseName}, its library beside this one's in the same rounds.` : ''}`, '',
    '| frame | median ms | over the same renderer\'s plain frame |', '|---|---|---|',
    ...rows.map(([name, t, plain]) => `| ${name} | ${t.toFixed(0)} | ${plain === null ? '—' : `×${(t / plain).toFixed(2)}`} |`),
    ...(isotropic.length === 0 ? [] : ['', 'The isotropic blur (`kernelGroups: \'auto\'`) in the same rounds, each path against itself with one kernel (the default):', '',
      '| frame | median ms | over the same path with one kernel |', '|---|---|---|',
      ...isotropic.map(([name, t, r]) => `| ${name} | ${t.toFixed(0)} | ×${r.toFixed(2)} |`)])].join('\n');
}

/** The heading bench/lights.js finds its section by in docs/BENCH.md. */
export const LIGHTS_HEADING = '## Transmitting lights and three\'s shadow maps';

/**
 * The frame with 0, 1 and 3 transmitting lights beside three's shadow maps of the same lights
 * (bench/lights.js's results), each row over the frame with no transmitting light, same rounds.
 * @param {object|null} lights bench/results/lights.json
 */
export function lightsSection(lights) {
  if (!lights?.medianMs) return '';
  const m = lights.medianMs;
  const row = (name, label) => `| ${label} | ${lights.lightMaps[name]} | ${m[name].toFixed(0)} | ×${(m[name] / m.ours0).toFixed(2)} |`;
  const perLight = (a, b, n) => ((m[a] - m[b]) / n).toFixed(0);
  return [`${LIGHTS_HEADING} (\`${lights.command}\`, ${lights.date.slice(0, 10)})`, '',
    `The head at ${lights.width}×${lights.height}, lit from behind by three lights (the key spot, the demo's point light behind the ear, a directional rim light; maps and shadow maps 1024²), each frame closed by a read-back, in ${lights.rounds} interleaved rounds of ${lights.frames} frames (bench/lightsPage.js), on SwiftShader: CPU times, to compare as ratios within the run only. Three's shadow maps (\`castShadow\`, the point light's six faces) are the pass that reading the thickness from them would have shared.`, '',
    '| frame | our light maps per frame | median ms | over no transmitting light |', '|---|---|---|---|',
    row('ours0', 'no transmitting light, three\'s shadows off'),
    row('ours1', '1 transmitting light (the spot), our map'),
    row('ours3', '3 transmitting lights, our maps'),
    row('three1', 'no transmittance, three\'s shadow map of the spot'),
    row('three3', 'no transmittance, three\'s shadow maps of the 3 lights'),
    row('both1', 'the spot: three\'s shadow map and our map'),
    row('both3', 'the 3 lights: three\'s shadow maps and our maps'),
    ...(m.hook0 === undefined ? [] : [
      row('hook0', 'no transmitting light, the head moved by a vertex hook of the user\'s'),
      row('hook1', '1 transmitting light (the spot), the hooked head: its own depth material runs the hook'),
    ]), '',
    `Per light, over these three: our map adds ${perLight('ours3', 'ours0', 3)} ms, three's shadow maps ${perLight('three3', 'ours0', 3)} ms; with three's shadows on, our maps add ×${(m.both3 / m.three3).toFixed(2)} to the frame (3 lights), ×${(m.both1 / m.three1).toFixed(2)} (the spot).${m.hook0 === undefined ? ''
      : ` The light's pass with the user's vertex hook (the head drawn from the light with its hook, in a depth material of its own) adds ${(m.hook1 - m.hook0).toFixed(0)} ms to the frame, against ${(m.ours1 - m.ours0).toFixed(0)} ms without the hook (×${((m.hook1 - m.hook0) / (m.ours1 - m.ours0)).toFixed(2)}).`}`].join('\n');
}

export const SCENE_GRAPH_HEADING = '## What is on the screen: frames without subsurface pixels, and a large scene';

/**
 * The pipeline's frame against three's plain frame (bench/sceneGraph.js's results): nothing
 * subsurface on the screen, the head in view, the head among 2,000 ordinary meshes; before and
 * after where the file has both.
 * @param {object|null} graph bench/results/scene-graph.json
 */
export function sceneGraphSection(graph) {
  const runs = ['before', 'after'].filter((label) => graph?.[label]?.medianMs);
  if (runs.length === 0) return '';
  const last = graph[runs[runs.length - 1]];
  const cells = (run, scene) => {
    const ours = `${scene}Ours`;
    const plain = `${scene}Plain`;
    return `${run.medianMs[ours].toFixed(1)} / ${run.medianMs[plain].toFixed(1)} (×${(run.medianMs[ours] / run.medianMs[plain]).toFixed(2)}) | ${run.medianJsMs[ours].toFixed(2)} / ${run.medianJsMs[plain].toFixed(2)} (×${(run.medianJsMs[ours] / run.medianJsMs[plain]).toFixed(2)}) | ${run.drawCalls[ours]} / ${run.drawCalls[plain]}`;
  };
  const scenes = [
    ['offScreen', 'the head among 2,000 ordinary meshes, off the screen (the camera turned to its side), its light behind it'],
    ['inView', 'the head at the first view, the same light'],
    ['crowd', 'the head in view among 2,000 ordinary meshes, one transmitting light'],
  ];
  return [`${SCENE_GRAPH_HEADING} (\`${graph.command}\`, ${last.date.slice(0, 10)})`, '',
    `The pipeline's frame (ours) against three's RenderPass frame (plain) of the same scene at ${last.width}×${last.height}, one renderer each, in ${last.rounds} interleaved rounds of ${last.frames} frames (bench/sceneGraphPage.js), on SwiftShader: CPU times, to compare as ratios within a run only. Frame ms: wall time closed by a 1-pixel read-back; JS ms: the time \`composer.render()\` takes to return; draw calls: three's \`renderer.info\`.${runs.length > 1 ? ` Before: ${graph.before.commit}; after: ${graph.after.commit}, each its own run.` : ''}`, '',
    `| scene | run | frame ms ours / plain | JS ms ours / plain | draw calls ours / plain |`, '|---|---|---|---|---|',
    ...scenes.flatMap(([scene, label]) => runs.map((run) => `| ${label} | ${run} | ${cells(graph[run], scene)} |`))].join('\n');
}

/**
 * `markdown` (docs/BENCH.md) with the section under `heading` replaced, or added before the
 * section after the WebGPU node's where it has none yet.
 * @param {string} markdown @param {string} heading @param {string} section
 */
export function withBenchSection(markdown, heading, section) {
  const start = markdown.indexOf(heading);
  const from = start >= 0 ? start : markdown.indexOf('\n## ', markdown.indexOf('## The WebGPURenderer node')) + 1;
  const next = markdown.indexOf('\n## ', start + 1);
  const end = start < 0 ? from : next < 0 ? markdown.length : next + 1;
  return `${markdown.slice(0, from)}${section}\n\n${markdown.slice(end)}`;
}

export const WARM_UP_HEADING = '## The first frame: warmed up or not';

/**
 * The first frame against a steady one on a fresh browser (bench/warmUp.js's results): after the
 * pipeline's compileAsync, after three's renderer.compileAsync alone, and without a warm-up.
 * @param {object|null} warmUp bench/results/warm-up.json
 */
export function warmUpSection(warmUp) {
  if (!warmUp?.summary) return '';
  const names = (list) => (list.length ? ` (${list.map((name) => name || 'unnamed').join(', ')})` : '');
  const row = (name, label) => {
    const r = warmUp.summary[name];
    return `| ${label} | ${r.warmUpMs.toFixed(0)} | ${r.programsWarmed} | ${r.programsFirstFrame}${names(r.firstPrograms)} | ${r.firstMs.toFixed(0)} | ${r.secondMs.toFixed(0)} | ${r.steadyMs.toFixed(0)} | ×${r.firstOverSteady.toFixed(2)} |`;
  };
  return [`${WARM_UP_HEADING} (\`${warmUp.command}\`, ${warmUp.date.slice(0, 10)})`, '',
    `The head at ${warmUp.width}×${warmUp.height} with the defaults and its transmitting light (its depth pass drawn; the light casts three's shadow), on a fresh browser each time (no program compiled, no shader cache), in ${warmUp.rounds} interleaved rounds (bench/warmUpPage.js); the first frame, the second, and the median of ${warmUp.frames} steady frames, each closed by a read-back, on SwiftShader (KHR_parallel_shader_compile ${warmUp.parallelCompile ? 'present' : 'absent'}): CPU times, to compare as ratios within the run. Medians over the rounds; the programs of the first round, by material name (unnamed: the head's material or three's shadow map depth material; what the warm-up leaves is the latter, by elimination: a subsurface material's is warmed, as test/browser/programs.test.js checks, and three draws its shadow maps inside render(), out of any compileAsync's reach).`, '',
    '| warm-up | its ms | programs it compiled | programs the first frame compiled | first frame ms | second | steady | first over steady |', '|---|---|---|---|---|---|---|---|',
    row('pipeline', '`await sss.compileAsync(renderer, composer.readBuffer)`'),
    row('uploads', 'the same, then the textures uploaded (`renderer.initTexture`)'),
    row('three', '`await renderer.compileAsync(scene, camera)` (three\'s alone)'),
    row('none', 'none'),
  ].join('\n');
}

export const MEMORY_HEADING = '## Memory: what the pipeline allocates';

/**
 * The bytes the pipeline allocates per setting (bench/memoryRun.js's results), counted from the
 * storage calls of its targets: per pixel, the light maps, the tables.
 * @param {object|null} memory bench/results/memory.json
 */
export function memorySection(memory) {
  if (!memory?.results) return '';
  const [first] = memory.results;
  const mib = (bytes) => (bytes / 2 ** 20).toFixed(1);
  const rows = memory.results.map((r) => `| ${r.label} | ${r.bytesPerPixel.toFixed(0)} | ${mib(r.bytesPerPixel * r.width * r.height)} | ${mib(r.lightMapBytes)} | ${(r.tableBytes / 2 ** 10).toFixed(0)} |`);
  return [`${MEMORY_HEADING} (\`${memory.command}\`, ${memory.date.slice(0, 10)})`, '',
    `The head at ${first.width}×${first.height}, the pipeline in place of a RenderPass in one composer (half-float buffers; MSAA as the row says, \`multisampling: 'auto'\` following it): what its frames add to what the plain frame allocated, counted from the sizes of the texture and renderbuffer storage calls (dev/glAllocations.js; a multisampled buffer counts each sample). Per pixel: the targets of the frame's size; light maps: lightDepthSize² each (RG float and its depth, 12 B a texel; the point light behind the ear six faces, 3 × 2 of them); tables: the profiles', footprints' and kernels'. Not counted: the composer's own two buffers and three's (${first.plainBytesPerPixel.toFixed(0)} B per pixel without MSAA). \`scattering\` false releases the blur's targets (before this release they stayed allocated: the defaults' bytes).`, '',
    '| setting | bytes per pixel | MiB at this size | light maps, MiB | tables, KiB |', '|---|---|---|---|---|',
    ...rows,
  ].join('\n');
}

/**
 * @param {object} json bench/results/<name>.json
 * @param {{ transfer?: object, surfaceTruth?: object, webgpu?: object, lights?: object, sceneGraph?: object, warmUp?: object, memory?: object }} [beyond] the other runs' results (see beyondDenseSection, webgpuSection, lightsSection, sceneGraphSection, warmUpSection, memorySection)
 */
export function benchMarkdown(json, beyond = {}) {
  const { results } = json;
  const main = rowsOf(results, MAIN.scene, MAIN.resolution);
  const skin = main.filter((r) => r.profile === 'skin');
  const def = main.find(isDefaultSetting);
  const ref17 = find(main, 'reference', 17);
  const marginal17 = find(main, 'marginal', 17);
  const fronts = frontsByProfile(main);
  const device = deviceName(json.webgl);
  const standIn = json.references.some((r) => r.isStandIn) ? ' **(the head scan was missing: these are the stand-in bust\'s numbers)**' : '';
  const key = [
    ...[11, 17, 25].map((n) => find(skin, 'reference', n)),
    ...[5, 9, 17, 25].map((n) => find(skin, 'marginal', n)),
    ...[5, 9, 17, 25].map((n) => find(skin, 'footprint', n)),
    skin.find((r) => r.auto),
    ...skin.filter((r) => r.kind === 'dense' && r.coverage < 0.997),
  ].filter(Boolean);
  const time = robustTime(skin.filter((r) => r.kind === 'separable'));
  const [autoHere] = autoAgainstFixed(main, time);
  const autoCost = autoHere?.cheapest
    ? ` It used ${def.taps ? `${def.taps.mean.toFixed(1)} taps per pixel and direction on average (up to ${def.taps.max})` : 'its per-pixel taps'}: ×${ratio(def[time], autoHere.cheapest[time])} the ${clockName(time)} of the cheapest fixed budget at its error (${autoHere.cheapest.samples} taps); the scene needs ${autoHere.needed.samples} fixed taps.`
    : '';
  const sentence = def && ref17
    ? `On the head at 1280×720${standIn}, the default setting (footprint kernel, skin profile, samples 'auto') is within **${pct(def.rmse)}** relative RMSE of the dense 2D reference (maximum error ${def.maxError.toFixed(3)}, PSNR ${def.psnr.toFixed(1)} dB, SSIM ${def.ssim.toFixed(4)}); the reference kernel (Jimenez 2012) at 17 taps is at **${pct(ref17.rmse)}** (maximum error ${ref17.maxError.toFixed(3)}, PSNR ${ref17.psnr.toFixed(1)} dB, SSIM ${ref17.ssim.toFixed(4)})${marginal17 ? ` and the marginal kernel at ${pct(marginal17.rmse)}` : ''}. Their SSS passes took ${ms(def.gpuMs)}, ${ms(ref17.gpuMs)}${marginal17 ? ` and ${ms(marginal17.gpuMs)}` : ''} on ${device}.${autoCost}`
    : 'The default or the reference kernel at 17 taps was not measured.';
  const gpuNote = /SwiftShader/.test(device)
    ? `**No GPU**: no GPU machine was available for this run, so there are no 1920×1080 GPU timings (the aim there: both SSS passes ≤ 0.15 ms); \`npm run bench -- --gpu\` measures them where a GPU is. These results are SwiftShader's (software WebGL 2 on ${json.machine.cores} CPU cores), so every time is a CPU time; compare them only as ratios within this run.`
    : `Device: ${device}.`;
  const defaultNote = "The bench's default is the module's own (`PIPELINE_DEFAULTS`): the footprint kernel with `samples: 'auto'`, skin; every side-by-side frame of ours and every row marked \"(default)\" is that setting.";
  return `# Speed and accuracy

<!-- Written by \`${json.command}\` (bench/run.js) from bench/results/${json.name}.json on ${json.createdAt.slice(0, 10)}: regenerate, do not edit. -->

## Speed and accuracy

<!-- README: the image is docs/speed-accuracy.png from the repository root. -->
![Error against SSS time, log scales: every method and tap count on the head at 1280×720, Pareto front dashed, the default ringed](speed-accuracy.png)

${gpuNote}

${defaultNote}

${sentence}

${paretoParagraph(skin, def)}

${fronts.map(({ profile, rows }) => `Pareto front of the ${profile} settings, fastest first: ${rows.map((r) => `${settingName(r)} (${ms(r.gpuMs)}, ${pct(r.rmse)})`).join(' → ')}.`).join('\n\n')}

${table(key)}

Error: against the dense 2D reference (\`DenseSubsurfacePass\`: brute-force 2D convolution with the full radial profile, exact pixel energies, 99.7 % of the energy) of the same profile, over subsurface pixels, linear radiance; SSIM on the tone-mapped 8-bit output. Time: median of timer queries around the SSS passes only (${device}${/SwiftShader/.test(device) ? ': CPU times, compare them as ratios' : ''}); frame: a whole composer frame with a read-back fence. Reproduce with \`npm run bench\` (about ${Math.ceil(json.durationS / 60)} minutes here; \`npm run bench -- --quick\` in under 2).

${beyondDenseSection(beyond)}

${peersSection(json)}

${webgpuSection(beyond.webgpu)}

${lightsSection(beyond.lights)}

${sceneGraphSection(beyond.sceneGraph)}

${warmUpSection(beyond.warmUp)}

${memorySection(beyond.memory)}

${issueTableSection(json)}

${costModelSection(json)}

${featuresSection(json)}

${autoSection(results, json.module)}

## All settings on the head at 1280×720

${table(main)}

${scalingSection(results)}

${syntheticSection(results)}

## How it was measured

- ${json.timing.gpuMs}.
- ${json.timing.ms}.
- ${json.timing.dense}.
- ${json.timing.peers}.
${json.timing.swiftShader ? `- ${json.timing.swiftShader}.\n` : ''}- Errors: ${json.errors}.
- Machine: ${json.machine.cpu}, ${json.machine.cores} cores, ${json.machine.memoryGiB} GiB, ${json.machine.platform}/${json.machine.arch}, Node ${json.machine.node}; ${json.browser.chromium}; WebGL: ${json.webgl.renderer}. The full run took ${json.durationS} s.
`;
}
