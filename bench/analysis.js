// What the bench concludes from its rows (Node side): the Pareto front of error against time, the
// scaling ratios, and docs/BENCH.md's text. Rows are bench/results/*.json's `results` entries.

import { median } from '../dev/gpuTimer.js';

export { median };

/**
 * The module's default setting (src/options.js's PIPELINE_DEFAULTS): the footprint kernel with
 * samples 'auto' (per pixel, the fewest taps within AUTO_STEP_ERROR for its scale), skin.
 */
export const DEFAULT_SETTING = Object.freeze({ method: 'footprint', profile: 'skin', samples: 'auto' });

export const isDefaultSetting = (row) => row.kind === 'separable' && row.auto === true
  && row.method === DEFAULT_SETTING.method && row.profile === DEFAULT_SETTING.profile;

/** True when `a` is at least as fast and as accurate as `b` and strictly better in one. */
export function dominates(a, b, x = 'gpuMs', y = 'rmse') {
  return a[x] <= b[x] && a[y] <= b[y] && (a[x] < b[x] || a[y] < b[y]);
}

/**
 * The rows no other row dominates, fastest first. Rows without a finite positive error (the
 * reference itself) or time take no part.
 */
export function paretoFront(rows, x = 'gpuMs', y = 'rmse') {
  const candidates = rows.filter((r) => r[x] > 0 && r[y] > 0 && Number.isFinite(r[x]) && Number.isFinite(r[y]));
  return candidates.filter((r) => !candidates.some((o) => dominates(o, r, x, y))).sort((a, b) => a[x] - b[x]);
}

/** The name a row goes by in tables and on the chart. */
export function settingName(row) {
  if (row.kind === 'dense') return `dense 2D, ${(row.coverage * 100).toFixed(1)} % radius`;
  const what = row.auto
    ? `${row.method}, auto (${row.taps ? `${row.taps.mean.toFixed(1)} taps per pixel, up to ${row.taps.max}` : `${row.samples} taps`})`
    : `${row.method}, ${row.samples} taps`;
  return row.profile === 'skin' ? what : `${what}, ${row.profile}`;
}

const fixed = (v, digits) => (v === null || v === undefined || !Number.isFinite(v) ? '—' : v.toFixed(digits));
/** A fraction as a percentage with 3 significant digits (errors differ in the third). */
export const percent = (v) => (v === null || v === undefined || !Number.isFinite(v) ? '—' : `${(v * 100).toPrecision(3)} %`);
const psnrText = (v) => (v === null ? '∞ (reference)' : fixed(v, 1));

/** A markdown table of rows. */
export function table(rows, { frame = true } = {}) {
  const head = ['setting', 'SSS ms', 'SSS CPU ms', ...(frame ? ['frame ms'] : []), 'rel. RMSE', 'max error', 'PSNR dB', 'SSIM', 'timer frames'];
  const lines = [`| ${head.join(' | ')} |`, `|${head.map(() => '---').join('|')}|`];
  for (const r of rows) {
    const name = isDefaultSetting(r) ? `**${settingName(r)} (default)**` : settingName(r);
    const cells = [name, fixed(r.gpuMs, 0), fixed(r.sssCpuMs, 0), ...(frame ? [fixed(r.ms, 0)] : []), percent(r.rmse), fixed(r.maxError, 4), psnrText(r.psnr), fixed(r.ssim, 4), String(r.timerQueries)];
    lines.push(`| ${cells.join(' | ')} |`);
  }
  return lines.join('\n');
}

/** Rows of one scene and resolution. */
export const rowsOf = (results, scene, resolution) => results.filter((r) => r.scene === scene && r.resolution === resolution);

/** A ratio as text: 'a / b = 2.31'. */
export const ratio = (a, b) => (a > 0 && b > 0 ? (a / b).toFixed(2) : '—');

/** Median, smallest and largest of a list (the spread over rounds). */
export function spread(values) {
  const finiteValues = values.filter(Number.isFinite);
  return { median: median(finiteValues), min: Math.min(...finiteValues), max: Math.max(...finiteValues), n: finiteValues.length };
}

/** The stages besides the blur that a frame of ours adds over a plain three.js frame. */
const NON_BLUR_STAGES = ['lightDepth', 'scene', 'compose', 'transparent'];

