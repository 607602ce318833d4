// The shaders as the builds ship them: without their comments. The GLSL under shaders/ explains
// every stage and constant in comments (about 47 % of its 75 kB); a bundler inlines `?raw` imports
// as strings, which no minifier touches, so every application using the package carried them.
// `vite build` (the library and the demo) loads each `.glsl?raw` import through
// glslCommentsStripped(); the dev server, the tests and the bench read the sources as they are (a
// shader's compile error there points at the commented line). The package still ships shaders/
// with their comments for reading.
import { readFile } from 'node:fs/promises';

/**
 * GLSL without comments, blank lines or indentation. One scan from the start: `//` runs to the end
 * of its line, `/*` to the next `*\/` (its line breaks kept, so that the preprocessor's lines stay
 * lines), whichever opens first; GLSL has no string literals, so both always open comments.
 * @param {string} source
 * @returns {string}
 */
export function stripGlslComments(source) {
  const text = String(source);
  // A line continuation joins lines before comments are taken out (GLSL ES 3.00 §3.2), which
  // this scan does not do: refused rather than stripped differently (no shader has one).
  if (/\\[ \t]*\r?\n/.test(text)) throw new SyntaxError('stripGlslComments: a line continuation (\\ at the end of a line) is not supported');
  let code = '';
  for (let i = 0; i < text.length;) {
    if (text.startsWith('//', i)) {
      const end = text.indexOf('\n', i);
      i = end === -1 ? text.length : end; // the line break stays
    } else if (text.startsWith('/*', i)) {
      const end = text.indexOf('*/', i + 2);
      if (end === -1) throw new SyntaxError(`stripGlslComments: a /* comment is never closed (at character ${i})`);
      const breaks = text.slice(i, end).split('\n').length - 1;
      code += breaks > 0 ? '\n'.repeat(breaks) : ' ';
      i = end + 2;
    } else {
      code += text[i++];
    }
  }
  return code.split('\n').map((line) => line.trim()).filter((line) => line.length > 0).join('\n');
}

/** The Vite plugin: every `*.glsl?raw` import of a build as stripGlslComments gives it. */
export function glslCommentsStripped() {
  return {
    name: 'three-separable-sss:glsl-comments-stripped',
    apply: 'build',
    enforce: 'pre',
    async load(id) {
      const [path, query] = id.split('?');
      if (!path.endsWith('.glsl') || query !== 'raw') return null;
      return `export default ${JSON.stringify(stripGlslComments(await readFile(path, 'utf8')))};\n`;
    },
  };
}
