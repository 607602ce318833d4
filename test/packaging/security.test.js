// The demo under a strict Content-Security-Policy and Trusted Types, and the library under Trusted Types:
// - the built demo (vite build, as deployed), served with DEMO_CSP as a header, alone and with
//   DEMO_TRUSTED_TYPES added: no script from a string (no 'unsafe-eval'), no inline script or style,
//   no data: font (lil-gui's icon font is a file); under Trusted Types no HTML from a string but
//   through the demo's text-only default policy (demo/trustedTypes.js: lil-gui's titles and names).
//   Under each, the page starts, renders a finite frame, its styled panel and its timings, with no
//   violation;
// - test/pages/trustedTypes.html: `require-trusted-types-for 'script'`, the library imported and
//   rendering, with no violation (no innerHTML, no string-to-code).
// Violations are collected from securitypolicyviolation events registered before the page loads.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { createServer } from 'node:http';
import { readFile, rm } from 'node:fs/promises';
import { existsSync, readFileSync } from 'node:fs';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';
import { browser, openPage } from '../harness/page.js';
import { openReadyPage } from '../../dev/browser.js';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** The policy CONTRIBUTING.md gives for serving the built demo. */
export const DEMO_CSP = [
  "default-src 'self'",
  "script-src 'self'",
  "style-src 'self'",
  "font-src 'self'",
  "img-src 'self' data: blob:",
  "connect-src 'self'",
  "object-src 'none'",
  "base-uri 'self'",
  "form-action 'none'",
  "frame-ancestors 'none'",
].join('; ');

/** Trusted Types on top: HTML from strings only through the one default policy (demo/trustedTypes.js). */
export const DEMO_TRUSTED_TYPES = "require-trusted-types-for 'script'; trusted-types default";

/** The policies the built demo is served with, by the path prefix it is served under. */
const POLICIES = { csp: DEMO_CSP, 'trusted-types': `${DEMO_CSP}; ${DEMO_TRUSTED_TYPES}` };

const TYPES = {
  '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.map': 'application/json',
  '.glb': 'model/gltf-binary', '.jpg': 'image/jpeg', '.png': 'image/png', '.svg': 'image/svg+xml', '.woff': 'font/woff',
};

/** Registers a securitypolicyviolation listener in `page` before any of its scripts run. */
async function collectViolations(page) {
  await page.evaluateOnNewDocument(() => {
    window.__violations = [];
    document.addEventListener('securitypolicyviolation', (e) => {
      window.__violations.push(`${e.effectiveDirective} refused ${e.blockedURI || '(inline)'} at ${e.sourceFile}:${e.lineNumber}`);
    });
  });
}

