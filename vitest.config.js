// The test suite in three layers (vitest projects), all run by `npm test`, one after the other:
//   node       pure maths, the float64 oracles, parameter checks, the demo's and bench's pure
//              modules, docs and package metadata: files in parallel, seconds (`npm run test:node`)
//   browser    the pixel tests in the run's one headless Chromium (SwiftShader uses both cores):
//              one file at a time (`npm run test:browser`)
//   packaging  vite builds, tsc on the declarations, the built demo under its CSP and Trusted
//              Types (`npm run test:packaging`, which adds the three-version matrix)
// See docs/TESTING.md for what each layer holds and what it costs.
import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

// The timeouts the suite had as one queue, for every layer: on the shared two-core machine a Node
// case of 1.3 s in the serial queue (standInBust's attribute check) took 5.2 s with the Node files
// in parallel under other sessions' load, past vitest's default of 5 s.
const timeouts = { testTimeout: 180_000, hookTimeout: 240_000 };

// One Chromium and one Vite server for the browser and packaging layers (started once per run).
const browserLayer = {
  globalSetup: ['test/harness/globalSetup.js'],
  fileParallelism: false,
  ...timeouts,
};

export default defineConfig({
  test: {
    reporters: ['default'],
    projects: [
      // vitest's default is one worker fewer than the cores: one on two cores, so no parallelism at all.
      { test: { name: 'node', include: ['test/node/**/*.test.js'], maxWorkers: availableParallelism(), ...timeouts, sequence: { groupOrder: 0 } } },
      { test: { name: 'browser', include: ['test/browser/**/*.test.js'], ...browserLayer, sequence: { groupOrder: 1 } } },
      { test: { name: 'packaging', include: ['test/packaging/**/*.test.js'], ...browserLayer, sequence: { groupOrder: 2 } } },
    ],
  },
});
