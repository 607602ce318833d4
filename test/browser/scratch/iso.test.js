import { it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';
import { accuracyMeasures } from '../3-blur/accuracyCases.js';
let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => { console.log(page.problems); await page.close(); });
const S = JSON.parse(process.env.ISO_S ?? '[5, 5.187]');
const P = JSON.parse(process.env.ISO_P ?? '["skin","skinBurley"]');
const A = JSON.parse(process.env.ISO_A ?? '[45]');
const SSS = JSON.parse(process.env.ISO_SSS ?? '{}');
it('scratch', async () => {
  const { grating } = accuracyMeasures((o) => evaluateFloats(page, (options) => window.lab.flat(options), o));
  const lines = [];
  for (const profile of P) for (const s of S) {
    const row = [profile, s];
    for (const angleDeg of A) {
      const r = await grating({ profile, s, angleDeg, sss: SSS, width: +(process.env.ISO_W ?? 256), height: +(process.env.ISO_H ?? process.env.ISO_W ?? 256) });
      row.push(angleDeg + ':' + r.worst.toFixed(4));
      if (process.env.ISO_DETAIL) { const e = (await import('../../oracle/closedForms.js')).transferOf; row.push('\n' + r.frequencies.map((f, k) => f.toFixed(2) + ' ' + [0,1,2].map(c => (r.measured[c][k] - e(profile, f)[c]).toFixed(4)).join(',')).join('\n')); }
    }
    lines.push(row.join(' '));
  }
  console.log(lines.join('\n'));
});
