// The WebGPURenderer tests' browser: a second headless Chromium with dev/browser.js's WebGPU
// SwiftShader flags (the run's shared browser has WebGL only), started once per test file that
// imports this module and closed after its tests. Pages come from the run's Vite server
// (http://127.0.0.1: a secure context, which WebGPU needs).
import { inject, afterAll } from 'vitest';
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import puppeteer from 'puppeteer-core';
import { chromiumFlags, findBrowser, openReadyPage } from '../../dev/browser.js';

let launched = null;

afterAll(async () => {
  if (!launched) return;
  const { browser, userDataDir } = await launched;
  launched = null;
  await browser.close().catch(() => browser.process()?.kill('SIGKILL'));
  await rm(userDataDir, { recursive: true, force: true });
});

async function launch() {
  const userDataDir = await mkdtemp(join(tmpdir(), 'sss-chromium-webgpu-'));
  const browser = await puppeteer.launch({
    executablePath: await findBrowser(), headless: true, userDataDir, args: chromiumFlags({ webgpu: true }), protocolTimeout: 600_000,
  });
  return { browser, userDataDir };
}

/**
 * Opens `path` of the run's server in the WebGPU browser (openReadyPage, 320 × 180 unless told otherwise).
 * @param {string} path e.g. '/test/pages/webgpu.html'
 * @param {{ width?: number, height?: number, readyExpr?: string, timeout?: number }} [options]
 */
export async function openWebgpuPage(path, { width = 320, height = 180, timeout = 240_000, ...options } = {}) {
  launched ??= launch();
  const { browser } = await launched;
  return openReadyPage(browser, new URL(path, inject('baseUrl')).href, { width, height, timeout, ...options });
}

/** The backends every WebGPURenderer test runs on: WebGPU, and WebGL 2 (forceWebGL). */
export const BACKENDS = Object.freeze(['webgpu', 'webgl']);
