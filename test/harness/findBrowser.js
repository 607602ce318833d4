// Locates the Chromium the browser tests drive, in the order the project promises:
// 1. PUPPETEER_EXECUTABLE_PATH, 2. Debian's chromium package, 3. a Chrome puppeteer downloaded itself.
// When none is found and we run as root on Debian, Debian's `chromium` is installed (what CI needs);
// otherwise the caller gets a one-line message saying what to install.
import { existsSync, readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';

export const DEBIAN_CHROMIUM = '/usr/lib/chromium/chromium';

const INSTALL_HINT =
  'No Chromium found for the browser tests: install Debian\'s "chromium" package ' +
  '(apt-get install chromium), or set PUPPETEER_EXECUTABLE_PATH, or run ' +
  '"PUPPETEER_SKIP_DOWNLOAD=false npx puppeteer browsers install chrome".';

/** @returns {Promise<string|null>} the path of a usable browser, or null. */
export async function lookupBrowser() {
  const fromEnv = process.env.PUPPETEER_EXECUTABLE_PATH;
  if (fromEnv) {
    if (existsSync(fromEnv)) return fromEnv;
    throw new Error(`PUPPETEER_EXECUTABLE_PATH points to a missing file: ${fromEnv}`);
  }
  if (existsSync(DEBIAN_CHROMIUM)) return DEBIAN_CHROMIUM;
  try {
    const { default: puppeteer } = await import('puppeteer');
    const own = puppeteer.executablePath();
    if (own && existsSync(own)) return own;
  } catch {
    // puppeteer has no browser of its own: fall through.
  }
  return null;
}

function isRootOnDebian() {
  return process.getuid?.() === 0 && existsSync('/etc/debian_version') &&
    /debian/i.test(readFileSync('/etc/os-release', 'utf8'));
}

/** Finds a browser, installing Debian's chromium when that is possible; throws a one-line hint otherwise. */
export async function findBrowser({ log = console.log } = {}) {
  let path = await lookupBrowser();
  if (path) return path;
  if (isRootOnDebian()) {
    log('No Chromium found: installing Debian\'s chromium package (root on Debian)...');
    const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
    execFileSync('apt-get', ['update', '-qq'], { stdio: 'inherit', env });
    execFileSync('apt-get', ['install', '-y', '-qq', 'chromium'], { stdio: 'inherit', env });
    path = await lookupBrowser();
    if (path) return path;
  }
  throw new Error(INSTALL_HINT);
}
