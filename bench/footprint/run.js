// `npm run bench:footprint [-- --repeat N] [-- --no-browser] [-- --keep-app]`: what the package weighs, as a
// newcomer and a user meet it (issue 35's before/after), read from the tree it runs in:
//   1. source: lines of src/**/*.js and shaders/**/*.glsl, and how many files
//   2. public names per entry of package.json's "exports" (each JS entry, whatever subpaths it
//      lists), imported in Node by the package's own name (Node's self-reference resolves it to the
//      dist/ file the exports map names; the pack step below builds dist/)
//   3. SubsurfaceScattering's public members (from the first entry that exports it): its
//      prototypes' and statics' names and the own names of an instance constructed in Node, without
//      '_' names and those of its base class (three's Pass); those whose JSDoc says @internal or
//      @deprecated (read from the src/ file that declares the class). When it cannot be constructed
//      in Node, the instance of page (b) below gives the own names
//   4. README.md characters
//   5. the bundle cost in a fresh Vite app: `npm pack` (prepack builds dist/), a new app in the
//      system's temp folder (footprint-app-XXXX) installs three and vite (the versions installed
//      here) and the tarball (npm's cache, --prefer-offline, makes that seconds on a rerun), and
//      `vite build`s two pages (bench/footprint/app), each on its own: (a) plain, three +
//      EffectComposer + RenderPass + OutputPass drawing a lit sphere; (b) sss, the same with
//      SubsurfaceScattering in place of the RenderPass, the sphere's material made subsurface, the
//      SpotLight its light. Each build's JS, minified and gzipped (zlib's default level), and (b) - (a)
//   6. both builds served on 127.0.0.1 to headless Chromium (dev/browser.js's flags: SwiftShader;
//      the GPU program caches off, so every load compiles): renderer.info.programs after the first
//      frame and the first frame's time (performance.now around composer.render plus gl.finish and
//      a 1-pixel readPixels), the pages loaded alternately `--repeat` times (default 5), medians;
//      then on the last page (b) `sss.samples` set to every odd value 3..63 and back down, one
//      frame each: the programs after each half, the median frame with a value new to the page (up;
//      not the first frame's 'auto' count) and with one seen before (down), beside the median of 5
//      frames with nothing changed.
// Prints the JSON and writes it to bench/results/footprint-<commit>.json (-dirty when src/,
// shaders/, README.md or package.json differ from the commit); the app's builds, the tarball and a
// screenshot of each page stay in the temp folder (its node_modules too with --keep-app). The pure
// parts: surface.js.
import { execFileSync, spawnSync } from 'node:child_process';
import { createServer } from 'node:http';
import { cp, mkdir, mkdtemp, readFile, readdir, rm, stat, writeFile } from 'node:fs/promises';
import { cpus, loadavg, tmpdir } from 'node:os';
import { dirname, extname, join, relative, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import {
  countLines, exportEntries, exportNames, median, memberTags, membersTagged, publicMembers, sliderSweep, specifierOf,
} from './surface.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const args = process.argv.slice(2);
const repeatAt = args.indexOf('--repeat');
const REPEAT = repeatAt >= 0 ? Math.max(1, Number(args[repeatAt + 1]) || 1) : 5;
const BROWSER = !args.includes('--no-browser');
const KEEP_APP = args.includes('--keep-app');
const log = (...m) => console.error('[footprint]', ...m);

const git = (...a) => execFileSync('git', a, { cwd: root, encoding: 'utf8' }).trimEnd();
const pkg = JSON.parse(await readFile(join(root, 'package.json'), 'utf8'));
const versionOf = async (name) => JSON.parse(await readFile(join(root, 'node_modules', name, 'package.json'), 'utf8')).version;

const commit = git('rev-parse', '--short=7', 'HEAD');
const changed = git('status', '--porcelain', '--untracked-files=all').split('\n').filter(Boolean).map((line) => line.slice(3)).filter((path) => path !== 'node_modules');
const measuredChanged = changed.filter((path) => /^(src|shaders)\//.test(path) || path === 'README.md' || path === 'package.json');
const result = {
  commit,
  date: new Date().toISOString(),
  changedFiles: changed,
  measuredFilesChanged: measuredChanged,
  // The times below are wall-clock on this machine: read them beside its load.
  machine: { cpus: cpus().length, node: process.version, loadAverageAtStart: loadavg().map((l) => +l.toFixed(2)) },
};

// ---- 1. Source lines.
async function filesUnder(dir, ext) {
  const out = [];
  for (const entry of await readdir(join(root, dir), { withFileTypes: true, recursive: true })) {
    if (entry.isFile() && entry.name.endsWith(ext)) out.push(relative(root, join(entry.parentPath ?? entry.path, entry.name)).split(sep).join('/'));
  }
  return out.sort();
}
async function linesOf(files) {
  let lines = 0;
  for (const file of files) lines += countLines(await readFile(join(root, file), 'utf8'));
  return { lines, files: files.length };
}
const js = await linesOf(await filesUnder('src', '.js'));
const glsl = await linesOf(await filesUnder('shaders', '.glsl'));
result.source = { lines: js.lines + glsl.lines, files: js.files + glsl.files, js, glsl };
log(`source: ${result.source.lines} lines in ${result.source.files} files`);

// ---- 4. README.
const readme = await readFile(join(root, 'README.md'), 'utf8');
result.readme = { characters: [...readme].length, bytes: Buffer.byteLength(readme) };

// ---- 5a. The tarball (its prepack builds dist/, which 2 and 3 import).
const work = await mkdtemp(join(tmpdir(), 'footprint-app-'));
log(`npm pack → ${work}`);
const packOutput = execFileSync('npm', ['pack', '--json', '--pack-destination', work], { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });
const packed = JSON.parse(packOutput.slice(packOutput.search(/^\[/m))); // after prepack's own output
const tarball = join(work, packed[0].filename);
result.tarball = { file: packed[0].filename, bytes: packed[0].size, unpackedBytes: packed[0].unpackedSize, files: packed[0].entryCount };

// ---- 2. Public names per entry.
result.entries = {};
const namespaces = [];
for (const { subpath, target } of exportEntries(pkg)) {
  const specifier = specifierOf(pkg.name, subpath);
  try {
    const namespace = await import(specifier);
    namespaces.push({ subpath, namespace });
    const names = exportNames(namespace);
    result.entries[subpath] = { target, ...names };
  } catch (error) {
    result.entries[subpath] = { target, error: String(error.message).split('\n')[0] };
  }
}
result.publicNames = Object.values(result.entries).reduce((sum, e) => sum + (e.count ?? 0), 0);
log(`public names: ${result.publicNames} over ${Object.keys(result.entries).length} entries (${Object.entries(result.entries).map(([k, v]) => `${k} ${v.count ?? v.error}`).join(', ')})`);

// ---- 3. SubsurfaceScattering's members.
const THREE = await import('three');
// The class from the first entry that exports it (the main entry, today), its source from src/.
const home = namespaces.find(({ namespace }) => typeof namespace.SubsurfaceScattering === 'function');
if (!home) throw new Error('no entry of package.json "exports" exports SubsurfaceScattering');
const { SubsurfaceScattering } = home.namespace;
let classFile = null;
for (const file of await filesUnder('src', '.js')) {
  if (/^export class SubsurfaceScattering\b/m.test(await readFile(join(root, file), 'utf8'))) { classFile = file; break; }
}
// The base is three's Pass: classes between it and SubsurfaceScattering (the settings' mixin) are
// the package's own, and their names count.
const { Pass } = await import('three/addons/postprocessing/Pass.js');
let base = Object.getPrototypeOf(SubsurfaceScattering);
for (let c = base; c && c !== Function.prototype; c = Object.getPrototypeOf(c)) if (c === Pass) { base = Pass; break; }
let baseInstance = null;
try { baseInstance = base === Function.prototype ? null : new base(); } catch { /* prototype names only */ }
const baseNames = new Set(baseInstance ? Object.getOwnPropertyNames(baseInstance) : []);
for (let p = base?.prototype; p && p !== Object.prototype; p = Object.getPrototypeOf(p)) for (const n of Object.getOwnPropertyNames(p)) baseNames.add(n);
baseNames.delete('constructor');
const tags = memberTags(classFile ? await readFile(join(root, classFile), 'utf8') : '');
function membersOf(instance, instanceFrom) {
  const m = publicMembers(SubsurfaceScattering, { instance, base: base === Function.prototype ? null : base, baseInstance });
  const onChain = new Set();
  for (let p = SubsurfaceScattering.prototype; p && p !== base?.prototype && p !== Object.prototype; p = Object.getPrototypeOf(p)) for (const n of Object.getOwnPropertyNames(p)) onChain.add(n);
  return {
    count: m.count,
    exportedBy: home.subpath,
    source: classFile,
    instanceFrom,
    ...membersTagged(m.names, tags),
    names: m.names,
    onPrototype: m.prototype,
    static: m.static,
    onInstanceOnly: m.instance,
    baseClass: base?.name ?? null,
    // The base's names the class defines again on its own prototype (not counted above).
    baseNamesRedefined: [...baseNames].filter((n) => onChain.has(n)).sort(),
  };
}
const sceneForNode = new THREE.Scene();
const nodeOptions = { scene: sceneForNode, camera: new THREE.PerspectiveCamera(30, 16 / 9, 0.01, 10), light: new THREE.SpotLight(), worldUnitInMm: 1000 };
try {
  result.members = membersOf(new SubsurfaceScattering(nodeOptions), 'node');
} catch (error) {
  result.members = { ...membersOf(null, null), nodeConstructError: String(error.message).split('\n')[0] };
}
log(`SubsurfaceScattering: ${result.members.count} public members (instance from ${result.members.instanceFrom ?? 'nowhere yet'}), ${result.members.internal.length} @internal, ${result.members.deprecated.length} @deprecated`);

// ---- 5b. The fresh Vite app and its two builds.
const app = join(work, 'app');
await cp(join(root, 'bench/footprint/app'), app, { recursive: true });
const versions = { three: await versionOf('three'), vite: await versionOf('vite') };
await writeFile(join(app, 'package.json'), `${JSON.stringify({ name: 'footprint-app', private: true, type: 'module' }, null, 1)}\n`);
log(`npm install three@${versions.three} vite@${versions.vite} ${packed[0].filename}`);
const t0 = performance.now();
execFileSync('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', '--loglevel=error', `three@${versions.three}`, `vite@${versions.vite}`, tarball], { cwd: app, stdio: ['ignore', 'ignore', 'inherit'] });
result.app = { dir: app, versions, installSeconds: +((performance.now() - t0) / 1000).toFixed(1) };

async function jsSizes(dir) {
  let minified = 0;
  let gzip = 0;
  const files = {};
  for (const entry of await readdir(dir, { withFileTypes: true, recursive: true })) {
    if (!entry.isFile() || !/\.m?js$/.test(entry.name)) continue;
    const code = await readFile(join(entry.parentPath ?? entry.path, entry.name));
    const z = gzipSync(code).length;
    files[relative(dir, join(entry.parentPath ?? entry.path, entry.name))] = { minified: code.length, gzip: z };
    minified += code.length;
    gzip += z;
  }
  return { minified, gzip, files };
}
const vite = join(app, 'node_modules/vite/bin/vite.js');
result.bundle = {};
for (const page of ['plain', 'sss']) {
  const build = spawnSync(process.execPath, [vite, 'build', page, '--outDir', `../dist/${page}`, '--emptyOutDir', '--base', './', '--logLevel', 'warn'], { cwd: app, encoding: 'utf8' });
  if (build.status !== 0) throw new Error(`vite build ${page} failed:\n${build.stdout}\n${build.stderr}`);
  result.bundle[page] = await jsSizes(join(app, 'dist', page));
}
result.bundle.cost = {
  minified: result.bundle.sss.minified - result.bundle.plain.minified,
  gzip: result.bundle.sss.gzip - result.bundle.plain.gzip,
};
log(`bundle: plain ${kB(result.bundle.plain.gzip)} gzip / ${kB(result.bundle.plain.minified)} min; sss ${kB(result.bundle.sss.gzip)} / ${kB(result.bundle.sss.minified)}; cost +${kB(result.bundle.cost.gzip)} gzip, +${kB(result.bundle.cost.minified)} min`);

// ---- 6. Programs and the first frame, in Chromium.
if (BROWSER) {
  try {
    result.browser = await measureInBrowser(join(app, 'dist'));
  } catch (error) {
    result.browser = { error: String(error.stack ?? error) };
    log(`the browser step failed: ${error.message}`);
  }
  if (!result.members.instanceFrom && result.browser.sssOwnNames) {
    // Not constructible in Node: the page's instance gives the own names (the bundle keeps public
    // property names; its class is the same source).
    const names = result.browser.sssOwnNames;
    const fake = Object.fromEntries(names.map((n) => [n, true]));
    result.members = { ...membersOf(fake, 'browser'), nodeConstructError: result.members.nodeConstructError };
  }
  delete result.browser.sssOwnNames;
}

result.machine.loadAverageAtEnd = loadavg().map((l) => +l.toFixed(2));
const dirty = measuredChanged.length ? '-dirty' : '';
const outFile = join(root, `bench/results/footprint-${commit}${dirty}.json`);
await mkdir(dirname(outFile), { recursive: true });
const json = JSON.stringify(result, null, 1);
await writeFile(outFile, `${json}\n`);
console.log(json);
// The app's node_modules go (60 MB a run); its pages, builds, the tarball and the screenshots stay.
if (!KEEP_APP) await rm(join(app, 'node_modules'), { recursive: true, force: true });
log(`wrote ${relative(root, outFile)}; the app's builds and screenshots stay in ${work}${KEEP_APP ? ' (its node_modules too)' : ''}`);

function kB(bytes) { return `${(bytes / 1000).toFixed(1)} kB`; }

async function measureInBrowser(distDir) {
  const { findBrowser, chromiumFlags } = await import(join(root, 'dev/browser.js'));
  const { default: puppeteer } = await import('puppeteer-core');
  const server = await serveStatic(distDir);
  const userDataDir = await mkdtemp(join(tmpdir(), 'footprint-chromium-'));
  const flags = [...chromiumFlags(), '--disable-gpu-program-cache', '--disable-gpu-shader-disk-cache'];
  const browser = await puppeteer.launch({ executablePath: await findBrowser(), headless: true, userDataDir, args: flags, protocolTimeout: 600_000 });
  const out = { chromium: await browser.version(), flags, firstFrame: { plain: [], sss: [] } };
  try {
    let lastSss = null;
    for (let round = 0; round < REPEAT; round++) {
      for (const name of ['plain', 'sss']) {
        if (lastSss) { await lastSss.close(); lastSss = null; }
        const page = await openApp(browser, `${server.url}/${name}/index.html`);
        const first = await page.evaluate(frameInPage, true);
        if (round === 0) await page.screenshot({ path: join(dirname(distDir), `${name}.png`) });
        const steady = [];
        for (let i = 0; i < 5; i++) steady.push((await page.evaluate(frameInPage, false)).ms);
        out.firstFrame[name].push({ ...first, steadyMedianMs: median(steady), warnings: page.warnings, problems: page.problems });
        if (name === 'sss' && round === REPEAT - 1) lastSss = page; else await page.close();
      }
    }
    for (const name of ['plain', 'sss']) {
      const runs = out.firstFrame[name];
      out[name] = {
        programsAfterFirstFrame: runs[0].programs,
        firstFrameMs: median(runs.map((r) => r.ms)),
        steadyFrameMs: median(runs.map((r) => r.steadyMedianMs)),
      };
    }
    out.firstFrameCostMs = Math.round((out.sss.firstFrameMs - out.plain.firstFrameMs) * 10) / 10;
    out.sssOwnNames = await lastSss.evaluate(() => Object.getOwnPropertyNames(window.app.sss));
    log(`first frame: plain ${out.plain.firstFrameMs.toFixed(0)} ms, sss ${out.sss.firstFrameMs.toFixed(0)} ms (+${out.firstFrameCostMs.toFixed(0)}); a steady frame ${out.plain.steadyFrameMs.toFixed(0)} / ${out.sss.steadyFrameMs.toFixed(0)} ms`);
    // The slider, on the last page (b): on its own, so that a refused value keeps the rest.
    try {
      out.slider = await slider(lastSss, out.firstFrame.sss.at(-1).plan?.samples ?? null);
      log(`programs: plain ${out.plain.programsAfterFirstFrame}, sss ${out.sss.programsAfterFirstFrame} after the first frame, ${out.slider.programsAfterUp} after the slider up, ${out.slider.programsAfterDown} after down; a new samples value ${out.slider.newValueMedianMs.toFixed(0)} ms, a seen one ${out.slider.seenValueMedianMs.toFixed(0)} ms`);
    } catch (error) {
      out.slider = { error: String(error.message).split('\n')[0], problems: lastSss.problems };
      log(`the slider failed: ${out.slider.error}`);
    }
    await lastSss.close();
  } finally {
    await browser.close().catch(() => browser.process()?.kill('SIGKILL'));
    await new Promise((resolve) => server.close(resolve));
    await rm(userDataDir, { recursive: true, force: true });
  }
  return out;
}

/** `sss.samples` over every odd value 3..63 and back down, one frame each. */
async function slider(page, firstPlanSamples) {
  const { up, down } = sliderSweep(3, 63);
  const sweep = await page.evaluate(async (upValues, downValues) => {
    const { sss } = window.app;
    const frame = window.__footprintFrame;
    const run = (values) => values.map((v) => { sss.samples = v; return { samples: v, ...frame(false) }; });
    const before = sss.samples;
    const upRuns = run(upValues);
    const downRuns = run(downValues);
    return { samplesBefore: before, up: upRuns, down: downRuns };
  }, up, down);
  return {
    values: `odd 3..63 (${up.length}), then 61..3 (${down.length}), one frame each`,
    samplesBefore: sweep.samplesBefore,
    programsAfterUp: sweep.up.at(-1).programs,
    programsAfterDown: sweep.down.at(-1).programs,
    // A new value: one no frame of this page drew with before (the first frame's 'auto' choice
    // included, as plan.samples says it).
    newValueMedianMs: median(sweep.up.filter((r) => r.samples !== firstPlanSamples).map((r) => r.ms)),
    firstFrameSamples: firstPlanSamples,
    seenValueMedianMs: median(sweep.down.map((r) => r.ms)),
    frames: [...sweep.up, ...sweep.down].map((r) => [r.samples, r.ms, r.programs]),
    problems: page.problems,
  };
}

// Runs in the page: one composer.render fenced by gl.finish and a 1-pixel readPixels (the centre,
// reported on the first frame as a check that the sphere was drawn).
function frameInPage(first) {
  window.__footprintFrame ??= (isFirst) => {
    const { renderer, composer } = window.app;
    const gl = renderer.getContext();
    const pixel = new Uint8Array(4);
    const t = performance.now();
    composer.render();
    gl.finish();
    gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    const ms = Math.round((performance.now() - t) * 10) / 10;
    const out = { ms, programs: renderer.info.programs.length };
    if (isFirst) out.centrePixel = [...pixel];
    const plan = window.app.sss?.plan;
    if (isFirst && plan) out.plan = { blur: plan.blur, samples: plan.samples, kernelPixels: plan.kernelPixels };
    return out;
  };
  return window.__footprintFrame(first);
}

async function openApp(browser, url) {
  const page = await browser.newPage();
  page.problems = [];
  page.warnings = [];
  page.on('console', (msg) => {
    if (msg.type() === 'error') page.problems.push(`console.error: ${msg.text()}`);
    if (msg.type() === 'warn' || msg.type() === 'warning') page.warnings.push(msg.text());
  });
  let failed;
  const pageFailed = new Promise((resolve) => { failed = resolve; });
  page.on('pageerror', (error) => { page.problems.push(`pageerror: ${error.message}`); failed(); });
  page.on('requestfailed', (req) => page.problems.push(`requestfailed: ${req.url()} ${req.failure()?.errorText}`));
  await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
  await page.goto(url, { waitUntil: 'load', timeout: 120_000 });
  // Ready when the page set window.app, or failed (a page error: no point waiting).
  const appSet = page.waitForFunction('window.app !== undefined', { timeout: 120_000, polling: 50 });
  await Promise.race([appSet, pageFailed.then(() => new Promise((resolve) => setTimeout(resolve, 1000)))]).catch(() => {});
  appSet.catch(() => {});
  const ready = await page.evaluate(() => window.app !== undefined);
  if (!ready) throw new Error(`${url} set no window.app: ${page.problems.join('; ') || 'no error reported'}`);
  return page;
}

function serveStatic(dir) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.map': 'application/json' };
  const server = createServer(async (req, res) => {
    const path = join(dir, decodeURIComponent(new URL(req.url, 'http://x').pathname));
    if (!path.startsWith(dir)) { res.writeHead(403).end(); return; }
    try {
      const file = (await stat(path)).isDirectory() ? join(path, 'index.html') : path;
      const body = await readFile(file);
      res.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => {
    server.url = `http://127.0.0.1:${server.address().port}`;
    resolve(server);
  }));
}
