// The side-by-side's runner (Node side): drives bench/peers.js in the page round by round. Each
// round times every measure of PEER_MEASURES (`frames` frames each, after one untimed frame), in an
// order rotated by one from the round before, so that a load passing on the machine touches them
// alike; around each timed call it reads the GPU process's CPU clock (dev/processClock.js).
import { PEER_MEASURES } from './peerPlan.js';
import { median } from './analysis.js';

/**
 * @param {import('puppeteer-core').Page} page bench/index.html with the head open
 * @param {{ nowMs(): number } | null} clock the GPU process's CPU clock (null: not measured)
 * @param {{ rounds: number, frames: number }} timing
 * @returns {Promise<object[]>} one entry per round: measure → { timerMs (median per frame),
 *   cpuMs (GPU-process CPU per frame, or null) }; 'stages' → stage → median timer ms (NaN: did not run)
 */
export async function peerRounds(page, clock, { rounds, frames }) {
  const out = [];
  for (let round = 0; round < rounds; round++) {
    const entry = {};
    for (let k = 0; k < PEER_MEASURES.length; k++) {
      const measure = PEER_MEASURES[(k + round) % PEER_MEASURES.length];
      await page.evaluate((m) => window.bench.peerMeasure({ measure: m, frames: 0, warmUp: 1 }), measure);
      const before = clock?.nowMs();
      const times = await page.evaluate((o) => window.bench.peerMeasure(o), { measure, frames });
      const cpuMs = clock ? (clock.nowMs() - before) / frames : null;
      if (measure === 'stages') entry.stages = Object.fromEntries(Object.entries(times).map(([stage, ms]) => [stage, median(ms)]));
      else entry[measure] = { timerMs: median(times[measure]), cpuMs };
    }
    out.push(entry);
  }
  return out;
}
