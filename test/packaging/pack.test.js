// What `npm pack` publishes (packaging; it builds): the tarball's exact file list, and every entry
// of package.json's "exports" imported from the unpacked tarball in plain Node, as a project that
// installed it would (three and the optional peers resolvable beside it, nothing else).
import { describe, it, expect } from 'vitest';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, renameSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));
const pkg = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));

/** Every file under `dir`, as paths relative to the repository root. */
function filesUnder(dir) {
  return readdirSync(join(root, dir), { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile())
    .map((entry) => relative(root, join(entry.parentPath, entry.name)));
}

/** What the tarball must hold: the built entries, the declarations, the sources, the three documents. */
function expectedFiles() {
  const tracked = execFileSync('git', ['ls-files', 'src', 'shaders'], { cwd: root, encoding: 'utf8' }).trim().split('\n');
  const built = readdirSync(join(root, 'dist')).filter((f) => /\.js(\.map)?$/.test(f)).map((f) => `dist/${f}`);
  return [...tracked, ...built, ...filesUnder('dist/types'), 'README.md', 'LICENSE', 'CHANGELOG.md', 'package.json'].sort();
}

/** The peers a project brings, linked from this repository's node_modules. */
const PEERS = ['three', 'postprocessing', 'react', '@react-three/fiber'];

describe('npm pack', () => {
  it('packs exactly the built entries, declarations, sources, shaders and documents, and each "exports" entry imports from it in plain Node', () => {
    const work = mkdtempSync(join(tmpdir(), 'sss-pack-'));
    try {
      // prepack builds dist/ (the library and its declarations) first.
      const stdout = execFileSync('npm', ['pack', '--json', '--pack-destination', work], { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
      // The build's own output comes first on stdout; npm's JSON report starts at a line "[".
      const [report] = JSON.parse(stdout.slice(stdout.search(/^\[$/m)));
      expect(report.name).toBe('three-separable-sss');
      expect(report.version).toBe(pkg.version);
      // The README's install steps name this tarball.
      expect(readFileSync(join(root, 'README.md'), 'utf8')).toContain(`npm install three /path/to/${report.filename}`);
      const packed = report.files.map((f) => f.path).sort();
      expect(packed).toEqual(expectedFiles());
      for (const path of packed) expect(path).not.toMatch(/^(test|bench|docs|demo|dev|scripts|public|dist\/demo|dist-demo|node_modules)\//);
      for (const entry of ['three-separable-sss.js', 'postprocessing.js', 'react.js']) expect(packed).toContain(`dist/${entry}`);

      // A project with the tarball unpacked as node_modules/three-separable-sss and its peers.
      const app = join(work, 'app');
      mkdirSync(join(app, 'node_modules', '@react-three'), { recursive: true });
      execFileSync('tar', ['-xzf', join(work, report.filename), '-C', join(app, 'node_modules')]);
      renameSync(join(app, 'node_modules', 'package'), join(app, 'node_modules', 'three-separable-sss'));
      for (const peer of PEERS) symlinkSync(join(root, 'node_modules', peer), join(app, 'node_modules', peer), 'dir');
      writeFileSync(join(app, 'package.json'), '{ "private": true, "type": "module" }\n');
      const subpaths = Object.keys(pkg.exports);
      for (const [subpath, conditions] of Object.entries(pkg.exports)) {
        if (typeof conditions === 'object') expect(existsSync(join(app, 'node_modules', 'three-separable-sss', conditions.types)), `${subpath} types`).toBe(true);
      }
      const script = `
        const out = {};
        for (const subpath of ${JSON.stringify(subpaths)}) {
          const specifier = 'three-separable-sss' + subpath.slice(1);
          const m = subpath.endsWith('.json') ? await import(specifier, { with: { type: 'json' } }) : await import(specifier);
          out[subpath] = Object.keys(m).sort();
        }
        const { SubsurfaceScattering } = await import('three-separable-sss');
        out.resolvedFrom = import.meta.resolve('three-separable-sss');
        out.isClass = typeof SubsurfaceScattering === 'function';
        console.log(JSON.stringify(out));`;
      const out = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '--no-deprecation', '-e', script], { cwd: app, encoding: 'utf8' }));
      expect(out.resolvedFrom).toBe(`file://${join(app, 'node_modules', 'three-separable-sss', 'dist', 'three-separable-sss.js')}`);
      expect(out.isClass).toBe(true);
      expect(out['.']).toContain('SubsurfaceScattering');
      expect(out['.']).toContain('getProfile');
      expect(out['./stages']).toContain('makeSubsurface'); // the parts of a hand-built pipeline
      expect(out['./postprocessing']).toEqual(['SubsurfaceScatteringPass']);
      expect(out['./react']).toContain('SubsurfaceComposer');
      expect(out['./package.json']).toEqual(['default']);
    } finally {
      rmSync(work, { recursive: true, force: true });
    }
  }, 300_000);
});
