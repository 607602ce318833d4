// What the bench concludes from its rows (Node side): the Pareto front of error against time, the
// scaling ratios, and docs/BENCH.md's text. Rows are bench/results/*.json's `results` entries.

export { median } from '../dev/gpuTimer.js';

/** The module's default setting (src/SubsurfaceScattering.js): footprint kernel, skin, 17 taps. */
export const DEFAULT_SETTING = Object.freeze({ method: 'footprint', profile: 'skin', samples: 17 });

export const isDefaultSetting = (row) => row.kind === 'separable' && row.auto !== true
  && row.method === DEFAULT_SETTING.method && row.profile === DEFAULT_SETTING.profile && row.samples === DEFAULT_SETTING.samples;

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
  const what = row.auto ? `auto (footprint, ${row.samples} taps)` : `${row.method}, ${row.samples} taps`;
  return row.profile === 'skin' ? what : `${what}, ${row.profile}`;
}

const fixed = (v, digits) => (v === null || v === undefined || !Number.isFinite(v) ? '—' : v.toFixed(digits));
/** A fraction as a percentage with 3 significant digits (errors differ in the third). */
export const percent = (v) => (v === null || v === undefined || !Number.isFinite(v) ? '—' : `${(v * 100).toPrecision(3)} %`);
const psnrText = (v) => (v === null ? '∞ (reference)' : fixed(v, 1));

/** A markdown table of rows. */
export function table(rows, { frame = true } = {}) {
  const head = ['setting', 'SSS ms', ...(frame ? ['frame ms'] : []), 'rel. RMSE', 'max error', 'PSNR dB', 'SSIM', 'timer frames'];
  const lines = [`| ${head.join(' | ')} |`, `|${head.map(() => '---').join('|')}|`];
  for (const r of rows) {
    const name = isDefaultSetting(r) ? `**${settingName(r)} (default)**` : settingName(r);
    const cells = [name, fixed(r.gpuMs, 0), ...(frame ? [fixed(r.ms, 0)] : []), percent(r.rmse), fixed(r.maxError, 4), psnrText(r.psnr), fixed(r.ssim, 4), String(r.timerQueries)];
    lines.push(`| ${cells.join(' | ')} |`);
  }
  return lines.join('\n');
}

/** Rows of one scene and resolution. */
export const rowsOf = (results, scene, resolution) => results.filter((r) => r.scene === scene && r.resolution === resolution);

/** A ratio as text: 'a / b = 2.31'. */
export const ratio = (a, b) => (a > 0 && b > 0 ? (a / b).toFixed(2) : '—');
