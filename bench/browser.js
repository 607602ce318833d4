// What the bench runs in: the project's launcher (dev/browser.js: Vite serving the repository and
// headless Chromium on SwiftShader, or the GPU with `gpu`), with bench/index.html open. Both are
// closed however `work` ends, and on Ctrl-C.
import { openReadyPage, startBrowser } from '../dev/browser.js';

export { chromiumFlags } from '../dev/browser.js';

/**
 * @param {(page: import('puppeteer-core').Page) => Promise<T>} work
 * @param {{ gpu?: boolean }} [options]
 * @returns {Promise<T>}
 * @template T
 */
export async function withBenchPage(work, { gpu = false } = {}) {
  const session = await startBrowser({ gpu, protocolTimeout: 900_000 });
  const onSignal = (signal) => {
    session.close().finally(() => process.exit(signal === 'SIGINT' ? 130 : 143));
  };
  process.once('SIGINT', onSignal);
  process.once('SIGTERM', onSignal);
  try {
    const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/index.html`);
    return await work(page);
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
    await session.close();
  }
}
