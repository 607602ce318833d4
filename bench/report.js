// Turns the bench's JSON into the chart's data and docs/BENCH.md (whose first section is meant to
// be pasted into the README). Every number comes from the results; nothing is typed in by hand.
import {
  dominates, isDefaultSetting, paretoFront, percent as pct, ratio, rowsOf, settingName, table,
} from './analysis.js';

const MAIN = { scene: 'head', resolution: '1280x720' };

/** The series a row belongs to on the chart. */
function seriesOf(row) {
  const method = row.kind === 'dense' ? 'dense' : row.auto ? 'auto' : row.method;
  return `${method} ${row.profile}`;
}

function pointLabel(row) {
  if (row.kind === 'dense') return `${(row.coverage * 100).toFixed(1)} %`;
  return row.auto ? `auto→${row.samples}` : String(row.samples);
}

/** A short name for the renderer string ('SwiftShader' or the GPU's). */
export function deviceName(webgl) {
  if (/swiftshader/i.test(webgl.renderer)) return 'SwiftShader (CPU)';
  return webgl.renderer.replace(/^ANGLE \(([^,]+), ([^,]+).*$/, '$2');
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
    highlight: main ? { ...toPoint(main), label: 'default: footprint, skin, 17 taps' } : { x: NaN, y: NaN, label: 'default: not measured' },
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

function scalingSection(results) {
  const lines = ['## Scaling (ratios within this run)', ''];
  // Resolution.
  const resolutions = ['640x360', '1280x720', '1920x1080'];
  const settings = ['footprint', 'reference'];
  const at = (resolution, method) => find(rowsOf(results, 'head', resolution), method, 17);
  lines.push('**Resolution** (head, 17 taps; SSS time relative to 1280×720; the pixel count ratios are 0.25, 1, 2.25):', '');
  lines.push('| setting | 640×360 | 1280×720 | 1920×1080 |', '|---|---|---|---|');
  for (const method of settings) {
    const base = at('1280x720', method);
    const cells = resolutions.map((res) => {
      const r = at(res, method);
      return r && base ? `${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)})` : '—';
    });
    lines.push(`| ${method}, 17 taps${method === 'footprint' ? ' (default)' : ''} | ${cells.join(' | ')} |`);
  }
  // Objects.
  lines.push('', '**Objects at equal screen coverage** (1280×720, 1, 4 and 16 heads in a grid, each scaled to 1/√n; same on-screen kernel):', '');
  lines.push('| setting | 1 head | 4 heads | 16 heads |', '|---|---|---|---|');
  for (const method of settings) {
    const rows = ['head', 'heads4', 'heads16'].map((scene) => find(rowsOf(results, scene, '1280x720'), method, 17));
    const base = rows[0];
    const cells = rows.map((r) => (r && base ? `SSS ${ms(r.gpuMs)} (×${ratio(r.gpuMs, base.gpuMs)}), frame ${ms(r.ms)}` : '—'));
    lines.push(`| ${method}, 17 taps | ${cells.join(' | ')} |`);
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

/** Relative error above the best of a sweep that still counts as "no better with more taps". */
const SATURATION = 0.02;

/**
 * Where the footprint kernel's error stops falling with more taps, per scene and resolution
 * (skin), against the module's on-screen radius estimate, and what 'auto' chose there.
 */
function footprintSweeps(results) {
  const groups = new Map();
  for (const r of results) {
    if (r.kind !== 'separable' || r.method !== 'footprint' || r.profile !== 'skin') continue;
    const key = `${r.scene} ${r.resolution}`;
    if (!groups.has(key)) groups.set(key, []);
    groups.get(key).push(r);
  }
  const sweeps = [];
  for (const rows of groups.values()) {
    const fixedRows = rows.filter((r) => !r.auto).sort((a, b) => a.samples - b.samples);
    if (fixedRows.length < 2) continue;
    const best = Math.min(...rows.map((r) => r.rmse));
    const saturated = fixedRows.find((r) => r.rmse <= best * (1 + SATURATION));
    sweeps.push({ scene: rows[0].scene, resolution: rows[0].resolution, rows: fixedRows, auto: rows.find((r) => r.auto), saturated, radiusPx: rows[0].kernelPixels });
  }
  return sweeps;
}

function autoSection(results, moduleInfo) {
  const sweeps = footprintSweeps(results);
  if (sweeps.length === 0) return '';
  const lines = [
    '## Footprint taps and auto quality',
    '',
    `Footprint kernel, skin: relative RMSE by taps. "saturates at" is the fewest taps within ${SATURATION * 100} % of the best error measured there; ` +
      '"radius" is the module\'s own estimate of the on-screen radius holding 99 % of the marginal (`kernelPixels`, at the nearest bounding-box corner), ' +
      `from which \`samples: 'auto'\` takes the fewest AUTO_SAMPLES with (taps − 3) / 2 ≥ ${moduleInfo?.autoReach ?? 1} × radius.`,
    '',
    '| scene | resolution | radius, px | rel. RMSE by taps | saturates at | auto chose |',
    '|---|---|---|---|---|---|',
  ];
  for (const w of sweeps) {
    const errors = w.rows.map((r) => `${r.samples}: ${pct(r.rmse)}`).join(', ');
    const auto = w.auto ? `${w.auto.samples} (${pct(w.auto.rmse)}, ${ms(w.auto.gpuMs)} vs ${ms(w.saturated.gpuMs)})` : '—';
    lines.push(`| ${w.scene} | ${w.resolution} | ${w.radiusPx.toFixed(1)} | ${errors} | ${w.saturated.samples} | ${auto} |`);
  }
  // Footprints per side at saturation over the estimated radius, where the estimate is a pixel's
  // (a large plane's nearest corner is not: its ratio says nothing).
  const ratios = sweeps.filter((w) => w.radiusPx < 50).map((w) => ({ w, k: (w.saturated.samples - 3) / 2 / w.radiusPx }));
  const levels = moduleInfo?.autoSamples;
  if (ratios.length > 0 && levels) {
    const k = Math.max(...ratios.map((x) => x.k));
    const choose = (radiusPx) => levels.find((n) => (n - 3) / 2 >= k * radiusPx) ?? levels[levels.length - 1];
    const changed = sweeps.filter((w) => w.auto && w.radiusPx < 50 && choose(w.radiusPx) !== w.auto.samples);
    lines.push('', `Measured: the error stops falling once (taps − 3) / 2 reaches ${ratios.map((x) => `${x.k.toFixed(2)}×`).join(', ')} the estimated radius ` +
      `(${ratios.map((x) => `${x.w.scene} ${x.w.resolution}`).join(', ')}; the sweeps are only as fine as the tap counts measured). ` +
      `With the levels ${levels.join(', ')}, the module's ${moduleInfo.autoReach ?? 1}× rule (AUTO_REACH) takes the next level up whenever the radius lies just past one. ` +
      (changed.length > 0
        ? `**Recommendation**: ask for (taps − 3) / 2 ≥ ${k.toFixed(2)} × radius (the largest ratio measured); auto would then pick ${changed.map((w) => `${choose(w.radiusPx)} instead of ${w.auto.samples} on ${w.scene} ${w.resolution} (${ms(w.saturated.gpuMs)} instead of ${ms(w.auto.gpuMs)}, error ${pct(w.saturated.rmse)} instead of ${pct(w.auto.rmse)})`).join('; ')}.`
        : `Asking for ${k.toFixed(2)}× (the largest ratio measured) would not change its choices here.`) +
      ' On surfaces reaching close to the camera (the grazing plane) the nearest-corner estimate is far above any pixel\'s radius: a percentile of the visible pixels\' scale would serve better.');
  }
  return lines.join('\n');
}

/**
 * docs/BENCH.md from the bench's JSON.
 * @param {object} json the results file's content
 * @returns {string}
 */
export function benchMarkdown(json) {
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
  const sentence = def && ref17
    ? `On the head at 1280×720${standIn}, the default setting (footprint kernel, skin profile, 17 taps) is within **${pct(def.rmse)}** relative RMSE of the dense 2D reference (maximum error ${def.maxError.toFixed(3)}, PSNR ${def.psnr.toFixed(1)} dB, SSIM ${def.ssim.toFixed(4)}); the reference kernel (Jimenez 2012) at the same 17 taps is at **${pct(ref17.rmse)}** (maximum error ${ref17.maxError.toFixed(3)}, PSNR ${ref17.psnr.toFixed(1)} dB, SSIM ${ref17.ssim.toFixed(4)})${marginal17 ? ` and the marginal kernel at ${pct(marginal17.rmse)}` : ''}. Their SSS passes took ${ms(def.gpuMs)}, ${ms(ref17.gpuMs)}${marginal17 ? ` and ${ms(marginal17.gpuMs)}` : ''} on ${device}.`
    : 'The default or the reference kernel at 17 taps was not measured.';
  return `# Speed and accuracy

<!-- Written by \`${json.command}\` (bench/run.js) from bench/results/${json.name}.json on ${json.createdAt.slice(0, 10)}: regenerate, do not edit. -->

## Speed and accuracy

<!-- README: the image is docs/speed-accuracy.png from the repository root. -->
![Error against SSS time, log scales: every method and tap count on the head at 1280×720, Pareto front dashed, the default ringed](speed-accuracy.png)

${sentence}

${paretoParagraph(skin, def)}

${fronts.map(({ profile, rows }) => `Pareto front of the ${profile} settings, fastest first: ${rows.map((r) => `${settingName(r)} (${ms(r.gpuMs)}, ${pct(r.rmse)})`).join(' → ')}.`).join('\n\n')}

${table(key)}

Error: against the dense 2D reference (\`DenseSubsurfacePass\`: brute-force 2D convolution with the full radial profile, exact pixel energies, 99.7 % of the energy) of the same profile, over subsurface pixels, linear radiance; SSIM on the tone-mapped 8-bit output. Time: median of timer queries around the SSS passes only (${device}${/SwiftShader/.test(device) ? ': CPU times, compare them as ratios' : ''}); frame: a whole composer frame with a read-back fence. Reproduce with \`npm run bench\` (about ${Math.ceil(json.durationS / 60)} minutes here; \`npm run bench -- --quick\` in under 2).

## All settings on the head at 1280×720

${table(main)}

${scalingSection(results)}

${syntheticSection(results)}
${autoSection(results, json.module)}

## How it was measured

- ${json.timing.gpuMs}.
- ${json.timing.ms}.
- ${json.timing.dense}.
${json.timing.swiftShader ? `- ${json.timing.swiftShader}.\n` : ''}- Errors: ${json.errors}.
- Machine: ${json.machine.cpu}, ${json.machine.cores} cores, ${json.machine.memoryGiB} GiB, ${json.machine.platform}/${json.machine.arch}, Node ${json.machine.node}; ${json.browser.chromium}; WebGL: ${json.webgl.renderer}. The full run took ${json.durationS} s.
`;
}
