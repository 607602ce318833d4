// The multi-target's attachments are read by name (ATTACHMENTS, src/2-scene-split/subsurfaceTarget.js)
// outside the library too: the demo, the bench and the test pages hold no literal index, so a
// change of the layout cannot leave one of them reading the wrong attachment.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';

const root = new URL('../../', import.meta.url);
const files = execFileSync('git', ['ls-files', 'demo', 'bench', 'dev', 'scripts', 'test/pages', 'test/reliability'], { cwd: root, encoding: 'utf8' })
  .trim().split('\n').filter((f) => /\.(m?js|jsx)$/.test(f));

// Being rewritten on other branches (issue 19: bench/peers.js; issue 21: the surface truth), which
// read the diffuse attachment as 1: to leave this list when they land.
const ELSEWHERE = ['bench/peers.js', 'bench/surfaceTruth/atlas.js', 'bench/surfaceTruth/page.js'];

describe('reads of the multi-target', () => {
  it('name the attachment (ATTACHMENTS.SURFACE, ...), never a number', () => {
    // A read of the scene pass's target with a literal attachment index, e.g. (renderer, sss._scenePass.renderTarget, 2).
    const literal = /scenePass\.renderTarget\s*,\s*\d/;
    expect(files.length).toBeGreaterThan(20);
    const found = files.filter((f) => literal.test(readFileSync(new URL(f, root), 'utf8')));
    expect(found.filter((f) => !ELSEWHERE.includes(f))).toEqual([]);
    expect(literal.test('readRenderTargetFloats(renderer, sss._scenePass.renderTarget, 2)')).toBe(true);
  });
});
