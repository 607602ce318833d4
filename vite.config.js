// One config, two builds:
//   `vite build --mode lib`  → dist/three-separable-sss.js, the ES module users import (GLSL inlined,
//                              three and gl-matrix left as imports), and the subpath exports
//                              dist/postprocessing.js and dist/react.js (pmndrs, R3F left as imports)
//                              and dist/webgpu.js (three/webgpu, three/tsl left as imports)
//   `vite build`             → dist/demo/, the static demo page
//   `vite` (npm start)       → the demo and the test pages on a dev server
import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { glslCommentsStripped } from './scripts/stripGlslComments.js';

const root = fileURLToPath(new URL('.', import.meta.url));

// The version matrix (scripts/threeMatrix.js): SSS_THREE_DIR names another three release's folder,
// served in place of the devDependency to the pages (the library, the lab, pmndrs postprocessing).
const threeDir = process.env.SSS_THREE_DIR;
const threeAliases = threeDir ? [
  { find: /^three$/, replacement: `${threeDir}/build/three.module.js` },
  { find: /^three\/addons\/(.*)$/, replacement: `${threeDir}/examples/jsm/$1` },
] : [];

// The WebGPU bench's before and after (bench/webgpu/run.js --base): SSS_BASE_DIR names another
// checkout whose library the bench page imports as three-separable-sss-base (without it, this
// checkout's), its three and gl-matrix resolved to this checkout's.
const baseDir = process.env.SSS_BASE_DIR;
const baseSrc = baseDir ? `${baseDir}/src/` : `${root}src/`;

export default defineConfig(({ mode }) => {
  if (mode === 'lib') {
    return {
      root,
      publicDir: false,
      plugins: [glslCommentsStripped()], // the shaders' comments stay in shaders/, not in every bundle
      build: {
        outDir: 'dist',
        emptyOutDir: true,
        sourcemap: true,
        minify: false,
        lib: {
          // The package and its subpath exports; the subpaths share the main entry's modules (one
          // copy of the material hook's state).
          entry: {
            'three-separable-sss': 'src/index.js',
            stages: 'src/stages.js',
            internals: 'src/internals.js',
            postprocessing: 'src/integrations/postprocessing.js',
            react: 'src/integrations/react.js',
            webgpu: 'src/webgpu/index.js',
          },
          formats: ['es'],
          fileName: (format, entryName) => `${entryName}.js`,
        },
        rollupOptions: {
          external: [/^three(\/.*)?$/, /^gl-matrix(\/.*)?$/, /^postprocessing$/, /^react(\/.*)?$/, /^@react-three\/fiber$/],
          // The modules the entries share, in one chunk of a fixed name.
          output: { chunkFileNames: 'three-separable-sss-core.js' },
        },
      },
    };
  }
  return {
    root,
    base: './',
    publicDir: 'public',
    plugins: [glslCommentsStripped()], // a build only: the dev server serves the shaders as they are
    // Pages in this repository (the README's snippet, the bench, the integration pages) import the
    // package and its subpaths by name.
    resolve: {
      alias: [
        ...threeAliases,
        { find: /^three-separable-sss$/, replacement: `${root}src/index.js` },
        { find: /^three-separable-sss\/stages$/, replacement: `${root}src/stages.js` },
        { find: /^three-separable-sss\/internals$/, replacement: `${root}src/internals.js` },
        { find: /^three-separable-sss\/postprocessing$/, replacement: `${root}src/integrations/postprocessing.js` },
        { find: /^three-separable-sss\/react$/, replacement: `${root}src/integrations/react.js` },
        { find: /^three-separable-sss\/webgpu$/, replacement: `${root}src/webgpu/index.js` },
        { find: /^three-separable-sss-base$/, replacement: `${baseSrc}index.js` },
        { find: /^three-separable-sss-base\/webgpu$/, replacement: `${baseSrc}webgpu/index.js` },
      ],
      dedupe: baseDir ? ['three', 'gl-matrix'] : [],
    },
    // Not pre-bundled with another three: the pre-bundled dependencies import the aliased one.
    // three/webgpu and three/tsl (the WebGPU pages) pre-bundled from the start: found later, they
    // made Vite re-optimize and answer the page's other imports 504 (Outdated Optimize Dep).
    optimizeDeps: threeDir ? { exclude: ['three'] } : { include: ['three/webgpu', 'three/tsl'] },
    build: {
      outDir: 'dist/demo',
      emptyOutDir: true,
      sourcemap: true,
      // Fonts stay files: the demo's Content-Security-Policy has no `font-src data:` (lil-gui's
      // 1.3 kB icon font would otherwise be inlined as one).
      assetsInlineLimit: (file) => (/\.woff2?$/.test(file) ? false : undefined),
    },
    server: {
      host: '127.0.0.1',
      ...(baseDir ? { fs: { allow: [root, baseDir] } } : {}),
    },
  };
});
