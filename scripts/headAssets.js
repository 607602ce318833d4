// Head asset step: puts the Lee Perry-Smith head scan into public/assets/LeePerrySmith/.
//
// "Infinite, 3D Head Scan" by Lee Perry-Smith (Infinite-Realities), CC BY 3.0, as distributed with
// the three.js examples (examples/models/gltf/LeePerrySmith/). The files are never committed: this
// step copies them from a local folder or downloads them from a pinned three.js release, and every
// file is checked against the SHA-256 pinned below before it is used.
//
// Sources are tried per file, in order, and the first one that yields the file with the right
// checksum wins:
//   1. the file already in the destination (a bad one is removed and reported),
//   2. the folder named by SSS_ASSETS_DIR,
//   3. ../shared/assets/LeePerrySmith relative to the repository root,
//   4. raw.githubusercontent.com/mrdoob/three.js/<THREE_RELEASE>/examples/models/gltf/LeePerrySmith/
//      (skipped with SSS_ASSETS_OFFLINE=1; 15 s timeout per file; the first network failure skips
//      the download source for the remaining files so an offline machine fails fast).
//
// The outcome is written to <destDir>/../head-status.json:
//   { "complete": bool, "missing": [file names], "source": { file: sourceDescription } }
// which the demo reads to choose between the scan and the procedural stand-in bust.

import { createHash, randomBytes } from 'node:crypto';
import { mkdir, readFile, rename, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** Pinned SHA-256 of each file (the truth; copied from the reference SHA256SUMS, never read at run time). */
export const HEAD_SHA256 = Object.freeze({
  'LeePerrySmith.glb': '402b8a8ac9f03232e6d64b5962929703a069daf99d3c49ac8eb0e48bedc9c576',
  'Map-COL.jpg': 'e976d73b31407f8d0967412bf468019ed26a5d5a32cf5811aabff7e816458a65',
  'Map-SPEC.jpg': 'cbb96b60e355b804d9b6c7338372d13ec8cc7adf664f50a00a3d32c66afd293a',
  'Infinite-Level_02_Tangent_SmoothUV.jpg': '36925e51ad9b324b94e8faf4692da1b4132809f2762bb8d5bd549ffd215d4ca6',
  'LeePerrySmith_License.txt': '7cf4da43a6ae6d32f7f7d063fe129a19468af6f4fe7c53b937f83959709fcb50',
});

export const HEAD_FILES = Object.freeze(Object.keys(HEAD_SHA256));

/** three.js release tag the download is pinned to. */
export const THREE_RELEASE = 'r187';
export const HEAD_DOWNLOAD_BASE_URL =
  `https://raw.githubusercontent.com/mrdoob/three.js/${THREE_RELEASE}/examples/models/gltf/LeePerrySmith/`;
export const DOWNLOAD_TIMEOUT_MS = 15000;

export const REPO_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const DEFAULT_DEST_DIR = path.join(REPO_ROOT, 'public', 'assets', 'LeePerrySmith');

export function sha256(buffer) {
  return createHash('sha256').update(buffer).digest('hex');
}

/**
 * The default source list: SSS_ASSETS_DIR (when set), ../shared/assets/LeePerrySmith next to the
 * checkout, then the pinned download.
 * A source is { type: 'dir', dir, label } or { type: 'download', baseUrl, label }.
 */
export function defaultHeadSources({ repoRoot = REPO_ROOT, env = process.env } = {}) {
  const sources = [];
  if (env.SSS_ASSETS_DIR) {
    const dir = path.resolve(env.SSS_ASSETS_DIR);
    sources.push({ type: 'dir', dir, label: `SSS_ASSETS_DIR (${dir})` });
  }
  const shared = path.resolve(repoRoot, '..', 'shared', 'assets', 'LeePerrySmith');
  sources.push({ type: 'dir', dir: shared, label: shared });
  sources.push({ type: 'download', baseUrl: HEAD_DOWNLOAD_BASE_URL, label: `three.js ${THREE_RELEASE} download` });
  return sources;
}

export function isOfflineEnv(env = process.env) {
  const v = String(env.SSS_ASSETS_OFFLINE ?? '').trim().toLowerCase();
  return v !== '' && v !== '0' && v !== 'false' && v !== 'no';
}

async function exists(file) {
  try {
    return (await stat(file)).isFile();
  } catch {
    return false;
  }
}

/** Write via a temp name in the same folder, then rename: never a half-written file under `file`. */
async function writeAtomic(file, data) {
  const tmp = `${file}.tmp-${process.pid}-${randomBytes(4).toString('hex')}`;
  try {
    await writeFile(tmp, data);
    await rename(tmp, file);
  } catch (err) {
    await rm(tmp, { force: true });
    throw err;
  }
}

/** fetch with a hard timeout covering both the request and the body. */
async function fetchBytes(fetchImpl, url, timeoutMs) {
  const controller = new AbortController();
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => {
      controller.abort();
      reject(Object.assign(new Error(`timed out after ${timeoutMs} ms`), { network: true }));
    }, timeoutMs);
  });
  try {
    return await Promise.race([
      (async () => {
        let res;
        try {
          res = await fetchImpl(url, { signal: controller.signal });
        } catch (err) {
          const cause = err?.cause?.code || err?.cause?.message || err?.message || String(err);
          throw Object.assign(new Error(`network error (${cause})`), { network: true });
        }
        if (!res || !res.ok) {
          throw new Error(`HTTP ${res ? `${res.status} ${res.statusText ?? ''}`.trim() : 'no response'}`);
        }
        return Buffer.from(await res.arrayBuffer());
      })(),
      timeout,
    ]);
  } finally {
    clearTimeout(timer);
  }
}