/**
 * What the side-by-side's rounds (bench/peerRun.js) conclude, per round then over the rounds:
 * - overhead: ours − threePlain and babylonSss − babylonPlain, and their ratio (the issue's goal:
 *   ≤ 0.5), from timer queries and from the GPU process's CPU time;
 * - blurOverFloor: the two blur passes over the fetch-only floor's two (goal: ≤ 1.5);
 * - nonBlurShare: (light depth + scene split + compose + transparent − the plain frame) over the
 *   plain frame (goal: ≤ 0.3), from the stage timer (a stage that did not run counts 0);
 * - stages: each stage's median over the rounds, ms.
 * @param {object[]} rounds
 */
export function peerSummary(rounds) {
  const per = (f) => spread(rounds.map(f));
  const timed = rounds.every((r) => Number.isFinite(r.ours.cpuMs)); // the CPU clock was read
  const clock = (key) => ({
    ours: per((r) => r.ours[key] - r.threePlain[key]),
    babylon: per((r) => r.babylonSss[key] - r.babylonPlain[key]),
    ratio: per((r) => (r.ours[key] - r.threePlain[key]) / (r.babylonSss[key] - r.babylonPlain[key])),
  });
  const stageMs = (r, stage) => (Number.isFinite(r.stages[stage]) ? r.stages[stage] : 0);
  const stages = Object.fromEntries(Object.keys(rounds[0]?.stages ?? {}).map((stage) => [stage, median(rounds.map((r) => stageMs(r, stage)))]));
  return {
    rounds: rounds.length,
    frames: Object.fromEntries(['threePlain', 'ours', 'babylonPlain', 'babylonSss', 'blur', 'floor'].map((m) => [m, { timerMs: per((r) => r[m].timerMs), cpuMs: timed ? per((r) => r[m].cpuMs) : null }])),
    overhead: { timer: clock('timerMs'), cpu: timed ? clock('cpuMs') : null },
    blurOverFloor: { timer: per((r) => r.blur.timerMs / r.floor.timerMs), cpu: timed ? per((r) => r.blur.cpuMs / r.floor.cpuMs) : null },
    nonBlurShare: per((r) => (NON_BLUR_STAGES.reduce((sum, stage) => sum + stageMs(r, stage), 0) - r.threePlain.timerMs) / r.threePlain.timerMs),
    stages,
  };
}

/** Errors within this fraction of each other count as the same (the fixed budget 'auto' is held against). */
export const SAME_ERROR = 0.01;

/** Relative error above the best of a sweep that still counts as "no better with more taps". */
export const SATURATION = 0.02;

/**
 * samples 'auto' against the fixed footprint budgets of each scene and resolution (skin): the
 * cheapest fixed budget whose error is within SAME_ERROR of auto's or below (the goal: auto within
 * 1.2 × its time), and the budget the scene needs (the fewest taps within SATURATION of the best
 * error measured there: auto should use no more per pixel).
 * @param {object[]} results the results file's rows
 * @param {'gpuMs'|'sssCpuMs'} [time='gpuMs'] which time: timer queries, or the GPU process's CPU time
 * @returns {Array<{ scene: string, resolution: string, auto: object, fixed: object[], cheapest: object|null, timeRatio: number, needed: object }>}
 */
export function autoAgainstFixed(results, time = 'gpuMs') {
  const groups = new Map();
  for (const r of results) {
    if (r.kind !== 'separable' || r.method !== 'footprint' || r.profile !== 'skin') continue;
    const key = `${r.scene} ${r.resolution}`;
    if (!groups.has(key)) groups.set(key, []);
    groups.get(key).push(r);
  }
  const out = [];
  for (const rows of groups.values()) {
    const auto = rows.find((r) => r.auto === true);
    const fixed = rows.filter((r) => r.auto !== true).sort((a, b) => a.samples - b.samples);
    if (!auto || fixed.length === 0) continue;
    const reaching = fixed.filter((r) => r.rmse <= auto.rmse * (1 + SAME_ERROR));
    const cheapest = reaching.length > 0 ? reaching.reduce((a, b) => (b[time] < a[time] ? b : a)) : null;
    const best = Math.min(...rows.map((r) => r.rmse));
    const needed = fixed.find((r) => r.rmse <= best * (1 + SATURATION)) ?? fixed[fixed.length - 1];
    out.push({ scene: auto.scene, resolution: auto.resolution, auto, fixed, cheapest, timeRatio: cheapest ? auto[time] / cheapest[time] : NaN, needed });
  }
  return out;
}

/** A short name for the renderer string ('SwiftShader' or the GPU's). */
export function deviceName(webgl) {
  if (/swiftshader/i.test(webgl.renderer)) return 'SwiftShader (CPU)';
  return webgl.renderer.replace(/^ANGLE \(([^,]+), ([^,]+).*$/, '$2');
}
