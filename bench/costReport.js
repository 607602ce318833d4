// docs/BENCH.md's cost sections (bench/report.js puts them in): the four cost ratios,
// version 0.2's next to this run's, and the cost model (bench/costModel.js) with the coverage the
// side-by-side measured on the head.
import { spread } from './analysis.js';
import { AFTER, BEFORE, ISOTROPIC, NOT_BUILT, frameTraffic, targetMemory } from './costModel.js';

const stageSum = (st) => Object.values(st).reduce((sum, v) => sum + (Number.isFinite(v) ? v : 0), 0);
const text = (x, digits = 2) => (x && Number.isFinite(x.median) ? `${x.median.toFixed(digits)} (${x.min.toFixed(digits)}–${x.max.toFixed(digits)})` : '—');
// A round below 0 (ours cheaper than the plain frame it adds to) is the machine's noise, not a
// measurement: such a median is not held against the goal.
export const verdict = (x, goal) => (x && Number.isFinite(x.median) ? (x.min <= 0 ? 'unresolved (a round ≤ 0)' : x.median <= goal ? 'met' : '**not met**') : '');

/**
 * What MSAA 4 adds to ours over what it adds to a plain three.js frame, per round of a features
 * block (ours: the sum of its stages; the plain frame: its timer query), then over the rounds.
 * @param {object[]|undefined} features a peers entry's features rounds
 */
export function msaaRatio(features, clock = 'timerMs') {
  if (!features?.every((r) => r.msaa4 && r.none)) return null;
  const ours = (x) => (clock === 'timerMs' ? stageSum(x.stages) : x.cpuMs);
  if (clock === 'cpuMs' && !features.every((r) => Number.isFinite(r.msaa4.cpuMs) && Number.isFinite(r.none.cpuMs))) return null;
  return spread(features.map((r) => (ours(r.msaa4) - ours(r.none)) / (r.msaa4.threePlain[clock] - r.none.threePlain[clock])));
}

/**
 * The issue's four ratios of one peers entry: { overhead, nonBlur, blurOverFloor, msaa } as spreads
 * (or null), by timer queries and, where the GPU process's CPU clock was read (`cpu`), by CPU time
 * (the stage timer has no CPU counterpart: nonBlur is by timer queries only).
 */
export function issueRatios(entry) {
  if (!entry) return null;
  const { overhead, nonBlurShare, blurOverFloor } = entry.summary;
  return {
    overhead: overhead.timer.ratio, nonBlur: nonBlurShare, blurOverFloor: blurOverFloor.timer, msaa: msaaRatio(entry.features),
    cpu: { overhead: overhead.cpu?.ratio ?? null, blurOverFloor: blurOverFloor.cpu ?? null, msaa: msaaRatio(entry.features, 'cpuMs') },
  };
}

const ROWS = [
  ['overhead', 'our overhead over a plain three.js frame / Babylon.js prepass SSS\'s over a plain Babylon frame', 0.5],
  ['nonBlur', '(our frame − both blur stages − the plain frame) / the plain frame (stage timer)', 0.3],
  ['blurOverFloor', 'both blur stages / the two-pass 17-tap fetch floor on the same pixels', 1.5],
  ['msaa', 'what MSAA 4 adds / what it adds to a plain frame', 2],
];

