// `npm run bench:transfer`: the modulation transfer of the default blur, measured against the
// analytic one, per channel. A flat skin plane seen straight on at a known scale (test/pages/lab.js's
// `flat`) carries cosine gratings of albedo; the transfer at f cycles/mm is the amplitude after over
// before the blur (test/oracle/gratingFit.js, least squares), and the analytic one the profile
// marginal's Fourier transform (test/oracle/closedForms.js). Writes bench/results/transfer.json
// and docs/transfer.svg. About a minute on SwiftShader.
import { writeFile } from 'node:fs/promises';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../../dev/browser.js';
import { transferOf } from '../../test/oracle/closedForms.js';
import { frequenciesAt } from '../../test/oracle/gratingFit.js';
import { transferSvg } from './plot.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
/** The scales of the goal (px/mm: 1 is a head at 720p, 10 a close-up) and its two profiles. */
const SCALES = [1, 2, 5, 10];
const PROFILES = ['skin', 'skinBurley'];
const SIZE = 256; // pixels per side: the gratings keep gratingMargin (9 mm) from the border

const session = await startBrowser({ protocolTimeout: 600_000 });
const started = Date.now();
const measurements = [];
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/test/pages/lab.html`, { width: 320, height: 180 });
  for (const profile of PROFILES) {
    for (const s of SCALES) {
      const frequencies = frequenciesAt(s);
      const measured = await page.evaluate(async (o) => {
        const { measuredTransfer } = await import('/test/oracle/gratingFit.js');
        const r = await window.lab.flat({ ...o.flat, sss: { profile: o.profile } });
        if (r.glError) throw new Error(`GL error ${r.glError}`);
        return measuredTransfer(r, o.flat.frequencies, o.flat.pxPerMm, 0);
      }, {
        profile,
        flat: { width: SIZE, height: SIZE, pxPerMm: s, pattern: 'cosines', frequencies, phases: frequencies.map((_, k) => 0.7 * k), angleDeg: 0 },
      });
      const analytic = frequencies.map((f) => transferOf(profile, f));
      const worst = Math.max(...frequencies.flatMap((_, k) => [0, 1, 2].map((c) => Math.abs(measured[c][k] - analytic[k][c]))));
      measurements.push({ profile, pxPerMm: s, frequencies, measured, worst });
      console.log(`${profile} at ${s} px/mm: worst |measured − analytic| ${worst.toFixed(4)}`);
    }
  }
  if (page.problems.length) throw new Error(`the page reported problems:\n${page.problems.join('\n')}`);
} finally {
  await session.close();
}
const results = { setting: 'defaults (footprint, samples auto)', measurements, seconds: (Date.now() - started) / 1000, date: new Date().toISOString() };
await writeFile(join(root, 'bench/results/transfer.json'), `${JSON.stringify(results, null, 1)}\n`);
await writeFile(join(root, 'docs/transfer.svg'), transferSvg(results));
console.log(`${results.seconds.toFixed(0)} s; bench/results/transfer.json, docs/transfer.svg`);
