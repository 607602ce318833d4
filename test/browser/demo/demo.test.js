// The demo page renders the head (or the stand-in) through EffectComposer → OutputPass, with no
// console errors. Measured on the linear HDR image OutputPass receives, read back as floats.
import { describe, it, expect } from 'vitest';
import { readFileSync, existsSync } from 'node:fs';
import { openPage } from '../../harness/page.js';

// The asset step (run before the tests) says whether the scan is here; without it only the
// stand-in can be checked, and the scan test says why it did not run.
const statusFile = new URL('../../../public/assets/head-status.json', import.meta.url);
const scanAvailable = existsSync(statusFile) && JSON.parse(readFileSync(statusFile, 'utf8')).complete === true;

const W = 320;
const H = 180;

/** Statistics of the demo's HDR frame, computed in the page. */
async function frameStats(page) {
  return page.evaluate(async () => {
    const { demo } = window;
    demo.stop();
    const first = await demo.readHdr();
    const second = await demo.readHdr();
    const { width, height, data } = first;
    const bg = demo.rig.scene.background; // linear
    let covered = 0;
    let nonFinite = 0;
    let identical = true;
    for (let i = 0; i < width * height; i++) {
      const r = data[i * 4], g = data[i * 4 + 1], b = data[i * 4 + 2];
      if (!Number.isFinite(r) || !Number.isFinite(g) || !Number.isFinite(b)) nonFinite++;
      if (Math.abs(r - bg.r) + Math.abs(g - bg.g) + Math.abs(b - bg.b) > 1e-3) covered++;
    }
    for (let i = 0; i < data.length; i++) if (data[i] !== second.data[i]) { identical = false; break; }
    // Face centre in pixels (GL rows bottom-up), and the mean radiance in a 9×9 box there.
    const p = demo.facePoint.clone().project(demo.rig.camera);
    const cx = Math.round((p.x * 0.5 + 0.5) * width);
    const cy = Math.round((p.y * 0.5 + 0.5) * height);
    let face = 0;
    for (let y = cy - 4; y <= cy + 4; y++) for (let x = cx - 4; x <= cx + 4; x++) {
      const i = (y * width + x) * 4;
      face += (data[i] + data[i + 1] + data[i + 2]) / 3 / 81;
    }
    return { width, height, coverage: covered / (width * height), nonFinite, identical, face, background: (bg.r + bg.g + bg.b) / 3 };
  });
}

describe('demo page', () => {
  it.skipIf(!scanAvailable)('renders the textured head scan with no console errors (needs the scan: npm run assets)', async () => {
    const page = await openPage('/?still', { width: W, height: H });
    const ok = await page.evaluate('window.testReady');
    expect(ok).toBe(true);
    expect(await page.evaluate('window.demo.isStandIn')).toBe(false);
    const s = await frameStats(page);
    expect(s.width).toBe(W);
    expect(s.height).toBe(H);
    expect(s.nonFinite).toBe(0);
    expect(s.identical).toBe(true);
    // The head and shoulders fill a good part of the 16:9 frame, but not all of it.
    expect(s.coverage).toBeGreaterThan(0.15);
    expect(s.coverage).toBeLessThan(0.8);
    // The face centre is lit: far brighter than the background.
    expect(s.face).toBeGreaterThan(0.05);
    expect(s.face).toBeGreaterThan(10 * s.background);
    // Textured with the scan's maps (Map-COL.jpg is 2048 px wide, in sRGB).
    const maps = await page.evaluate(() => {
      const m = window.demo.head.mesh.material;
      return { map: m.map?.image?.width, colorSpace: m.map?.colorSpace, normal: !!m.normalMap, specular: !!m.specularColorMap };
    });
    expect(maps.map).toBeGreaterThan(256);
    expect(maps.colorSpace).toBe('srgb');
    expect(maps.normal && maps.specular).toBe(true);
    expect(await page.evaluate(() => document.getElementById('attribution').textContent)).toMatch(/Lee Perry-Smith.*CC BY 3\.0/s);
    expect(await page.evaluate(() => document.getElementById('notice').hidden)).toBe(true);
    expect(page.problems).toEqual([]);
    await page.close();
  });

  it('falls back to the procedural stand-in with a notice when the asset step found nothing', async () => {
    // The page sees what a machine without the scan sees: the asset step's status says so, and
    // the scan files are not served.
    const missing = ['LeePerrySmith.glb', 'Map-COL.jpg', 'Map-SPEC.jpg', 'Infinite-Level_02_Tangent_SmoothUV.jpg'];
    const page = await openPage('/?still', {
      width: W,
      height: H,
      beforeLoad: async (p) => {
        await p.setRequestInterception(true);
        p.on('request', (request) => {
          const url = request.url();
          if (url.endsWith('/assets/head-status.json')) {
            request.respond({ status: 200, contentType: 'application/json', body: JSON.stringify({ complete: false, missing, source: {} }) });
          } else if (url.includes('/assets/LeePerrySmith/')) {
            request.abort();
          } else {
            request.continue();
          }
        });
      },
    });
    expect(await page.evaluate('window.testReady')).toBe(true);
    expect(await page.evaluate('window.demo.isStandIn')).toBe(true);
    const notice = await page.evaluate(() => ({ hidden: document.getElementById('notice').hidden, text: document.getElementById('notice').textContent }));
    expect(notice.hidden).toBe(false);
    expect(notice.text).toContain('LeePerrySmith.glb');
    expect(notice.text).toContain('Map-COL.jpg');
    expect(notice.text).toContain('SSS_ASSETS_DIR');
    expect(notice.text).toContain('Infinite-Level_02_Tangent_SmoothUV.jpg');
    const s = await frameStats(page);
    expect(s.nonFinite).toBe(0);
    expect(s.coverage).toBeGreaterThan(0.1);
    expect(s.face).toBeGreaterThan(10 * s.background);
    expect(page.problems).toEqual([]);
    await page.close();
  });
});
