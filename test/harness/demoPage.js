// Opening the demo in a browser test: still (no animation), an optional URL hash, every page
// checked for console errors after each test. A test file calls demoOpener once.
// With `reuse`, the file loads the demo once at its default size and shows each later hash on that
// page, as an edited hash does (window.demo.show: the state replaced whole by the hash's, every
// setting applied): a load of the head and its pipeline costs seconds, a hash change a frame.
// `{ fresh: true }` (or another size) still loads a page of its own, closed after the test.
import { afterAll, afterEach, expect } from 'vitest';
import { openPage } from './page.js';

/**
 * @param {{ width: number, height: number, reuse?: boolean }} options the default viewport, CSS pixels
 * @returns {(hash?: string, options?: { width?: number, height?: number, fresh?: boolean }) => Promise<import('puppeteer-core').Page>}
 */
export function demoOpener({ width, height, reuse = false }) {
  let pages = [];
  let shared = null;
  afterEach(async () => {
    if (shared) {
      expect(shared.problems).toEqual([]);
      shared.problems.length = 0;
    }
    for (const page of pages) {
      expect(page.problems).toEqual([]);
      await page.close();
    }
    pages = [];
  });
  afterAll(async () => {
    await shared?.close();
    shared = null;
  });
  const load = async (hash, w, h) => {
    const page = await openPage(`/?still${hash ? `#${hash}` : ''}`, { width: w, height: h });
    expect(await page.evaluate('window.testReady')).toBe(true);
    await page.evaluate(() => window.demo.stop());
    return page;
  };
  return async (hash, { fresh = false, ...size } = {}) => {
    const own = fresh || !reuse || (size.width ?? width) !== width || (size.height ?? height) !== height;
    if (own) {
      const page = await load(hash, size.width ?? width, size.height ?? height);
      pages.push(page);
      return page;
    }
    if (!shared) shared = await load(hash, width, height);
    else await shared.evaluate((h) => window.demo.show(h), hash ?? '');
    return shared;
  };
}
