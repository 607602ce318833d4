// Opening the demo in a browser test: still (no animation), an optional URL hash, every page
// checked for console errors and closed after each test. A test file calls demoOpener once.
import { afterEach, expect } from 'vitest';
import { openPage } from './page.js';

/**
 * @param {{ width: number, height: number }} size the default viewport, CSS pixels
 * @returns {(hash?: string, size?: { width?: number, height?: number }) => Promise<import('puppeteer-core').Page>}
 */
export function demoOpener({ width, height }) {
  let pages = [];
  afterEach(async () => {
    for (const page of pages) {
      expect(page.problems).toEqual([]);
      await page.close();
    }
    pages = [];
  });
  return async (hash, size = {}) => {
    const page = await openPage(`/?still${hash ? `#${hash}` : ''}`, { width: size.width ?? width, height: size.height ?? height });
    expect(await page.evaluate('window.testReady')).toBe(true);
    await page.evaluate(() => window.demo.stop());
    pages.push(page);
    return page;
  };
}
