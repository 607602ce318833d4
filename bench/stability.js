// The cost of the plan's ramps (src/3-blur/blurPlan.js: the blur fading in, the 'auto' groups
// fading in, the 'auto' fixed-tap counts blended), beside another checkout's (`--base <dir>`: one
// with test/pages/stability.js, e.g. the commit before the ramps) in the same rounds: the head at
// each ramp's middle, median milliseconds of a frame per round, the two pages interleaved.
// SwiftShader's times are CPU times: read the ratios. node bench/stability.js [--base dir] [--rounds n]
import { parseArgs } from 'node:util';
import { join, resolve } from 'node:path';
import { AUTO_REACH } from '../src/options.js';
import { PLAN_RAMP, FADE_IN_PIXELS } from '../src/3-blur/blurPlan.js';
import { MIN_KERNEL_PIXELS } from '../src/3-blur/samplingModel.js';
import { groupingStepEnd } from '../src/3-blur/kernelGroups.js';
import { blurSettings, planThresholds } from '../test/harness/planThresholds.js';

const { values } = parseArgs({ options: { base: { type: 'string' }, rounds: { type: 'string', default: '3' }, frames: { type: 'string', default: '9' }, only: { type: 'string' } } });
const WIDTH = 320;
const HEIGHT = 180;
const skin = blurSettings();
// Where the groups start (the ramp's start here, the switch on a base without ramps), to the end of that scale step.
const groupsEnd = groupingStepEnd(planThresholds(blurSettings({ kernelGroups: 'auto' }), 0.05, 1).find((t) => JSON.parse(t.after)[2] > 1).pixelsPerMm * 1.0001);
const tapChange = (n) => (n - 3) / 2 / AUTO_REACH / skin.marginalRadiusMm; // px/mm where 'auto' leaves n taps
const middle = Math.sqrt(PLAN_RAMP);
/** Each ramp's middle: [name, the pipeline's options, px/mm]. */
const POINTS = [
  ['blur fading in (default)', {}, Math.sqrt(MIN_KERNEL_PIXELS * FADE_IN_PIXELS) / skin.marginalRadiusMm],
  ["kernelGroups 'auto' fading in", { kernelGroups: 'auto' }, groupsEnd / middle],
  ["reference 'auto' 17 + 25 taps", { method: 'reference' }, tapChange(17) / middle],
  ["reference 'auto' 25 + 33 taps", { method: 'reference' }, tapChange(25) / middle],
  ["reference 'auto' 33 (no ramp, control)", { method: 'reference' }, tapChange(25) * 1.2],
];

async function openAt(root) {
  const { startBrowser, openReadyPage } = await import(join(root, 'dev/browser.js'));
  const run = await startBrowser();
  const page = await openReadyPage(run.browser, `${run.baseUrl}/test/pages/stability.html`, {});
  return { run, page };
}

const sides = [['this checkout', await openAt(resolve('.'))]];
if (values.base) sides.push(['base', await openAt(resolve(values.base))]);
try {
  for (const [name, sss, pixelsPerMm] of POINTS.filter(([name]) => !values.only || name.includes(values.only))) {
    const fovDeg = (2 * Math.atan((HEIGHT / 50) / (2 * pixelsPerMm * 18)) * 180) / Math.PI;
    const medians = sides.map(() => []);
    for (const [, { page }] of sides) await page.evaluate((o) => window.stability.open(o), { width: WIDTH, height: HEIGHT, fovDeg, sss });
    for (let round = 0; round < Number(values.rounds); round++) {
      for (const [i, [, { page }]] of sides.entries()) {
        medians[i].push(await page.evaluate((p, n) => window.stability.time(window.stability.distanceFor(p), n), pixelsPerMm, Number(values.frames)));
      }
    }
    const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
    const ms = medians.map(median);
    console.log(`${name} at ${pixelsPerMm.toFixed(3)} px/mm: ${sides.map(([side], i) => `${side} ${ms[i].toFixed(1)} ms`).join(', ')}${ms.length > 1 ? `, ratio ${(ms[0] / ms[1]).toFixed(3)}` : ''}`);
  }
} finally {
  for (const [, { page, run }] of sides) {
    await page.evaluate(() => window.stability.close());
    await run.close();
  }
}
