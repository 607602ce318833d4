// The demo's stylesheet for lil-gui (demo/lil-gui.css) is what three's lil-gui would inject as an
// inline <style> (which the demo's Content-Security-Policy refuses; the panel is made with
// injectStyles: false), with its icon font, a data: URL there, as a file (the policy has no
// `font-src data:`). A three release with another lil-gui fails here: copy its stylesheet again.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';

const root = new URL('../../../', import.meta.url);
const FONT_URL = /url\("data:application\/font-woff;charset=utf-8;base64,([A-Za-z0-9+/=]+)"\)/;

/** The stylesheet three's lil-gui injects. */
function injected() {
  const module = readFileSync(new URL('node_modules/three/examples/jsm/libs/lil-gui.module.min.js', root), 'utf8');
  const start = module.indexOf("('.lil-gui{") + 2;
  expect(start).toBeGreaterThan(1);
  return module.slice(start, module.indexOf("'", start));
}

describe("the demo's lil-gui stylesheet", () => {
  it("is three's lil-gui's, as it would inject it, with its icon font as a file of the same bytes", () => {
    const css = injected();
    const font = css.match(FONT_URL);
    expect(font).not.toBeNull();
    const file = readFileSync(new URL('demo/lil-gui.css', root), 'utf8').replace(/^\/\*[\s\S]*?\*\/\n/, '').trim();
    expect(file).toBe(css.replace(FONT_URL, 'url("lil-gui-icons.woff")'));
    expect(file).not.toMatch(/data:/);
    const bytes = readFileSync(new URL('demo/lil-gui-icons.woff', root));
    expect(bytes.equals(Buffer.from(font[1], 'base64'))).toBe(true);
    expect(bytes.subarray(0, 4).toString('latin1')).toBe('wOFF');
  });

  it('is linked by the page, and the panel does not inject its own', () => {
    expect(readFileSync(new URL('index.html', root), 'utf8')).toMatch(/<link rel="stylesheet" href="demo\/lil-gui\.css">/);
    expect(readFileSync(new URL('demo/controls.js', root), 'utf8')).toMatch(/new GUI\(\{[^}]*injectStyles: false/);
  });
});
