// Every name of the WebGL entries in one namespace (the main entry, ./stages and ./internals), for
// the tests and the pages that reach the stages and the plumbing as well as the API. The entries
// share no name (test/node/api.test.js holds them apart), so `export *` drops none.
export * from '../../src/index.js';
export * from '../../src/stages.js';
export * from '../../src/internals.js';