/** What the built demo shows once started: its frame, its panel, its fonts and timings, and the violations so far. */
async function demoReport(page) {
  await page.evaluate(() => document.fonts.ready);
  return page.evaluate(async () => {
    const { demo } = window;
    demo.stop();
    demo.updateTimings();
    const { data, width, height } = await demo.readHdr();
    let nonFinite = 0;
    let covered = 0;
    const bg = demo.rig.scene.background;
    for (let i = 0; i < width * height; i++) {
      const [r, g, b] = [data[i * 4], data[i * 4 + 1], data[i * 4 + 2]];
      if (![r, g, b].every(Number.isFinite)) nonFinite++;
      else if (Math.abs(r - bg.r) + Math.abs(g - bg.g) + Math.abs(b - bg.b) > 1e-3) covered++;
    }
    const panel = document.querySelector('.lil-gui.root');
    const fonts = [...document.fonts].filter((f) => f.family.replace(/"/g, '') === 'lil-gui').map((f) => f.status);
    return {
      nonFinite, coverage: covered / (width * height), standIn: demo.isStandIn,
      panelBackground: panel && getComputedStyle(panel).backgroundColor, fonts,
      panelTitle: panel?.querySelector('.title')?.textContent,
      controlNames: [...document.querySelectorAll('.lil-gui .controller .name')].map((e) => e.textContent).filter(Boolean).length,
      fps: document.querySelector('.hud-fps').textContent,
      violations: window.__violations,
    };
  });
}

/** Runs `probe` in the page (through DevTools, as every evaluate) and returns the violations it caused. */
async function violationsOf(page, probe) {
  const before = await page.evaluate(() => window.__violations.length);
  const result = await page.evaluate(probe);
  await page.evaluate(() => new Promise((resolve) => setTimeout(resolve, 100))); // the violation event is queued
  return { result, violations: await page.evaluate((n) => window.__violations.slice(n), before) };
}

describe('the built demo under a strict Content-Security-Policy and Trusted Types', () => {
  const outDir = join(root, 'node_modules/.cache/sss-csp-demo');
  let server;
  let baseUrl;
  beforeAll(async () => {
    await build({ root, configFile: join(root, 'vite.config.js'), logLevel: 'error', build: { outDir, emptyOutDir: true, sourcemap: false } });
    server = createServer(async (request, response) => {
      const [, prefix, rest] = new URL(request.url, 'http://x').pathname.match(/^\/([^/]+)(\/.*)$/) ?? [];
      const policy = POLICIES[prefix] ?? DEMO_CSP;
      const path = normalize(decodeURIComponent(rest ?? '/')).replace(/^(\.\.[/\\])+/, '');
      const file = join(outDir, path.endsWith('/') ? `${path}index.html` : path);
      try {
        const body = await readFile(file);
        response.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream', 'Content-Security-Policy': policy });
        response.end(body);
      } catch {
        response.writeHead(404, { 'Content-Security-Policy': policy });
        response.end();
      }
    });
    await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
    baseUrl = `http://127.0.0.1:${server.address().port}`;
  }, 120_000);
  afterAll(async () => {
    await new Promise((resolve) => server?.close(resolve));
    await rm(outDir, { recursive: true, force: true });
  });

  it('has no inline script or style in the built page, and no data: URL in its stylesheets', () => {
    const html = readFileSync(join(outDir, 'index.html'), 'utf8');
    expect(html).not.toMatch(/<script(?![^>]*\bsrc=)[^>]*>/);
    expect(html).not.toMatch(/<style|style="/);
    const sheets = [...html.matchAll(/<link rel="stylesheet"[^>]*href="([^"]+)"/g)].map((m) => m[1]);
    expect(sheets.length).toBeGreaterThan(0);
    for (const sheet of sheets) expect(readFileSync(join(outDir, sheet), 'utf8')).not.toMatch(/url\(\s*["']?data:/);
  });

  for (const name of Object.keys(POLICIES)) {
    it(`${name}: starts, renders, styles its panel and shows its timings with no violation and no console error`, async () => {
      const page = await openReadyPage(await browser(), `${baseUrl}/${name}/index.html?still`, { width: 480, height: 270, beforeLoad: collectViolations });
      try {
        expect(await page.evaluate('window.testReady')).toBe(true);
        const r = await demoReport(page);
        expect(r.violations).toEqual([]);
        expect(page.problems).toEqual([]);
        expect(r.nonFinite).toBe(0);
        expect(r.coverage).toBeGreaterThan(0.1);
        expect(r.panelBackground).toBe('rgb(31, 31, 31)'); // lil-gui's --background-color: its stylesheet applies
        expect(r.fonts).toEqual(['loaded']); // its icon font, from its file
        expect(r.panelTitle).toBe('Settings'); // lil-gui's innerHTML, as text
        expect(r.controlNames).toBeGreaterThan(20);
        expect(r.fps).toMatch(/fps · render\(\) [\d.…]+ ms/);
        // The policy is in force: an inline script is refused (and reported), under Trusted Types
        // already its text (no policy makes TrustedScript).
        const inline = await violationsOf(page, () => {
          const script = document.createElement('script');
          try { script.textContent = 'window.inlineScriptRan = true'; } catch (e) { return e.name; }
          document.head.append(script);
          return window.inlineScriptRan === true;
        });
        expect(inline.result).toBe(name === 'trusted-types' ? 'TypeError' : false);
        expect(inline.violations).toEqual([expect.stringMatching(name === 'trusted-types' ? /^require-trusted-types-for refused/ : /^script-src-elem refused inline/)]);
        // Under Trusted Types, HTML with markup is refused even through the default policy; plain text passes.
        const markup = await violationsOf(page, () => {
          const div = document.createElement('div');
          div.innerHTML = 'plain text';
          try { div.innerHTML = '<b>x</b>'; } catch (e) { return `${div.textContent}; ${e.name}`; }
          return `${div.textContent}; accepted`;
        });
        if (name === 'trusted-types') {
          expect(markup.result).toBe('plain text; TypeError');
          expect(markup.violations).toEqual([expect.stringMatching(/^require-trusted-types-for refused/)]);
        } else {
          expect(markup.result).toBe('x; accepted');
          expect(markup.violations).toEqual([]);
        }
        page.problems.length = 0; // the refusals' console errors
      } finally {
        await page.close();
      }
    });
  }
});

describe('the library under Trusted Types', () => {
  it('imports and renders with require-trusted-types-for \'script\' and no violation', async () => {
    const page = await openPage('/test/pages/trustedTypes.html', { beforeLoad: collectViolations });
    try {
      const r = await page.evaluate('window.testReady');
      const violations = await page.evaluate(() => window.__violations);
      expect(r.violationsWhileRendering).toBe(0);
      expect(r.glError).toBe(0);
      expect(r.nonFinite).toBe(0);
      expect(r.mean).toBeGreaterThan(0.05);
      expect(r.problems).toEqual([]);
      // Enforcement was on: the page's own probes were refused, and were the only violations.
      expect(r.refused).toEqual(['innerHTML: TypeError', 'new Function: EvalError']);
      expect(violations).toHaveLength(2);
      expect(page.problems.filter((p) => !/trusted|TrustedHTML|TrustedScript|Refused to evaluate/i.test(p))).toEqual([]);
    } finally {
      await page.close();
    }
  });
});

// Checked here so a missing scan says why the demo shows the stand-in (the test passes either way).
if (!existsSync(join(root, 'public/assets/LeePerrySmith/LeePerrySmith.glb'))) {
  console.log('security.test.js: the head scan is not in public/assets: the built demo shows the stand-in bust');
}
