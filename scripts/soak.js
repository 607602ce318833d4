// The long reliability run: create/dispose cycles, then the soak of test/pages/reliability.js for
// as long as asked (the test suite runs 12 cycles and 1,000 frames of the same):
//   npm run soak -- --minutes 4              frames with option changes and a moving camera and light
//   npm run soak -- --minutes 10 --cycles 300 --every 25
// Every full cycle of option changes (20 changes, `every` frames apart) it prints the frames, the JS
// heap after a garbage collection, the live WebGL objects and three's programs; at the end a
// summary, and exits 1 when the cycles did not return to their baseline, anything grew over the
// second half of the soak, a GL error was raised, a pixel was NaN or a frame check warned.
import { startBrowser } from '../dev/browser.js';

function option(name, fallback) {
  const i = process.argv.indexOf(`--${name}`);
  if (i < 0) return fallback;
  const value = Number(process.argv[i + 1]);
  if (!Number.isFinite(value) || value < 0) throw new RangeError(`soak: --${name} must be a non-negative number, got ${process.argv[i + 1]}`);
  return value;
}

const minutes = option('minutes', 4);
const cycleCount = Math.round(option('cycles', 50));
const every = Math.max(1, Math.round(option('every', 25)));
const gpu = process.argv.includes('--gpu');
/** Heap growth over the second half of the run that counts as a leak, bytes. */
const HEAP_SLACK = 2 * 1024 * 1024;

const mb = (bytes) => `${(bytes / 1048576).toFixed(2)} MB`;

const { browser, baseUrl, close } = await startBrowser({ gpu });
let failed = false;
try {
  const page = await browser.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warn') problems.push(`${m.type()}: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.setViewport({ width: 320, height: 180, deviceScaleFactor: 1 });
  await page.goto(`${baseUrl}/test/pages/reliability.html`, { waitUntil: 'load' });
  await page.waitForFunction('window.testReady === true', { timeout: 120_000 });
  const client = await page.createCDPSession();
  const heap = async () => {
    await client.send('HeapProfiler.collectGarbage');
    await client.send('HeapProfiler.collectGarbage');
    // V8's heap and the array buffers' backing stores (typed arrays live outside it).
    const { usedSize, backingStorageSize = 0 } = await client.send('Runtime.getHeapUsage');
    return usedSize + backingStorageSize;
  };

  if (cycleCount > 0) {
    console.log(`${cycleCount} create → render → dispose cycles...`);
    const c = await page.evaluate((count) => window.reliability.cycles({ count }), cycleCount);
    const same = JSON.stringify(c.after.gl) === JSON.stringify(c.baseline.gl) &&
      JSON.stringify(c.after.memory) === JSON.stringify(c.baseline.memory) && c.after.programs === c.baseline.programs;
    console.log(`cycles: ${c.count} (${c.msPerCycle.toFixed(0)} ms each), live WebGL objects ${c.baseline.total} → ${c.after.total}, ` +
      `renderer.info ${JSON.stringify(c.baseline.memory)} → ${JSON.stringify(c.after.memory)}, programs ${c.baseline.programs} → ${c.after.programs}, ` +
      `errors ${c.errors.length}: ${same && c.errors.length === 0 ? 'back to baseline' : 'NOT back to baseline'}`);
    if (!same) console.log(`  baseline ${JSON.stringify(c.baseline.gl)}\n  after    ${JSON.stringify(c.after.gl)}`);
    if (!same || c.errors.length) failed = true;
  }

  const { cycleFrames, changes } = await page.evaluate((e) => window.reliability.soakStart({ every: e }), every);
  console.log(`soak: ${minutes} min, an option change every ${every} frames, ${changes} changes per cycle (${cycleFrames} frames)`);
  const start = Date.now();
  const rows = [];
  do {
    const t0 = Date.now();
    const s = await page.evaluate((n) => window.reliability.soakRun(n), cycleFrames);
    const h = await heap();
    rows.push({ ...s, heap: h });
    const fps = cycleFrames / ((Date.now() - t0) / 1000);
    console.log(`frames ${String(s.frames).padStart(7)}  changes ${String(s.changes).padStart(5)}  heap ${mb(h)}  ` +
      `WebGL objects ${s.total}  programs ${s.programs}  textures ${s.memory.textures}  GL errors ${s.glErrorCount}  NaN pixels ${s.nonFinite}  (${fps.toFixed(0)} fps)`);
  } while (Date.now() - start < minutes * 60_000);
  const last = await page.evaluate(() => window.reliability.soakStop());
  await client.detach();

  // Flat: over the second half of the run nothing grows. (In the first, three compiles a program
  // for each tap count 'auto' first meets as the camera moves and keeps it on the material until
  // it is disposed, and the kernel and footprint caches fill: bounded, not leaks.)
  const first = rows[0];
  const middle = rows[Math.floor((rows.length - 1) / 2)];
  const end = rows[rows.length - 1];
  const maxHeap = Math.max(...rows.map((r) => r.heap));
  const objectsFlat = rows.slice(rows.indexOf(middle)).every((r) => JSON.stringify(r.gl) === JSON.stringify(middle.gl) &&
    r.programs === middle.programs && JSON.stringify(r.memory) === JSON.stringify(middle.memory));
  const heapGrowth = end.heap - middle.heap;
  const summary = {
    minutes: (Date.now() - start) / 60_000, frames: last.frames, optionChanges: last.changes,
    heap: { afterFirstCycle: first.heap, halfway: middle.heap, end: end.heap, max: maxHeap, growthOverSecondHalf: heapGrowth },
    webglObjects: { afterFirstCycle: first.total, halfway: middle.total, end: end.total, byKind: end.gl, flatOverSecondHalf: objectsFlat },
    programs: end.programs, rendererMemory: end.memory,
    glErrors: last.glErrorCount, nanPixels: last.nonFinite, reads: last.reads, frameProblems: last.problems, pageProblems: problems,
  };
  console.log(`\n${summary.frames} frames, ${summary.optionChanges} option changes in ${summary.minutes.toFixed(1)} min; ` +
    `heap ${mb(first.heap)} → ${mb(middle.heap)} halfway → ${mb(end.heap)} (max ${mb(maxHeap)}); ` +
    `WebGL objects ${first.total} → ${middle.total} → ${end.total}; ` +
    `GL errors ${summary.glErrors}; NaN pixels ${summary.nanPixels} in ${summary.reads} read-backs`);
  console.log(JSON.stringify(summary));
  if (!objectsFlat || heapGrowth > HEAP_SLACK || summary.glErrors || summary.nanPixels || summary.frameProblems.length || problems.length) {
    failed = true;
    console.log('soak: FAILED (objects or heap grew, or a GL error, NaN pixel, frame problem or console error/warning)');
  } else {
    console.log('soak: passed');
  }
} finally {
  await close();
}
process.exit(failed ? 1 : 0);