/** The cost table: each ratio per resolution, version 0.2's run next to this one's. */
export function issueTableSection(json) {
  const before = json.peersVersion02?.peers ?? [];
  const now = json.peers ?? [];
  if (now.length === 0) return '';
  const resolutions = now.map((p) => p.resolution);
  const when = json.peersRun ? `\`${json.peersRun.command}\`, ${json.peersRun.createdAt.slice(0, 10)}` : `\`${json.command}\``;
  const lines = ['## The separable blur as the fast method: its cost against a plain frame', '',
    `Each ratio is taken per round from the stage and frame timers of that round, then the median and range (min–max) over the rounds (timer queries, and after "CPU" the same ratio by the GPU process's CPU time, which other load on the machine swells less; the stage timer has no CPU counterpart). `
    + `SwiftShader's times are CPU times; on a machine shared with other work a timer query also counts the time its process waited, so a round's ratio can even come out negative: the spreads say how far to trust a median. `
    + `Version 0.2: the side-by-side of ${json.peersVersion02 ? `the run of ${json.peersVersion02.createdAt.slice(0, 10)}` : 'no earlier run'}; now: ${when}. MSAA: the features block's rounds (version 0.2 measured it at 1280×720 only).`, '',
    `| measure | goal | ${resolutions.map((r) => `version 0.2, ${r.replace('x', '×')} | now, ${r.replace('x', '×')}`).join(' | ')} |`,
    `|---|---|${resolutions.map(() => '---|---').join('|')}|`];
  for (const [key, name, goal] of ROWS) {
    const cells = resolutions.map((r) => {
      const [old, fresh] = [before, now].map((runs) => issueRatios(runs.find((p) => p.resolution === r)));
      const cpu = (x, judged) => (x?.cpu[key] ? `; CPU ${text(x.cpu[key])}${judged ? ` ${verdict(x.cpu[key], goal)}` : ''}` : '');
      return `${text(old?.[key])}${cpu(old, false)} | ${text(fresh?.[key])} ${verdict(fresh?.[key], goal)}${cpu(fresh, true)}`;
    });
    lines.push(`| ${name} | ≤ ${goal} | ${cells.join(' | ')} |`);
  }
  return lines.join('\n');
}

/** The head's coverage as the cost model takes it, from the side-by-side's first entry that measured it. */
function coverageOf(json) {
  const entry = (json.peers ?? []).find((p) => p.coverage);
  if (!entry) return null;
  const { pixels, subsurfacePixels, boxPixels, taps } = entry.coverage;
  return { resolution: entry.resolution, subsurface: subsurfacePixels / pixels, box: boxPixels / pixels, taps: taps.mean, centred: taps.centredMean ?? 0 };
}

const MB = (bytes) => `${(bytes / 2 ** 20).toFixed(1)} MiB`;
const bytes = (x) => x.toFixed(1);

