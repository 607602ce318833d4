// The head asset step (scripts/headAssets.js): checksums, per-file fallthrough between sources,
// the missing case and head-status.json. Everything runs in temp folders; public/ is never touched.

import { existsSync, readdirSync } from 'node:fs';
import { mkdir, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';

import {
  HEAD_FILES,
  HEAD_SHA256,
  HEAD_DOWNLOAD_BASE_URL,
  defaultHeadSources,
  ensureHeadAssets,
  sha256,
} from '../../../scripts/headAssets.js';

const REPO_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const REAL_DIR = path.resolve(REPO_ROOT, '..', 'shared', 'assets', 'LeePerrySmith');

// Five small fake files standing in for the real ones; their hashes replace the pinned table.
const FAKE = Object.fromEntries(HEAD_FILES.map((f, i) => [f, Buffer.from(`fake ${f} #${i}\n`.repeat(3 + i))]));
const FAKE_EXPECTED = Object.fromEntries(HEAD_FILES.map((f) => [f, sha256(FAKE[f])]));

const rejectingFetch = async () => {
  throw new TypeError('fetch failed');
};
const notFoundFetch = async () => ({ ok: false, status: 404, statusText: 'Not Found', arrayBuffer: async () => new ArrayBuffer(0) });

let tmp;
let destDir;
let statusPath;

beforeEach(async () => {
  tmp = await mkdtemp(path.join(os.tmpdir(), 'sss-assets-'));
  destDir = path.join(tmp, 'public', 'assets', 'LeePerrySmith');
  statusPath = path.join(tmp, 'public', 'assets', 'head-status.json');
});

afterEach(async () => {
  await rm(tmp, { recursive: true, force: true });
});

async function makeSource(name, files) {
  const dir = path.join(tmp, name);
  await mkdir(dir, { recursive: true });
  for (const [file, data] of Object.entries(files)) await writeFile(path.join(dir, file), data);
  return { type: 'dir', dir, label: name };
}

function run(sources, extra = {}) {
  return ensureHeadAssets({ destDir, sources, expected: FAKE_EXPECTED, fetchImpl: rejectingFetch, ...extra });
}

describe('ensureHeadAssets', () => {
  it('copies every file from a correct source, byte-identical, and reports complete', async () => {
    const src = await makeSource('good', FAKE);
    const r = await run([src]);
    expect(r.complete).toBe(true);
    expect(r.missing).toEqual([]);
    expect(r.errors).toEqual([]);
    for (const f of HEAD_FILES) {
      expect(r.sources[f]).toBe('good');
      expect((await readFile(path.join(destDir, f))).equals(FAKE[f])).toBe(true);
    }
    const status = JSON.parse(await readFile(statusPath, 'utf8'));
    expect(status).toEqual({ complete: true, missing: [], source: r.sources });
    // no temp files left behind
    expect(readdirSync(destDir).sort()).toEqual([...HEAD_FILES].sort());
  });

  it('rejects a file with a wrong checksum, naming it, and does not copy it', async () => {
    const bad = 'Map-COL.jpg';
    const src = await makeSource('tampered', { ...FAKE, [bad]: Buffer.from('not the colour map') });
    const r = await run([src]);
    expect(r.complete).toBe(false);
    expect(r.missing).toEqual([bad]);
    const err = r.errors.find((e) => e.kind === 'checksum');
    expect(err.file).toBe(bad);
    expect(err.message).toContain(bad);
    expect(err.message).toContain('tampered');
    expect(err.message).toContain(FAKE_EXPECTED[bad]);
    expect(err.message).toContain(sha256(Buffer.from('not the colour map')));
    expect(existsSync(path.join(destDir, bad))).toBe(false);
    for (const f of HEAD_FILES.filter((x) => x !== bad)) expect(existsSync(path.join(destDir, f))).toBe(true);
  });

  it('falls through per file: a file missing (or bad) in the first source comes from the next', async () => {
    const { 'LeePerrySmith.glb': _glb, ...withoutGlb } = FAKE;
    const first = await makeSource('first', { ...withoutGlb, 'Map-SPEC.jpg': Buffer.from('corrupt') });
    const second = await makeSource('second', FAKE);
    const r = await run([first, second]);
    expect(r.complete).toBe(true);
    expect(r.sources['LeePerrySmith.glb']).toBe('second');
    expect(r.sources['Map-SPEC.jpg']).toBe('second');
    expect(r.sources['Map-COL.jpg']).toBe('first');
    expect(r.errors.map((e) => e.file)).toEqual(['Map-SPEC.jpg']);
    for (const f of HEAD_FILES) expect((await readFile(path.join(destDir, f))).equals(FAKE[f])).toBe(true);
  });

  it('with nothing anywhere (empty sources, download failing) reports all five missing and writes head-status.json', async () => {
    const empty = await makeSource('empty', {});
    const absent = { type: 'dir', dir: path.join(tmp, 'does-not-exist'), label: 'absent' };
    const download = { type: 'download', baseUrl: 'https://example.invalid/LeePerrySmith/', label: 'dl' };
    for (const fetchImpl of [rejectingFetch, notFoundFetch]) {
      const r = await run([empty, absent, download], { fetchImpl, offline: false });
      expect(r.complete).toBe(false);
      expect(r.missing).toEqual([...HEAD_FILES]);
      expect(r.sources).toEqual({});
      expect(r.errors.some((e) => e.kind === 'download')).toBe(true);
      const status = JSON.parse(await readFile(statusPath, 'utf8'));
      expect(status).toEqual({ complete: false, missing: [...HEAD_FILES], source: {} });
      expect(readdirSync(destDir)).toEqual([]);
    }
  });

  it('replaces a corrupted file already in the destination from the next source', async () => {
    await mkdir(destDir, { recursive: true });
    for (const f of HEAD_FILES) await writeFile(path.join(destDir, f), FAKE[f]);
    await writeFile(path.join(destDir, 'LeePerrySmith.glb'), 'truncated');
    const src = await makeSource('fresh', FAKE);
    const r = await run([src]);
    expect(r.complete).toBe(true);
    expect(r.sources['LeePerrySmith.glb']).toBe('fresh');
    expect(r.sources['Map-COL.jpg']).toBe('destination (already present)');
    const err = r.errors.find((e) => e.file === 'LeePerrySmith.glb');
    expect(err.message).toContain('LeePerrySmith.glb');
    expect(err.message).toContain(sha256(Buffer.from('truncated')));
    expect((await readFile(path.join(destDir, 'LeePerrySmith.glb'))).equals(FAKE['LeePerrySmith.glb'])).toBe(true);
  });

  it('removes a corrupted destination file even when no source can replace it', async () => {
    await mkdir(destDir, { recursive: true });
    await writeFile(path.join(destDir, 'Map-SPEC.jpg'), 'garbage');
    const r = await run([]);
    expect(r.missing).toContain('Map-SPEC.jpg');
    expect(existsSync(path.join(destDir, 'Map-SPEC.jpg'))).toBe(false);
  });

  it('downloads through fetchImpl from the pinned URL, checking the checksum', async () => {
    const urls = [];
    const fetchImpl = async (url) => {
      urls.push(url);
      const file = decodeURIComponent(url.split('/').pop());
      const data = file === 'Map-SPEC.jpg' ? Buffer.from('evil') : FAKE[file];
      return { ok: true, status: 200, arrayBuffer: async () => data.buffer.slice(data.byteOffset, data.byteOffset + data.length) };
    };
    const download = defaultHeadSources({ repoRoot: tmp, env: {} }).find((s) => s.type === 'download');
    expect(download.baseUrl).toBe(HEAD_DOWNLOAD_BASE_URL);
    expect(HEAD_DOWNLOAD_BASE_URL).toBe('https://raw.githubusercontent.com/mrdoob/three.js/r187/examples/models/gltf/LeePerrySmith/');
    const r = await run([download], { fetchImpl, offline: false });
    expect(urls).toEqual(HEAD_FILES.map((f) => HEAD_DOWNLOAD_BASE_URL + f));
    expect(r.missing).toEqual(['Map-SPEC.jpg']);
    expect(r.errors.find((e) => e.kind === 'checksum').file).toBe('Map-SPEC.jpg');
    expect(existsSync(path.join(destDir, 'Map-SPEC.jpg'))).toBe(false);
    expect(r.sources['LeePerrySmith.glb']).toBe(HEAD_DOWNLOAD_BASE_URL + 'LeePerrySmith.glb');
  });

  it('fails fast offline: a hanging download times out once and is not retried for the other files', async () => {
    let calls = 0;
    const hanging = () => {
      calls++;
      return new Promise(() => {});
    };
    const download = { type: 'download', baseUrl: 'https://example.invalid/', label: 'dl' };
    const t0 = Date.now();
    const r = await run([download], { fetchImpl: hanging, offline: false, timeoutMs: 50 });
    expect(Date.now() - t0).toBeLessThan(2000);
    expect(calls).toBe(1);
    expect(r.missing).toEqual([...HEAD_FILES]);

    calls = 0;
    const r2 = await run([download], { fetchImpl: hanging, offline: true });
    expect(calls).toBe(0);
    expect(r2.complete).toBe(false);
  });

  it('default sources: SSS_ASSETS_DIR first, then ../shared next to the checkout, then the download', () => {
    const s = defaultHeadSources({ repoRoot: '/x/main', env: { SSS_ASSETS_DIR: '/data/head' } });
    expect(s.map((x) => x.type)).toEqual(['dir', 'dir', 'download']);
    expect(s[0].dir).toBe(path.resolve('/data/head'));
    expect(s[1].dir).toBe(path.resolve('/x/shared/assets/LeePerrySmith'));
    expect(defaultHeadSources({ repoRoot: '/x/main', env: {} }).map((x) => x.type)).toEqual(['dir', 'download']);
  });

  it.skipIf(!existsSync(REAL_DIR))(
    `the real scan files in ../shared/assets/LeePerrySmith pass the pinned SHA-256 (skipped when that folder is absent, e.g. a clean CI clone)`,
    async () => {
      const r = await ensureHeadAssets({
        destDir,
        sources: [{ type: 'dir', dir: REAL_DIR, label: 'shared' }],
        offline: true,
      });
      expect(r.errors).toEqual([]);
      expect(r.complete).toBe(true);
      for (const f of HEAD_FILES) {
        const data = await readFile(path.join(destDir, f));
        expect(sha256(data)).toBe(HEAD_SHA256[f]);
        expect(data.equals(await readFile(path.join(REAL_DIR, f)))).toBe(true);
      }
    },
  );
});
