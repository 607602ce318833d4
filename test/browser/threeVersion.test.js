// The three release the browser tests run against: the devDependency, or in the version matrix
// (scripts/threeMatrix.js) the one SSS_THREE_REVISION names. Guards the matrix itself: without it
// a broken alias would run the newest three twice and pass.
import { it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { openPage } from '../harness/page.js';

const installed = JSON.parse(readFileSync(new URL('../../node_modules/three/package.json', import.meta.url), 'utf8')).version;

it('the pages run the three release this run is for', async () => {
  const expected = process.env.SSS_THREE_REVISION ?? installed.split('.')[1];
  const page = await openPage('/test/pages/lab.html');
  const revision = await page.evaluate(() => window.lab.THREE.REVISION);
  expect(revision).toBe(expected);
  expect(page.problems).toEqual([]);
  await page.close();
});