function checksumError(file, sourceLabel, expected, actual) {
  return {
    file,
    source: sourceLabel,
    kind: 'checksum',
    expected,
    actual,
    message: `${file} from ${sourceLabel}: SHA-256 mismatch (expected ${expected}, got ${actual}); file rejected`,
  };
}

/**
 * Ensure the head files are in `destDir`, checksum-verified.
 *
 * @param {object} [opts]
 * @param {string} [opts.destDir]        destination folder (default public/assets/LeePerrySmith)
 * @param {Array}  [opts.sources]        source list overriding defaultHeadSources()
 * @param {object} [opts.expected]       { fileName: sha256 } overriding HEAD_SHA256 (tests)
 * @param {(line: string) => void} [opts.log]   one line per file at most (default: silent)
 * @param {(line: string) => void} [opts.warn]  rejected files (default: opts.log)
 * @param {Function} [opts.fetchImpl]    fetch implementation (default globalThis.fetch)
 * @param {boolean} [opts.offline]       skip download sources (default: SSS_ASSETS_OFFLINE)
 * @param {number}  [opts.timeoutMs]     per-file download timeout (default 15000)
 * @param {string|null} [opts.statusPath] head-status.json path (default <destDir>/../head-status.json; null: don't write)
 * @returns {Promise<{complete: boolean, missing: string[], sources: Record<string, string>, errors: object[], statusPath: string|null}>}
 */
export async function ensureHeadAssets({
  destDir = DEFAULT_DEST_DIR,
  sources,
  expected = HEAD_SHA256,
  log = () => {},
  warn,
  fetchImpl = globalThis.fetch,
  offline = isOfflineEnv(),
  timeoutMs = DOWNLOAD_TIMEOUT_MS,
  statusPath,
} = {}) {
  warn ??= log;
  sources ??= defaultHeadSources();
  if (statusPath === undefined) statusPath = path.join(path.dirname(destDir), 'head-status.json');

  await mkdir(destDir, { recursive: true });

  const files = Object.keys(expected);
  const found = {};
  const errors = [];
  const missing = [];
  const unreachable = new Set(); // download sources that failed at the network level
  let quietSoFar = true; // all files already present: print one summary line instead of five

  const reject = (err) => {
    errors.push(err);
    warn(err.message);
  };

  for (const file of files) {
    const want = String(expected[file]).toLowerCase();
    const dest = path.join(destDir, file);

    // 1. already in the destination
    if (await exists(dest)) {
      const actual = sha256(await readFile(dest));
      if (actual === want) {
        found[file] = 'destination (already present)';
        continue;
      }
      await rm(dest, { force: true });
      reject({
        ...checksumError(file, `destination ${destDir}`, want, actual),
        message: `${file} in destination ${destDir}: SHA-256 mismatch (expected ${want}, got ${actual}); removed`,
      });
    }
    quietSoFar = false;

    // 2.. the sources, in order
    for (const source of sources) {
      let data;
      let where;
      if (source.type === 'dir') {
        if (!source.dir) continue;
        const from = path.join(source.dir, file);
        if (!(await exists(from))) continue;
        data = await readFile(from);
        where = source.label ?? source.dir;
      } else if (source.type === 'download') {
        if (offline || unreachable.has(source) || typeof fetchImpl !== 'function') continue;
        const url = new URL(file, source.baseUrl).href;
        where = url;
        try {
          data = await fetchBytes(fetchImpl, url, timeoutMs);
        } catch (err) {
          if (err.network) unreachable.add(source);
          errors.push({ file, source: url, kind: 'download', message: `${file}: download from ${url} failed: ${err.message}` });
          continue;
        }
      } else {
        throw new Error(`unknown head asset source type: ${JSON.stringify(source)}`);
      }
      const actual = sha256(data);
      if (actual !== want) {
        reject(checksumError(file, where, want, actual));
        continue;
      }
      await writeAtomic(dest, data);
      found[file] = where;
      break;
    }

    if (found[file]) log(`head asset ${file}: ok (from ${found[file]})`);
    else missing.push(file);
  }

  const complete = missing.length === 0;
  if (complete && quietSoFar) log(`head assets: complete (${files.length} files already present in ${destDir})`);

  if (statusPath) {
    const status = { complete, missing, source: found };
    await mkdir(path.dirname(statusPath), { recursive: true });
    await writeAtomic(statusPath, `${JSON.stringify(status, null, 2)}\n`);
  }

  return { complete, missing, sources: found, errors, statusPath };
}

/** The notice printed when the head is incomplete. */
export function missingNotice(missing, destDir = DEFAULT_DEST_DIR) {
  return [
    `head assets: ${missing.length} file(s) missing: ${missing.join(', ')}.`,
    'The demo will use the procedural stand-in bust. To get the Lee Perry-Smith scan (CC BY 3.0), either:',
    '  - set SSS_ASSETS_DIR to a folder holding the files, or',
    `  - put the files in ${destDir}, or`,
    `  - go online (unset SSS_ASSETS_OFFLINE) to download them from three.js ${THREE_RELEASE}:`,
    `    ${HEAD_DOWNLOAD_BASE_URL}`,
    'then run `npm run assets` again.',
  ].join('\n');
}
