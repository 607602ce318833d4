// Helpers for browser tests: connect to the run's shared Chromium, open a page served by the run's
// Vite server, collect console errors, and read float pixel data back from the page.
import { inject, afterAll } from 'vitest';
import puppeteer from 'puppeteer';

let connection = null;

/** Connects (once per test file) to the browser started in globalSetup. */
export async function browser() {
  if (!connection) {
    connection = await puppeteer.connect({
      browserWSEndpoint: inject('browserWSEndpoint'),
      protocolTimeout: 600_000,
    });
    afterAll(async () => {
      await connection?.disconnect();
      connection = null;
    });
  }
  return connection;
}

/**
 * Opens `path` (relative to the server root) and waits until `window.testReady` (or `readyExpr`)
 * resolves. Console errors, page errors and failed requests are collected in `page.problems`.
 * @param {string} path e.g. '/test/pages/blur.html' or '/#sss=0'
 * @param {{ width?: number, height?: number, readyExpr?: string, timeout?: number }} [options]
 */
export async function openPage(path, { width = 320, height = 180, readyExpr = 'window.testReady', timeout = 120_000 } = {}) {
  const b = await browser();
  const page = await b.newPage();
  page.problems = [];
  page.on('console', (msg) => {
    if (msg.type() === 'error') page.problems.push(`console.error: ${msg.text()}`);
  });
  page.on('pageerror', (error) => page.problems.push(`pageerror: ${error.message}`));
  page.on('requestfailed', (req) => page.problems.push(`requestfailed: ${req.url()} ${req.failure()?.errorText}`));
  await page.setViewport({ width, height, deviceScaleFactor: 1 });
  await page.goto(new URL(path, inject('baseUrl')).href, { waitUntil: 'load', timeout });
  await page.waitForFunction(`${readyExpr} !== undefined`, { timeout, polling: 50 });
  await page.evaluate(`Promise.resolve(${readyExpr})`);
  return page;
}

/**
 * Runs `fn(...args)` in the page; it must return a Float32Array (or an object whose `data` is one).
 * The bytes travel as base64 so NaN and Infinity survive (JSON would turn them into null).
 * @returns {Promise<Float32Array | object>}
 */
export async function readFloats(page, fn, ...args) {
  const packed = await page.evaluate(async (source, argList) => {
    // eslint-disable-next-line no-new-func
    const f = new Function(`return (${source})`)();
    const result = await f(...argList);
    const encode = (array) => {
      const bytes = new Uint8Array(array.buffer, array.byteOffset, array.byteLength);
      let binary = '';
      for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(binary);
    };
    if (result instanceof Float32Array) return { data: encode(result) };
    return { ...result, data: encode(result.data) };
  }, fn.toString(), args);
  const bytes = Buffer.from(packed.data, 'base64');
  const data = new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
  return packed.data && Object.keys(packed).length === 1 ? data : { ...packed, data };
}