/** The cost model's table: bytes per pixel per stage before and after, and the targets' memory at 1920×1080. */
export function costModelSection(json) {
  const coverage = coverageOf(json);
  if (!coverage) return '';
  // 'auto' at 1920×1080 takes more taps per pixel than at 1280×720 (the main plan's row, when measured).
  const hd = json.results?.find((r) => r.scene === 'head' && r.resolution === '1920x1080' && r.auto && r.taps);
  // Taps on texel centres: the side-by-side's share of its taps, applied to the 1920×1080 count.
  const taps = hd?.taps.mean ?? coverage.taps;
  const scene = { subsurface: coverage.subsurface, box: coverage.box, taps, centred: coverage.centred * (taps / coverage.taps) };
  const before = frameTraffic(BEFORE, scene);
  const after = frameTraffic(AFTER, scene);
  const lines = ['## Cost model (bytes per pixel; bench/costModel.js)', '',
    `Per screen pixel of the head at 1920×1080, with what the side-by-side measured at ${coverage.resolution.replace('x', '×')}: ${(100 * scene.subsurface).toFixed(1)} % of the pixels subsurface, ${(100 * scene.box).toFixed(1)} % in their screen box, ${scene.taps.toFixed(1)} taps per pixel and direction (${hd ? "'auto' at 1920×1080, the main plan's row" : "'auto' there"}). `
    + 'Memory: each texel a pass reads is counted once per pass (its neighbours\' taps find it in cache: a vertical pass\'s 30-row reach at 1920×1080 is about 0.9 MB of diffuse + surface, within an L2), every write once, clears as writes, the small tables (footprints, profile) free. Fetched: every texel fetch, no reuse (the texture units\' load); texel fetches: their count, the small tables\' included (the instructions a GPU issues for them). Material textures are left out (a plain frame reads the same). '
    + `${scene.centred.toFixed(1)} of the taps per pixel and direction sit on a texel centre (footprints one pixel wide). `
    + 'Before: version 0.2 (the depth prepass, the blurs over the whole frame, two texels fetched per tap); after: this version (each object drawn once, the blurs scissored to the box, one texel for a tap on a texel centre, the depth carried in the light\'s alpha: the diffuse attachment and the horizontal blur\'s output in 32-bit float, so a tap texel is one fetch of 16 B instead of two of 8 B). '
    + 'The carried depth halves the fetch instructions per tap but not the bytes they move (a texture unit moves 16 B either way), and adds 8 B per pixel of clears and reads: on SwiftShader it pays (the optimizations table below: depthFromSurface, maskInDiffuse); on a GPU bound by the bytes its texture units move it may not, which the same switches in a `--gpu` run would measure.', '',
    '| stage | written, before → after | read, before → after | fetched, before → after | texel fetches (instructions), before → after |', '|---|---|---|---|---|'];
  for (const key of ['scene', 'blurH', 'blurV', 'compose', 'total']) {
    const [b, a] = [before[key], after[key]];
    lines.push(`| ${key} | ${bytes(b.written)} → ${bytes(a.written)} | ${bytes(b.read)} → ${bytes(a.read)} | ${bytes(b.fetched)} → ${bytes(a.fetched)} | ${b.fetches.toFixed(1)} → ${a.fetches.toFixed(1)} |`);
  }
  const traffic = (x) => x.written + x.read;
  lines.push(`| a plain three.js frame | ${bytes(before.plain.written)} | ${bytes(before.plain.read)} | ${bytes(before.plain.fetched)} | ${before.plain.fetches.toFixed(1)} |`, '',
    `Memory traffic (written + read) per pixel: ${bytes(traffic(before.total))} B before, ${bytes(traffic(after.total))} B after (×${(traffic(after.total) / traffic(before.total)).toFixed(2)}; the goal: ×0.5, **${traffic(after.total) <= 0.5 * traffic(before.total) ? 'met' : 'not met'}**); a plain frame's: ${bytes(traffic(before.plain))} B.`);
  const modelled = Object.entries({
    surfaceFromDepth: 'no surface attachment (the depth texture, the width in a channel elsewhere)',
    composeInBlur: 'the compose folded into the vertical pass',
    both: 'both',
  }).map(([key, name]) => {
    const t = traffic(frameTraffic(NOT_BUILT[key], scene).total);
    return `${name}: ${bytes(t)} B (×${(t / traffic(before.total)).toFixed(2)} of before)`;
  });
  const isotropic = traffic(frameTraffic(ISOTROPIC, scene).total);
  lines.push('', `The isotropic blur (\`kernelGroups: 'auto'\`, four groups carried between the passes in two RGBA32UI texels, the depth in their alphas): ${bytes(isotropic)} B per pixel (×${(isotropic / traffic(before.total)).toFixed(2)} of before), ${bytes(isotropic - traffic(after.total))} B more than one kernel.`);
  lines.push('', `Not built, modelled on top of after (what they would save; the surface's coverage-weighted MSAA resolve has no depth-texture equivalent): ${modelled.join('; ')}.`);
  const memory = targetMemory(1920, 1080);
  const msaa = targetMemory(1920, 1080, { samples: 4 });
  const before0 = targetMemory(1920, 1080, { groups: false });
  lines.push('', `Targets at 1920×1080: ${memory.targets.map((t) => `${t.name} ${MB(t.bytes)}`).join(', ')}; **${MB(memory.bytes)}** in all with the isotropic blur's group target (${MB(msaa.bytes)} with MSAA 4; one kernel, the default, builds no group target: ${MB(before0.bytes)}). The composer's own two buffers are the application's, as with a RenderPass.`);
  return lines.join('\n');
}

