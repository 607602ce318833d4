// One browser and one Vite server for the whole test run (vitest globalSetup), started by the
// project's one launcher (dev/browser.js). Test files connect to the browser through its WebSocket
// endpoint (see page.js). Both are closed in teardown, which vitest runs even when tests fail, so
// no stray processes are left behind.
import { startBrowser } from '../../dev/browser.js';

export default async function setup(project) {
  const { browser, baseUrl, close } = await startBrowser();
  project.provide('browserWSEndpoint', browser.wsEndpoint());
  project.provide('baseUrl', baseUrl);
  return close;
}
