// three-separable-sss/react in a React Three Fiber app (test/pages/r3f.jsx, the real
// @react-three/fiber and React, in StrictMode): <SubsurfaceComposer> and <Subsurface> draw what
// the three.js pass draws by hand, follow a camera swap without a rebuild, and mount and unmount
// without leaving anything in three's memory.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { openPage, evaluateFloats } from '../../harness/page.js';
import { litAndTint } from '../../harness/snippetPage.js';

let page;
beforeAll(async () => {
  page = await openPage('/test/pages/r3f.html');
});
afterAll(async () => {
  expect(page.problems).toEqual([]);
  await page.close();
});

/** Largest |a − b| over RGB. */
function worstDifference(a, b) {
  let worst = 0;
  for (let i = 0; i < a.length; i++) if (i % 4 !== 3) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  return worst;
}

const ONE_LEVEL = 1 / 255; // the canvas is 8-bit

describe('<SubsurfaceComposer> and <Subsurface>', () => {
  let mounted;
  it('renders the scene as the three.js pass does by hand (within one 8-bit level), and scatters', async () => {
    mounted = await evaluateFloats(page, async () => {
      const r = window.r3f;
      await r.advance(2);
      const baseline = r.info(); // nothing mounted yet
      await r.mount(true);
      await r.advance(2);
      const image = r.readCanvas();
      const info = r.info();
      const byHand = r.renderByHand();
      const unscattered = r.renderByHand({ scattering: false });
      return { baseline, info, image, byHand, unscattered };
    });
    const { image, byHand, unscattered, info } = mounted;
    expect(info.passId).not.toBeNull();
    expect(info.subsurface).toBe(true);
    const { lit, red, blue } = litAndTint(image, 0.3);
    expect(lit).toBeGreaterThan(0.05); // the knot is there and lit
    expect(red).toBeGreaterThan(blue);
    expect(worstDifference(image, byHand)).toBeLessThanOrEqual(ONE_LEVEL);
    expect(worstDifference(byHand, unscattered)).toBeGreaterThan(0.05); // scattering shows
  });

  it('follows a camera swap (set({ camera }), as makeDefault does) with the same pipeline', async () => {
    const r = await evaluateFloats(page, async () => {
      const lab = window.r3f;
      const before = lab.readCanvas();
      const passBefore = lab.info().passId;
      const uuid = lab.swapCamera();
      await lab.advance(2);
      const image = lab.readCanvas();
      const info = lab.info();
      const byHand = lab.renderByHand();
      return { before, image, byHand, passBefore, info, uuid };
    });
    expect(r.info.cameraUuid).toBe(r.uuid);
    expect(r.info.passId).toBe(r.passBefore); // no rebuild
    expect(worstDifference(r.image, r.before)).toBeGreaterThan(0.1); // the view did change
    expect(worstDifference(r.image, r.byHand)).toBeLessThanOrEqual(ONE_LEVEL);
  });

  it('unmounts and remounts without leaks: three holds what it held before, the material is unhooked', async () => {
    const r = await page.evaluate(async () => {
      const lab = window.r3f;
      const cycles = [];
      for (let i = 0; i < 3; i++) {
        await lab.mount(false);
        await lab.advance(1);
        const unmounted = lab.info();
        await lab.mount(true);
        await lab.advance(2);
        cycles.push({ unmounted, mounted: lab.info() });
      }
      await lab.mount(false);
      await lab.advance(1);
      return { cycles, last: lab.info() };
    });
    const { baseline, info: first } = mounted;
    const memory = ({ textures, geometries, programs, sssPrograms }) => ({ textures, geometries, programs, sssPrograms });
    // three keeps one texture per renderer once a MeshStandardMaterial has drawn (r187's DFG
    // lookup table, never disposed): the state after the first unmount is the one to come back to.
    const empty = r.cycles[0].unmounted;
    expect(empty.textures - baseline.textures).toBeLessThanOrEqual(1);
    expect({ ...memory(empty), textures: baseline.textures }).toEqual(memory(baseline));
    for (const { unmounted, mounted: again } of r.cycles) {
      expect(memory(unmounted)).toEqual(memory(empty));
      expect(memory(again)).toEqual(memory(first));
    }
    expect(memory(r.last)).toEqual(memory(empty));
    expect(r.last.sssPrograms).toBe(0);
    expect(r.last.passId).toBeNull();
    // A new pipeline each mount (the old one disposed), not one kept alive.
    expect(new Set(r.cycles.map((c) => c.mounted.passId)).size).toBe(3);
    expect(first.textures).toBeGreaterThan(baseline.textures + 3); // the pipeline's targets were counted
  });
});
