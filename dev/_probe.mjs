import { startBrowser, openReadyPage } from './browser.js';
const s = await startBrowser();
try {
  const page = await openReadyPage(s.browser, `${s.baseUrl}/test/pages/lab.html`, { width: 320, height: 180 });
  const r = await page.evaluate(process.argv[2]);
  console.log(JSON.stringify(r, null, 0)?.slice(0, 6000));
  console.log(page.problems.map((p) => p.slice(0, 2000)).join('\n----\n').slice(0, 4000));
} finally { await s.close(); }
