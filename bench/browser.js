// Starts what the bench runs in with the tests' own set-up (test/harness/globalSetup.js): Vite
// serving the repository and headless Chromium (SwiftShader, or the GPU with `gpu`), then opens
// bench/index.html. Both are closed however `work` ends, and on Ctrl-C.
import puppeteer from 'puppeteer';
import setup, { CHROMIUM_FLAGS } from '../test/harness/globalSetup.js';

const SWIFTSHADER_FLAGS = [...CHROMIUM_FLAGS];

/** The tests' flags, or for a GPU the same without SwiftShader and with the GPU allowed. */
export function chromiumFlags({ gpu = false } = {}) {
  if (!gpu) return SWIFTSHADER_FLAGS;
  return [
    ...SWIFTSHADER_FLAGS.filter((flag) => !flag.includes('swiftshader')),
    '--ignore-gpu-blocklist', '--enable-gpu', '--use-angle=vulkan', '--enable-features=Vulkan',
  ];
}

/** globalSetup's `setup` launching Chromium with `flags` (it reads CHROMIUM_FLAGS only at launch). */
async function startWith(flags, provided) {
  CHROMIUM_FLAGS.splice(0, CHROMIUM_FLAGS.length, ...flags);
  try {
    return await setup({ provide: (key, value) => { provided[key] = value; } });
  } finally {
    CHROMIUM_FLAGS.splice(0, CHROMIUM_FLAGS.length, ...SWIFTSHADER_FLAGS);
  }
}

/**
 * @param {(page: import('puppeteer').Page) => Promise<T>} work
 * @param {{ gpu?: boolean }} [options]
 * @returns {Promise<T>}
 * @template T
 */
export async function withBenchPage(work, { gpu = false } = {}) {
  const provided = {};
  const teardown = await startWith(chromiumFlags({ gpu }), provided);
  let connection = null;
  let closing = null;
  const closeAll = () => {
    closing ??= (async () => {
      await connection?.disconnect().catch(() => {});
      await teardown();
    })();
    return closing;
  };
  const onSignal = (signal) => {
    closeAll().finally(() => process.exit(signal === 'SIGINT' ? 130 : 143));
  };
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);
  try {
    connection = await puppeteer.connect({ browserWSEndpoint: provided.browserWSEndpoint, protocolTimeout: 900_000 });
    const page = await connection.newPage();
    page.problems = [];
    page.on('console', (msg) => {
      if (msg.type() === 'error') page.problems.push(msg.text());
    });
    page.on('pageerror', (error) => page.problems.push(error.message));
    await page.goto(`${provided.baseUrl}/bench/index.html`, { waitUntil: 'load', timeout: 120_000 });
    await page.waitForFunction('window.testReady === true', { timeout: 120_000, polling: 50 });
    return await work(page);
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
    await closeAll();
  }
}
