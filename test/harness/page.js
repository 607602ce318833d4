// Helpers for browser tests: connect to the run's shared Chromium, open a page served by the run's
// Vite server, collect console errors, and read float pixel data back from the page.
import { inject, afterAll, expect } from 'vitest';
import puppeteer from 'puppeteer-core';
import { openReadyPage } from '../../dev/browser.js';

let connection = null;

// Registered when a test file imports this module, so it runs after that file's tests.
afterAll(async () => {
  await connection?.disconnect();
  connection = null;
});

/** Connects (once per test file) to the browser started in globalSetup. */
export async function browser() {
  connection ??= await puppeteer.connect({
    browserWSEndpoint: inject('browserWSEndpoint'),
    protocolTimeout: 600_000,
  });
  return connection;
}

/**
 * Opens `path` (relative to the server root) and waits until `window.testReady` (or `readyExpr`)
 * resolves (dev/browser.js's openReadyPage, at 320 × 180 unless told otherwise).
 * @param {string} path e.g. '/test/pages/lab.html' or '/#sss=0'
 * @param {{ width?: number, height?: number, readyExpr?: string, timeout?: number, beforeLoad?: (page) => Promise<void> }} [options]
 */
export async function openPage(path, { width = 320, height = 180, ...options } = {}) {
  return openReadyPage(await browser(), new URL(path, inject('baseUrl')).href, { width, height, ...options });
}

/**
 * Opens the lab page (test/pages/lab.html), pushing the text of each console warning it logs
 * into `warnings`.
 * @param {string[]} warnings
 */
export async function openLabPage(warnings) {
  const page = await openPage('/test/pages/lab.html');
  page.on('console', (msg) => { if (msg.type() === 'warn') warnings.push(msg.text()); });
  return page;
}

/** Closes `page` after checking it logged no error, threw nothing and failed no request. */
export async function closeCheckedPage(page) {
  expect(page.problems).toEqual([]);
  await page.close();
}

/**
 * Runs `fn(...args)` in the page and returns its result, with every Float32Array in it (at any
 * depth of plain objects) carried as base64 bytes so NaN and Infinity survive (JSON would turn
 * them into null).
 * @param {import('puppeteer-core').Page} page
 * @param {Function} fn runs in the page: it cannot see this file's variables
 */
export async function evaluateFloats(page, fn, ...args) {
  const packed = await page.evaluate(async (source, argList) => {
    // eslint-disable-next-line no-new-func
    const f = new Function(`return (${source})`)();
    const encode = (value) => {
      if (value instanceof Float32Array) {
        const bytes = new Uint8Array(value.buffer, value.byteOffset, value.byteLength);
        let binary = '';
        for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
        return { __float32: btoa(binary) };
      }
      if (Array.isArray(value)) return value.map(encode);
      if (value && typeof value === 'object') return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, encode(v)]));
      return value;
    };
    return encode(await f(...argList));
  }, fn.toString(), args);
  const decode = (value) => {
    if (value && typeof value === 'object' && typeof value.__float32 === 'string') {
      const bytes = Buffer.from(value.__float32, 'base64');
      return new Float32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
    }
    if (Array.isArray(value)) return value.map(decode);
    if (value && typeof value === 'object') return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, decode(v)]));
    return value;
  };
  return decode(packed);
}

/** Runs `lab.run(options)` in a page opened on test/pages/lab.html (see lab.js for the options). */
export function runLab(page, options) {
  return evaluateFloats(page, (o) => window.lab.run(o), options);
}

/**
 * The page as the visitor sees it: a screenshot, decoded by the browser into 8-bit sRGB RGBA,
 * rows top-down.
 * @param {import('puppeteer').Page} page
 * @returns {Promise<{ width: number, height: number, data: Uint8Array }>}
 */
export async function screenshotPixels(page) {
  const png = await page.screenshot({ encoding: 'base64' });
  const { width, height, bytes } = await page.evaluate(async (data) => {
    const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${data}`)).blob());
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    const px = ctx.getImageData(0, 0, bitmap.width, bitmap.height).data;
    let binary = '';
    for (let i = 0; i < px.length; i += 0x8000) binary += String.fromCharCode(...px.subarray(i, i + 0x8000));
    return { width: bitmap.width, height: bitmap.height, bytes: btoa(binary) };
  }, png);
  return { width, height, data: new Uint8Array(Buffer.from(bytes, 'base64')) };
}
