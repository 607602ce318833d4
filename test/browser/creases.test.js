// Steady at creases (issue 40): the demo's first view (the face close-up at 1280 × 720, its key
// light, MSAA 4, OutputPass) dollied slowly, 0.02 % of the distance a frame, through a crop of
// the lips and a nostril (a view offset: the demo's scale in few pixels). Each frame is read as a
// user sees it, in output steps; a pixel pops where its change from one frame to the next departs
// a whole step from its steady change and the unscattered light (the same frames without
// scattering) does not pop there or beside it (test/pages/pops.js states it exactly). The default
// pipeline's largest pop is within twice the plain blur's (no depth rule, no slope: a linear filter
// of the light at the same scale) and it pops no more than a stated multiple of its count.
//
// What popped is the grazing-angle correction's slope estimate, whose limits switched
// (docs/ARCHITECTURE.md, "Steady at creases"); the depth rule alone pops less than the plain blur.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { closeCheckedPage, openPage } from '../harness/page.js';

/** The crop of the first view at 1280 × 720: x, y (from the top left), width, height. */
const VIEW = { fullWidth: 1280, fullHeight: 720, crop: [560, 440, 160, 128] };
const DOLLY = { frames: 16, step: 0.0002 };
/** The plain blur: the same kernel at the same scale, neither depth rule nor slope. */
const PLAIN = { followSurface: 'off', foreshortening: false };
/**
 * The multiple of the plain blur's count allowed: the foreshortened scale still moves in steps
 * where the head's facets meet, and the footprint row and edges with it (6.4 times the plain
 * blur's when measured; 9.1 times with the limits switching).
 */
const MARGIN = 7;

let page;
beforeAll(async () => { page = await openPage('/test/pages/creases.html'); });
afterAll(async () => {
  await page.evaluate(() => window.creases.close());
  await closeCheckedPage(page);
});

/** Dollies the view with pipeline options `sss`, kept in the page as `name`. */
async function dolly(name, sss) {
  const { isStandIn } = await page.evaluate((o) => window.creases.open(o), { ...VIEW, sss });
  if (isStandIn) return false;
  const { glError } = await page.evaluate((o) => window.creases.dolly(o), { name, ...DOLLY });
  expect(glError).toBe(0);
  return true;
}

describe('a slow dolly at the demo\'s first view', () => {
  it(`the default pipeline's pixels pop by no more than twice the plain blur's largest pop, and no more than ${MARGIN} times as often`, async (context) => {
    if (!(await dolly('light', { scattering: false }))) context.skip('the head scan is missing: npm run assets');
    await dolly('plain', PLAIN);
    await dolly('default', {});
    const [plain, pipeline] = await Promise.all(['plain', 'default'].map((name) => page.evaluate((o) => window.creases.pops(o), { name, explainedBy: 'light' })));
    console.log(`pops in ${DOLLY.frames} frames (pixel-pairs; by octave from 1 step): plain blur ${plain.pops} ${JSON.stringify(plain.byOctave)}, largest ${plain.largest.toFixed(2)}; default ${pipeline.pops} ${JSON.stringify(pipeline.byOctave)}, largest ${pipeline.largest.toFixed(2)}`);
    expect(plain.pops).toBeGreaterThan(0); // the measure sees the light's own pops spread by the blur
    expect(pipeline.pops).toBeLessThanOrEqual(MARGIN * plain.pops);
    expect(pipeline.largest).toBeLessThanOrEqual(2 * plain.largest);
  });
});
