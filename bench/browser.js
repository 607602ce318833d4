// Starts what the bench runs in, the way the tests do (test/harness/globalSetup.js): Vite serving
// the repository, and Chromium (SwiftShader unless `gpu`), then opens bench/index.html. Both are
// closed however `work` ends.
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { createServer } from 'vite';
import puppeteer from 'puppeteer';
import { CHROMIUM_FLAGS } from '../test/harness/globalSetup.js';
import { findBrowser } from '../test/harness/findBrowser.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

/** The test flags, or for a GPU the same without SwiftShader and with the GPU allowed. */
export function chromiumFlags({ gpu = false } = {}) {
  if (!gpu) return CHROMIUM_FLAGS;
  return [
    ...CHROMIUM_FLAGS.filter((flag) => !flag.includes('swiftshader')),
    '--ignore-gpu-blocklist', '--enable-gpu', '--use-angle=vulkan', '--enable-features=Vulkan',
  ];
}

/**
 * @param {(page: import('puppeteer').Page) => Promise<T>} work
 * @param {{ gpu?: boolean, log?: (line: string) => void }} [options]
 * @returns {Promise<T>}
 * @template T
 */
export async function withBenchPage(work, { gpu = false, log = console.log } = {}) {
  const executablePath = await findBrowser({ log });
  const server = await createServer({
    root,
    configFile: join(root, 'vite.config.js'),
    logLevel: 'error',
    clearScreen: false,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
  });
  let browser = null;
  const userDataDir = await mkdtemp(join(tmpdir(), 'sss-bench-'));
  const closeAll = async () => {
    if (browser) await browser.close().catch(() => browser.process()?.kill('SIGKILL'));
    browser = null;
    await server.close();
    await rm(userDataDir, { recursive: true, force: true });
  };
  const onSignal = (signal) => {
    closeAll().finally(() => process.exit(signal === 'SIGINT' ? 130 : 143));
  };
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);
  try {
    await server.listen();
    const { port } = server.httpServer.address();
    browser = await puppeteer.launch({
      executablePath, headless: true, userDataDir, args: chromiumFlags({ gpu }), protocolTimeout: 900_000,
    });
    const page = await browser.newPage();
    const problems = [];
    page.on('console', (msg) => {
      if (msg.type() === 'error') problems.push(msg.text());
    });
    page.on('pageerror', (error) => problems.push(error.message));
    await page.goto(`http://127.0.0.1:${port}/bench/index.html`, { waitUntil: 'load', timeout: 120_000 });
    await page.waitForFunction('window.testReady === true', { timeout: 120_000, polling: 50 });
    page.problems = problems;
    return await work(page);
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
    await closeAll();
  }
}
