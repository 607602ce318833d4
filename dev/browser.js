// The one browser launcher of the tests, the bench and the figure script (Node side): it finds a
// Chromium, starts Vite on the repository and headless Chromium on SwiftShader (or a GPU), and
// closes both however the work ends.
//
// The Chromium, in the order the project promises: 1. PUPPETEER_EXECUTABLE_PATH, 2. Debian's
// chromium package. When none is found and we run as root on Debian, Debian's `chromium` is
// installed (what CI needs); otherwise the caller gets a one-line message saying what to install.
// puppeteer-core drives it: it has no install script (puppeteer's would download a Chrome, which
// npm 11 blocks with a warning and the machines here cannot reach anyway).
import { existsSync, readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/** SwiftShader (software WebGL2), and no background network traffic (the machine's network is closed). */
export const CHROMIUM_FLAGS = Object.freeze([
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
  '--no-first-run',
]);

/**
 * WebGPU on SwiftShader (the WebGPURenderer tests, test/browser/webgpu*): without the two Vulkan
 * flags the adapter is found but configuring a canvas loses the device ("A valid external Instance
 * reference no longer exists"). WebGPU needs a secure context: pages served from http://127.0.0.1.
 */
export const WEBGPU_FLAGS = Object.freeze([
  '--enable-unsafe-webgpu',
  '--use-webgpu-adapter=swiftshader',
  '--use-vulkan=swiftshader',
  '--enable-features=Vulkan',
]);

/**
 * The flags for SwiftShader, or for a GPU the same without SwiftShader and with the GPU allowed;
 * `webgpu` adds WEBGPU_FLAGS (SwiftShader only).
 */
export function chromiumFlags({ gpu = false, webgpu = false } = {}) {
  if (!gpu) return [...CHROMIUM_FLAGS, ...(webgpu ? WEBGPU_FLAGS : [])];
  return [
    ...CHROMIUM_FLAGS.filter((flag) => !flag.includes('swiftshader')),
    '--ignore-gpu-blocklist', '--enable-gpu', '--use-angle=vulkan', '--enable-features=Vulkan',
  ];
}

export const DEBIAN_CHROMIUM = '/usr/lib/chromium/chromium';

const INSTALL_HINT =
  'No Chromium found for the browser tests: install Debian\'s "chromium" package ' +
  '(apt-get install chromium), or set PUPPETEER_EXECUTABLE_PATH to a Chrome or Chromium ' +
  '(e.g. one installed by "npx @puppeteer/browsers install chrome@stable").';

/** @returns {Promise<string|null>} the path of a usable browser, or null. */
export async function lookupBrowser() {
  const fromEnv = process.env.PUPPETEER_EXECUTABLE_PATH;
  if (fromEnv) {
    if (existsSync(fromEnv)) return fromEnv;
    throw new Error(`PUPPETEER_EXECUTABLE_PATH points to a missing file: ${fromEnv}`);
  }
  if (existsSync(DEBIAN_CHROMIUM)) return DEBIAN_CHROMIUM;
  return null;
}

function isRootOnDebian() {
  return process.getuid?.() === 0 && existsSync('/etc/debian_version') &&
    /debian/i.test(readFileSync('/etc/os-release', 'utf8'));
}

/** Finds a browser, installing Debian's chromium when that is possible; throws a one-line hint otherwise. */
export async function findBrowser({ log = console.log } = {}) {
  let path = await lookupBrowser();
  if (path) return path;
  if (isRootOnDebian()) {
    log('No Chromium found: installing Debian\'s chromium package (root on Debian)...');
    const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
    execFileSync('apt-get', ['update', '-qq'], { stdio: 'inherit', env });
    execFileSync('apt-get', ['install', '-y', '-qq', 'chromium'], { stdio: 'inherit', env });
    path = await lookupBrowser();
    if (path) return path;
  }
  throw new Error(INSTALL_HINT);
}

/**
 * Starts Vite serving the repository and headless Chromium.
 * @param {{ gpu?: boolean, webgpu?: boolean, protocolTimeout?: number }} [options]
 * @returns {Promise<{ browser: import('puppeteer-core').Browser, baseUrl: string, flags: string[], close(): Promise<void> }>}
 */
export async function startBrowser({ gpu = false, webgpu = false, protocolTimeout = 600_000 } = {}) {
  const executablePath = await findBrowser();
  const { createServer } = await import('vite');
  const { default: puppeteer } = await import('puppeteer-core');
  const server = await createServer({
    root,
    configFile: join(root, 'vite.config.js'),
    // The checkout's own dependency cache (git-ignored), not node_modules/.vite: worktrees sharing
    // one node_modules re-optimised it under each other's servers (504 "Outdated Optimize Dep").
    cacheDir: join(root, '.vite'),
    logLevel: 'error',
    clearScreen: false,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
  });
  await server.listen();
  const { port } = server.httpServer.address();
  const userDataDir = await mkdtemp(join(tmpdir(), 'sss-chromium-'));
  const flags = chromiumFlags({ gpu, webgpu });
  let browser;
  try {
    browser = await puppeteer.launch({ executablePath, headless: true, userDataDir, args: flags, protocolTimeout });
  } catch (error) {
    await server.close();
    await rm(userDataDir, { recursive: true, force: true });
    throw error;
  }
  let closing = null;
  return {
    browser,
    baseUrl: `http://127.0.0.1:${port}`,
    flags,
    close() {
      closing ??= (async () => {
        await browser.close().catch(() => browser.process()?.kill('SIGKILL'));
        await server.close();
        await rm(userDataDir, { recursive: true, force: true });
      })();
      return closing;
    },
  };
}

/**
 * Opens `url` in a new page and waits until `readyExpr` is defined, then resolves it (the pages
 * set `window.testReady` to a promise or a value). Console errors, page errors and failed requests
 * are collected in `page.problems`.
 * @param {import('puppeteer-core').Browser} browser
 * @param {string} url
 * @param {{ width?: number, height?: number, readyExpr?: string, timeout?: number, beforeLoad?: (page) => Promise<void> }} [options]
 *   `beforeLoad` runs before navigation, e.g. to intercept requests
 * @returns {Promise<import('puppeteer-core').Page>}
 */
export async function openReadyPage(browser, url, { width, height, readyExpr = 'window.testReady', timeout = 120_000, beforeLoad } = {}) {
  const page = await browser.newPage();
  page.problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') page.problems.push(`console.error: ${msg.text()}`); });
  page.on('pageerror', (error) => page.problems.push(`pageerror: ${error.message}`));
  page.on('requestfailed', (req) => page.problems.push(`requestfailed: ${req.url()} ${req.failure()?.errorText}`));
  if (width && height) await page.setViewport({ width, height, deviceScaleFactor: 1 });
  await beforeLoad?.(page);
  await page.goto(url, { waitUntil: 'load', timeout });
  await page.waitForFunction(`${readyExpr} !== undefined`, { timeout, polling: 50 });
  await page.evaluate(`Promise.resolve(${readyExpr})`);
  return page;
}
