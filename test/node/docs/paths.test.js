// Every repository path the docs (*.md) and the code's comments name exists: a moved or deleted
// file leaves no stale pointer behind (issue 18 found four in comments). The names are parsed, not
// listed: `dir/file.ext` with or without backticks, resolved against the repository root, the
// file's own folder or its top folder (src/ names its modules under src/); GLSL chunks also under
// shaders/, as #include names them. Package paths (three/addons/..., the dependencies' own files),
// URLs and what a build or a run writes (dist/, bench/results/tmp/, ...: .gitignore) are not
// repository paths. The notebook (docs/notebook/) is a record of past runs and is not checked.
import { describe, it, expect } from 'vitest';
import { readFileSync, existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../../', import.meta.url));

/** The comment text of a JS/TS/GLSL/CSS/HTML source (strings skipped), lines kept apart. */
export function commentsOf(text) {
  const out = [];
  let i = 0;
  const until = (close, from) => { const e = text.indexOf(close, from); return e < 0 ? text.length : e; };
  while (i < text.length) {
    if (text.startsWith('//', i)) { const end = until('\n', i); out.push(text.slice(i + 2, end)); i = end; }
    else if (text.startsWith('/*', i)) { const end = until('*/', i + 2); out.push(text.slice(i + 2, end)); i = end + 2; }
    else if (text.startsWith('<!--', i)) { const end = until('-->', i + 4); out.push(text.slice(i + 4, end)); i = end + 3; }
    else if (`'"\``.includes(text[i])) {
      const quote = text[i++];
      while (i < text.length && text[i] !== quote && (quote === '`' || text[i] !== '\n')) i += text[i] === '\\' ? 2 : 1;
      i++;
    } else i++;
  }
  return out.join('\n');
}

const EXTENSIONS = 'm?js|jsx|tsx?|glsl|md|json|html|css|png|svg|jpe?g|glb|woff2?|ya?ml|txt|sh|csv';
// A `dir/file.ext` name: at least one folder, not inside a longer word, a URL or a longer path.
const PATH = new RegExp(`(?<![\\w./@:~-])((?:\\.{1,2}/)?(?:[\\w@.-]+/)+[\\w.-]+\\.(?:${EXTENSIONS}))(?![\\w/])`, 'g');

/** The `dir/file.ext` names in `text`, without those that are part of a URL. */
export function pathsIn(text) {
  const found = [];
  for (const line of text.split('\n')) {
    for (const m of line.matchAll(PATH)) {
      if (/[a-z]+:\/\/\S*$/.test(line.slice(0, m.index))) continue; // https://host/dir/file.js
      found.push(m[1]);
    }
  }
  return found;
}

const pkg = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));
const PACKAGES = new Set(Object.keys({ ...pkg.devDependencies, ...pkg.peerDependencies, ...pkg.dependencies }));
// Written by a build, the asset step or a run, never committed (as in .gitignore).
const GENERATED = ['node_modules/', 'dist/', 'public/assets/', 'bench/results/tmp/', 'test/pages/.generated/'];

function packageName(path) {
  const [first, second] = path.split('/');
  return first.startsWith('@') ? `${first}/${second}` : first;
}

/** Whether `path`, named in `file`, is a repository path that exists (or not a repository path). */
function resolves(path, file) {
  if (PACKAGES.has(packageName(path))) return true;
  if (GENERATED.some((folder) => path.startsWith(folder))) return true;
  const top = file.split('/')[0];
  const bases = [root, join(root, dirname(file)), join(root, top)];
  if (path.endsWith('.glsl')) bases.push(join(root, 'shaders')); // the #include convention
  return bases.some((base) => existsSync(join(base, path)));
}

const tracked = execFileSync('git', ['ls-files'], { cwd: root, encoding: 'utf8' }).trim().split('\n');
// docs/notebook/ records past runs as they were, naming the files of their day: not checked.
const docs = tracked.filter((f) => f.endsWith('.md') && !f.startsWith('docs/notebook/'));
const sources = tracked.filter((f) => /^(src|shaders|bench|demo|dev|scripts|test)\//.test(f) && /\.(m?js|jsx|tsx?|glsl|html|css)$/.test(f));

function named(files, textOf) {
  return files.flatMap((file) => pathsIn(textOf(readFileSync(join(root, file), 'utf8'))).map((path) => ({ file, path })));
}

describe('the paths named in the docs and in comments', () => {
  it('are found by the parser: backticked and bare, not URLs, not code outside comments', () => {
    const text = commentsOf([
      "import x from './not/a/comment.js'; // see `src/index.js` and shaders/common/finite.glsl,",
      '/* and docs/ARCHITECTURE.md. https://example.com/dir/page.html is a URL */',
      "const s = 'in/a/string.js'; // three/addons/postprocessing/Pass.js",
    ].join('\n'));
    expect(pathsIn(text)).toEqual(['src/index.js', 'shaders/common/finite.glsl', 'docs/ARCHITECTURE.md', 'three/addons/postprocessing/Pass.js']);
    expect(resolves('src/index.js', 'README.md')).toBe(true);
    expect(resolves('common/finite.glsl', 'shaders/3-blur/subsurfaceBlur.frag.glsl')).toBe(true); // under shaders/
    expect(resolves('three/addons/postprocessing/Pass.js', 'README.md')).toBe(true); // a package's
    expect(resolves('src/gone.js', 'README.md')).toBe(false);
    expect(resolves('shaders/surfaceSlope.glsl', 'test/browser/3-blur/dense.test.js')).toBe(false);
  });

  it('in the docs (*.md) exist', () => {
    const paths = named(docs, (text) => text);
    expect(paths.length).toBeGreaterThan(50);
    expect(paths.filter(({ path, file }) => !resolves(path, file))).toEqual([]);
  });

  it('in the comments of src/, shaders/, bench/, demo/, dev/, scripts/ and test/ exist', () => {
    const paths = named(sources, commentsOf);
    expect(paths.length).toBeGreaterThan(50);
    expect(paths.filter(({ path, file }) => !resolves(path, file))).toEqual([]);
  });
});
