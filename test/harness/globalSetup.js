// One browser and one Vite server for the whole test run (vitest globalSetup). Test files connect
// to the browser through its WebSocket endpoint (see page.js). Both are closed in teardown, which
// vitest runs even when tests fail, so no stray processes are left behind.
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { findBrowser } from './findBrowser.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');

// SwiftShader (software WebGL2), and no background network traffic (the machine's network is closed).
export const CHROMIUM_FLAGS = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-quic',
  '--no-first-run',
];

export default async function setup(project) {
  const executablePath = await findBrowser();
  const { createServer } = await import('vite');
  const { default: puppeteer } = await import('puppeteer');

  const server = await createServer({
    root,
    configFile: join(root, 'vite.config.js'),
    logLevel: 'error',
    clearScreen: false,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
  });
  await server.listen();
  const { port } = server.httpServer.address();

  const userDataDir = await mkdtemp(join(tmpdir(), 'sss-chromium-'));
  let browser;
  try {
    browser = await puppeteer.launch({
      executablePath,
      headless: true,
      userDataDir,
      args: CHROMIUM_FLAGS,
      protocolTimeout: 600_000,
    });
  } catch (error) {
    await server.close();
    await rm(userDataDir, { recursive: true, force: true });
    throw error;
  }

  project.provide('browserWSEndpoint', browser.wsEndpoint());
  project.provide('baseUrl', `http://127.0.0.1:${port}`);

  return async function teardown() {
    await browser.close().catch(() => browser.process()?.kill('SIGKILL'));
    await server.close();
    await rm(userDataDir, { recursive: true, force: true });
  };
}
