// The demo's stylesheet for lil-gui (demo/lil-gui.css) is what three's lil-gui would inject as an
// inline <style> (which the demo's Content-Security-Policy refuses; the panel is made with
// injectStyles: false). A three release with another lil-gui fails here: copy its stylesheet again.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';

const root = new URL('../../../', import.meta.url);

describe("the demo's lil-gui stylesheet", () => {
  it("is three's lil-gui's, as it would inject it", () => {
    const module = readFileSync(new URL('node_modules/three/examples/jsm/libs/lil-gui.module.min.js', root), 'utf8');
    const start = module.indexOf("('.lil-gui{") + 2;
    expect(start).toBeGreaterThan(1);
    const injected = module.slice(start, module.indexOf("'", start));
    const file = readFileSync(new URL('demo/lil-gui.css', root), 'utf8').replace(/^\/\*[\s\S]*?\*\/\n/, '').trim();
    expect(file).toBe(injected);
  });

  it('is linked by the page, and the panel does not inject its own', () => {
    expect(readFileSync(new URL('index.html', root), 'utf8')).toMatch(/<link rel="stylesheet" href="demo\/lil-gui\.css">/);
    expect(readFileSync(new URL('demo/controls.js', root), 'utf8')).toMatch(/new GUI\(\{[^}]*injectStyles: false/);
  });
});
