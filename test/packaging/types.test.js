// The TypeScript declarations as a consumer gets them: generated from the JSDoc by the package's
// own build step (tsconfig.types.json), installed with package.json's `exports` into a scratch
// project, and compiled by the real `tsc` in strict mode: every README snippet, every export
// (test/types/consumer.ts), the subpath exports with JSX (test/types/integrations.tsx) and a file of
// deliberate misuses (test/types/misuse.ts), which must fail on exactly the lines it marks.
import { describe, it, expect, beforeAll } from 'vitest';
import { spawnSync } from 'node:child_process';
import { cpSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as runtime from '../../src/index.js';
import * as stages from '../../src/stages.js';
import * as internals from '../../src/internals.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
// Inside the repository so that three, @types/three, postprocessing, react and R3F resolve from its node_modules.
const project = `${root}node_modules/.cache/sss-types-test`;
const installed = `${project}/node_modules/three-separable-sss`;
const tsc = `${root}node_modules/typescript/bin/tsc`;

const COMPILER_OPTIONS = {
  strict: true, noEmit: true, target: 'es2022', lib: ['es2022', 'dom'], module: 'esnext',
  moduleResolution: 'bundler', jsx: 'react-jsx', types: [], skipLibCheck: false,
  noUnusedLocals: false, isolatedModules: true,
};

function compile(files, name, options = {}) {
  writeFileSync(`${project}/${name}.json`, JSON.stringify({ compilerOptions: { ...COMPILER_OPTIONS, ...options }, files }, null, 2));
  const run = spawnSync(process.execPath, [tsc, '-p', `${name}.json`, '--pretty', 'false'], { cwd: project, encoding: 'utf8' });
  return { status: run.status, output: `${run.stdout}${run.stderr}` };
}

/** `file(line,col): error TSnnnn: ...` lines of tsc's output. */
function errorsOf(output) {
  return [...output.matchAll(/^(.+?)\((\d+),\d+\): error (TS\d+)/gm)].map(([, file, line, code]) => ({ file, line: Number(line), code }));
}

const misuse = readFileSync(`${root}test/types/misuse.ts`, 'utf8').split('\n');
let expectedLines = [];
/** The README's snippets but the usage and WebGPURenderer ones, as written by beforeAll. */
let readmeFiles = [];

beforeAll(() => {
  rmSync(project, { recursive: true, force: true });
  mkdirSync(`${project}/src`, { recursive: true });
  // A package of its own: otherwise TypeScript would resolve the name as this repository's self-reference.
  writeFileSync(`${project}/package.json`, '{ "name": "sss-types-consumer", "private": true, "type": "module" }\n');
  // The declarations, by the build's own step, where the package's `exports` point.
  const generate = spawnSync(process.execPath, [tsc, '-p', 'tsconfig.types.json', '--outDir', `${installed}/dist/types`], { cwd: root, encoding: 'utf8' });
  expect(generate.status, generate.stdout + generate.stderr).toBe(0);
  cpSync(`${root}package.json`, `${installed}/package.json`);
  cpSync(`${root}test/types`, `${project}/src`, { recursive: true });
  // The README's snippets as TypeScript files, each by the heading it stands under: the usage
  // snippet (under "## Usage") as it is, the WebGPURenderer one against its own context, every other
  // one with the usage snippet's variables it builds on declared.
  const readme = readFileSync(`${root}README.md`, 'utf8');
  let heading = '';
  const snippets = [];
  for (const [, title, lang, code] of readme.slice(readme.indexOf('## Usage')).matchAll(/^(#{2,3} .+)$|^```(js|ts|jsx)\n([\s\S]*?)```/gm)) {
    if (title) heading = title;
    else snippets.push({ heading, lang, code });
  }
  const usage = snippets.find((s) => s.heading === '## Usage');
  const webgpu = snippets.find((s) => s.heading === '### WebGPURenderer');
  const others = snippets.filter((s) => s !== usage && s !== webgpu);
  expect(usage?.lang).toBe('js');
  expect(webgpu?.code).toContain("from 'three-separable-sss/webgpu'");
  expect(others.filter((s) => s.lang === 'jsx').length).toBe(1); // the React Three Fiber snippet
  expect(others.length).toBeGreaterThanOrEqual(3);
  const context = [
    "import * as THREE from 'three';",
    'declare const renderer: THREE.WebGLRenderer, scene: THREE.Scene, camera: THREE.PerspectiveCamera;',
    'declare const light: THREE.SpotLight, skin: THREE.MeshStandardMaterial, pattern: THREE.Texture;',
  ].join('\n');
  writeFileSync(`${project}/src/readme.ts`, `${usage.code}\nexport {};\n`);
  readmeFiles = others.map(({ lang, code }, i) => {
    const withoutThree = code.replace("import * as THREE from 'three';\n", '');
    const file = `src/readme-${i + 1}.${lang === 'jsx' ? 'tsx' : 'ts'}`;
    writeFileSync(`${project}/${file}`, `${context}\n${withoutThree}\nexport {};\n`);
    return file;
  });
  // The WebGPURenderer snippet imports three/webgpu as THREE itself: the usage snippet's objects typed
  // from 'three', `disc` as TypeScript infers it there (a Mesh of its geometry and `skin`'s class).
  const webgpuContext = "declare const scene: import('three').Scene, camera: import('three').PerspectiveCamera, disc: import('three').Mesh<import('three').CylinderGeometry, import('three').MeshStandardMaterial>, skin: import('three').MeshStandardMaterial;";
  writeFileSync(`${project}/src/readme-webgpu.ts`, `${webgpuContext}\n${webgpu.code}\nexport {};\n`);
  // The misuses without their directives: the lines after each must be the errors.
  const bare = [];
  for (const line of misuse) {
    if (line.trim().startsWith('// @ts-expect-error')) expectedLines.push(bare.length + 2); // 1-based, the next line
    else bare.push(line);
  }
  expectedLines = expectedLines.map((n) => n - 1);
  writeFileSync(`${project}/src/misuse-bare.ts`, bare.join('\n'));
}, 120_000);

describe('the generated declarations', () => {
  it('compile a strict consumer of the README snippets, every export, the pmndrs pass and the R3F components', () => {
    const files = readmeFiles.filter((f) => f.endsWith('.ts'));
    const { status, output } = compile(['src/readme.ts', ...files, 'src/consumer.ts', 'src/integrations.tsx', 'src/misuse.ts'], 'tsconfig.consumer');
    expect(output).toBe('');
    expect(status).toBe(0);
  }, 120_000);

  it("compile the README's WebGPURenderer snippet and a webgpu consumer against the webgpu entry (strict, its declarations checked too)", () => {
    const { status, output } = compile(['src/readme-webgpu.ts', 'src/webgpuConsumer.ts'], 'tsconfig.webgpu');
    expect(output).toBe('');
    expect(status).toBe(0);
  }, 120_000);

  it("compile the README's JSX snippet (strict)", () => {
    const { status, output } = compile(readmeFiles.filter((f) => f.endsWith('.tsx')), 'tsconfig.jsx');
    expect(output).toBe('');
    expect(status).toBe(0);
  }, 120_000);

  it('refuse every deliberate misuse, on exactly the lines marked', () => {
    expect(expectedLines.length).toBe(misuse.filter((l) => l.includes('@ts-expect-error ')).length);
    expect(expectedLines.length).toBeGreaterThanOrEqual(15);
    const { status, output } = compile(['src/misuse-bare.ts'], 'tsconfig.misuse');
    expect(status).not.toBe(0);
    const errors = errorsOf(output);
    expect(errors.every((e) => e.file === 'src/misuse-bare.ts'), output).toBe(true);
    expect([...new Set(errors.map((e) => e.line))].sort((a, b) => a - b)).toEqual(expectedLines);
  }, 120_000);

  it('consumer.ts names every value the package, its stages entry and its internals entry export', () => {
    const consumer = readFileSync(`${root}test/types/consumer.ts`, 'utf8');
    const namesIn = (block) => [...block.matchAll(/^ {2}(\w+):/gm)].map((m) => m[1]).sort();
    const blockOf = (from, to) => consumer.slice(consumer.indexOf(from), to ? consumer.indexOf(to) : undefined);
    expect(namesIn(blockOf('export const ALL_EXPORTS'))).toEqual(Object.keys(runtime).sort());
    expect(namesIn(blockOf('export const ALL_STAGES', 'export const ALL_EXPORTS'))).toEqual(Object.keys(stages).sort());
    expect(namesIn(blockOf('export const ALL_INTERNALS', 'export const ALL_STAGES'))).toEqual(Object.keys(internals).sort());
  });
});
