// Puppeteer's postinstall would download its own Chrome, which fails on machines that only reach
// the npm registry. The tests use a system Chromium (see test/harness/browser.js for the lookup
// order), so the download is skipped unless PUPPETEER_SKIP_DOWNLOAD=false asks for it.
module.exports = {
  skipDownload: process.env.PUPPETEER_SKIP_DOWNLOAD !== 'false',
};
