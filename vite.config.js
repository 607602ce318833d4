// One config, two builds:
//   `vite build --mode lib`  → dist/three-separable-sss.js, the ES module users import (GLSL inlined,
//                              three and gl-matrix left as imports)
//   `vite build`             → dist/demo/, the static demo page
//   `vite` (npm start)       → the demo and the test pages on a dev server
import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('.', import.meta.url));

export default defineConfig(({ mode }) => {
  if (mode === 'lib') {
    return {
      root,
      publicDir: false,
      build: {
        outDir: 'dist',
        emptyOutDir: true,
        sourcemap: true,
        minify: false,
        lib: {
          entry: 'src/index.js',
          formats: ['es'],
          fileName: () => 'three-separable-sss.js',
        },
        rollupOptions: {
          external: [/^three(\/.*)?$/, /^gl-matrix(\/.*)?$/],
        },
      },
    };
  }
  return {
    root,
    base: './',
    publicDir: 'public',
    // Pages in this repository (the README's snippet, the bench, the integration pages) import the
    // package and its subpaths by name.
    resolve: {
      alias: [
        { find: /^three-separable-sss$/, replacement: `${root}src/index.js` },
        { find: /^three-separable-sss\/postprocessing$/, replacement: `${root}src/integrations/postprocessing.js` },
        { find: /^three-separable-sss\/react$/, replacement: `${root}src/integrations/react.js` },
      ],
    },
    build: {
      outDir: 'dist/demo',
      emptyOutDir: true,
      sourcemap: true,
    },
    server: {
      host: '127.0.0.1',
    },
  };
});
