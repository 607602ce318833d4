import { startBrowser, openReadyPage } from './browser.js';
const s = await startBrowser();
try {
  const page = await openReadyPage(s.browser, `${s.baseUrl}/test/pages/lab.html`, { width: 320, height: 180 });
  const code = process.argv[2];
  const r = await page.evaluate(code);
  console.log(JSON.stringify(r, null, 1)?.slice(0, 4000));
  console.log(page.problems.map((p) => p.slice(0, 3000)).join('\n----\n').slice(0, 6000));
} finally { await s.close(); }
