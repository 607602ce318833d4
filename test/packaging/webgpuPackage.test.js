// The three-separable-sss/webgpu entry as users get it: in package.json's exports with its own
// three floor (subpathPeerDependencies, held equal to src/support/threeVersion.js's WEBGPU_THREE_RANGE), built by Vite's
// library mode into dist/webgpu.js, and imported by plain Node with no DOM and no globals added.
import { describe, it, expect } from 'vitest';
import { build } from 'vite';
import { execFileSync } from 'node:child_process';
import { readFileSync, rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { WEBGPU_THREE, WEBGPU_THREE_RANGE, checkThreeRevision } from '../../src/support/threeVersion.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const pkg = JSON.parse(readFileSync(`${root}package.json`, 'utf8'));
// Inside the repository so that bare imports (three, three/webgpu) resolve from its node_modules.
const outDir = `${root}node_modules/.cache/sss-webgpu-package-test`;

describe('the webgpu entry', () => {
  it("is a subpath export with its own three floor, and refuses an older three by name", () => {
    expect(pkg.exports['./webgpu']).toEqual({ types: './dist/types/webgpu/index.d.ts', import: './dist/webgpu.js', default: './dist/webgpu.js' });
    expect(pkg.subpathPeerDependencies['./webgpu'].three).toBe(WEBGPU_THREE_RANGE);
    expect(() => checkThreeRevision('SubsurfaceScatteringNode', WEBGPU_THREE, '186')).toThrow(/^SubsurfaceScatteringNode: three r186 is not supported \(supported: three >=0\.187\.0 <0\.188\.0, r187 to r187\)$/);
    expect(() => checkThreeRevision('SubsurfaceScatteringNode', WEBGPU_THREE, '187')).not.toThrow();
  });

  it('builds and imports in plain Node without side effects', async () => {
    rmSync(outDir, { recursive: true, force: true });
    await build({ root, configFile: `${root}vite.config.js`, mode: 'lib', logLevel: 'error', build: { outDir, emptyOutDir: true } });
    const script = `
      const before = new Set(Object.getOwnPropertyNames(globalThis));
      const m = await import(${JSON.stringify(`${outDir}/webgpu.js`)});
      const added = Object.getOwnPropertyNames(globalThis).filter((k) => !before.has(k));
      console.log(JSON.stringify({ exports: Object.keys(m).sort(), added, typeofWindow: typeof window, navigator: typeof navigator === 'undefined' ? 'undefined' : typeof navigator.gpu }));`;
    const out = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '--no-deprecation', '-e', script], { encoding: 'utf8' }));
    expect(out.added).toEqual([]);
    expect(out.typeofWindow).toBe('undefined');
    for (const name of ['subsurfaceScattering', 'subsurfaceMaterial', 'subsurfaceMRT', 'SubsurfaceScatteringNode', 'SubsurfaceStandardNodeMaterial', 'SubsurfacePhysicalNodeMaterial']) {
      expect(out.exports).toContain(name);
    }
    rmSync(outDir, { recursive: true, force: true });
  }, 240_000);
});
