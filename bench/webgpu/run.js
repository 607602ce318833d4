// `node bench/webgpu/run.js [--quick]`: the WebGPURenderer node's cost beside the WebGL pipeline's
// (bench/webgpu/page.js has the rows and how a frame is timed), in headless Chromium on SwiftShader
// with WebGPU (dev/browser.js's WEBGPU_FLAGS). Writes bench/results/webgpu.json (quick:
// bench/results/tmp/webgpu.json) and prints the medians and the node's cost over each backend's
// plain frame, from the same interleaved rounds.
import { mkdir, writeFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { openReadyPage, startBrowser } from '../../dev/browser.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const quick = process.argv.includes('--quick');
const options = quick ? { width: 320, height: 180, rounds: 3, frames: 3 } : { width: 640, height: 360, rounds: 5, frames: 5 };

const session = await startBrowser({ webgpu: true, protocolTimeout: 900_000 });
try {
  const page = await openReadyPage(session.browser, `${session.baseUrl}/bench/webgpu/index.html`, { timeout: 300_000 });
  const result = await page.evaluate((o) => window.bench.run(o), options);
  const m = result.medianMs;
  const summary = {
    ...result,
    date: new Date().toISOString(),
    flags: session.flags,
    nodeOverPlain: { webgpu: m.webgpuNode / m.webgpuPlain, webgl: m.webglNode / m.webglPlain },
    nodeOverComposer: { webgpu: m.webgpuNode / m.composer, webgl: m.webglNode / m.composer },
    // The frame with the isotropic blur over the same path's frame with one kernel.
    isotropicOverOneKernel: {
      composer: m.composerIsotropic / m.composer,
      webgpu: m.webgpuNodeIsotropic / m.webgpuNode,
      webgl: m.webglNodeIsotropic / m.webglNode,
    },
  };
  const file = join(root, quick ? 'bench/results/tmp/webgpu.json' : 'bench/results/webgpu.json');
  await mkdir(dirname(file), { recursive: true });
  await writeFile(file, `${JSON.stringify(summary, null, 1)}\n`);
  console.log(JSON.stringify({ medianMs: m, nodeOverPlain: summary.nodeOverPlain, nodeOverComposer: summary.nodeOverComposer, isotropicOverOneKernel: summary.isotropicOverOneKernel }, null, 1));
  console.log(`wrote ${file}`);
} finally {
  await session.close();
}
