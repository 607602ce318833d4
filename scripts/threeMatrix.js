// The version matrix's other end: runs the core browser tests against the oldest supported three
// release (src/support/threeVersion.js), installed from the npm registry into its own folder
// (node_modules/.cache/three-matrix/, once) and served to the pages in place of the devDependency
// through vite.config.js's SSS_THREE_DIR alias. `npm test` covers the newest release.
//   node scripts/threeMatrix.js            the oldest supported release
//   node scripts/threeMatrix.js 0.175.0    another release (to try one before widening the range)
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { SUPPORTED_THREE } from '../src/support/threeVersion.js';

const root = fileURLToPath(new URL('..', import.meta.url));
const version = process.argv[2] ?? `0.${SUPPORTED_THREE.oldest}.0`;
if (!/^0\.\d+\.\d+$/.test(version)) throw new RangeError(`threeMatrix: version must look like 0.168.0, got ${version}`);

/** What the matrix runs: the pipeline's core (blur, transmittance, the drop-in pass), the integrations and the reliability suite (bad inputs, leaks, soak, context loss). */
const CORE_TESTS = [
  'test/browser/threeVersion.test.js', // first: fails at once if the alias did not take
  'test/browser/3-blur/blur.test.js',
  'test/browser/1-light-depth/transmittance.test.js',
  'test/browser/dropIn.test.js',
  'test/browser/integrations/postprocessing.test.js',
  'test/browser/integrations/r3f.test.js',
  'test/browser/reliability.test.js',
];

const folder = `${root}node_modules/.cache/three-matrix/${version}`;
const threeDir = `${folder}/node_modules/three`;
const installed = existsSync(`${threeDir}/package.json`) && JSON.parse(readFileSync(`${threeDir}/package.json`, 'utf8')).version;
if (installed !== version) {
  console.log(`three ${version}: installing into ${folder}`);
  mkdirSync(folder, { recursive: true });
  writeFileSync(`${folder}/package.json`, '{ "private": true }\n');
  execFileSync('npm', ['install', '--no-audit', '--no-fund', '--no-package-lock', '--prefix', folder, `three@${version}`], { stdio: 'inherit' });
}

console.log(`three ${version}: ${CORE_TESTS.length} browser test files`);
const run = spawnSync('npx', ['vitest', 'run', ...CORE_TESTS], {
  cwd: root,
  stdio: 'inherit',
  env: { ...process.env, SSS_THREE_DIR: threeDir, SSS_THREE_REVISION: version.split('.')[1] },
});
process.exit(run.status ?? 1);
