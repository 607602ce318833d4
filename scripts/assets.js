#!/usr/bin/env node
// `npm run assets`: put the Lee Perry-Smith head scan into public/assets/LeePerrySmith/ (see
// scripts/headAssets.js for the sources and checks) and write public/assets/head-status.json.
// Exits 0 whether the head is complete or missing (the demo then uses the procedural stand-in);
// exits 1 only on an unexpected failure (e.g. the destination cannot be written).

import { DEFAULT_DEST_DIR, ensureHeadAssets, isOfflineEnv, missingNotice } from './headAssets.js';

try {
  const result = await ensureHeadAssets({
    destDir: DEFAULT_DEST_DIR,
    log: (line) => console.log(line),
    warn: (line) => console.warn(`warning: ${line}`),
    offline: isOfflineEnv(),
  });
  if (!result.complete) {
    const download = result.errors.find((e) => e.kind === 'download');
    if (download) console.log(`(${download.message})`);
    else if (isOfflineEnv()) console.log('(download skipped: SSS_ASSETS_OFFLINE is set)');
    console.log(missingNotice(result.missing, DEFAULT_DEST_DIR));
  }
  process.exitCode = 0;
} catch (err) {
  console.error(`head assets: unexpected failure: ${err?.stack ?? err}`);
  process.exitCode = 1;
}
