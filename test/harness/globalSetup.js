// One browser and one Vite server for the whole test run (vitest globalSetup), started by the
// project's one launcher (dev/browser.js). The browser and packaging layers (vitest.config.js) both
// name this setup; vitest runs it once per layer in the same process, so the first call starts
// them and the others share them (one Chromium per run). Test files connect to the browser through
// its WebSocket endpoint (see page.js). Both are closed in the last layer's teardown, which vitest
// runs even when tests fail, so no stray processes are left behind.
import { startBrowser } from '../../dev/browser.js';

const shared = Symbol.for('three-separable-sss.testBrowser');

export default async function setup(project) {
  globalThis[shared] ??= { started: startBrowser(), users: 0 };
  const run = globalThis[shared];
  run.users++;
  const { browser, baseUrl, close } = await run.started;
  project.provide('browserWSEndpoint', browser.wsEndpoint());
  project.provide('baseUrl', baseUrl);
  return async () => {
    if (--run.users > 0) return;
    delete globalThis[shared];
    await close();
  };
}
