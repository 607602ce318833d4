// The library as users get it: built by Vite's library mode (GLSL inlined), imported by plain Node
// with no DOM, no globals added (the subpath exports too), and computeKernel reproducing the
// reference presets.
import { describe, it, expect } from 'vitest';
import { build } from 'vite';
import { execFileSync } from 'node:child_process';
import { rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));
// Inside the repository so that bare imports (three, gl-matrix) resolve from its node_modules.
const outDir = `${root}node_modules/.cache/sss-package-test`;

describe('the built package', () => {
  it('imports in plain Node without side effects and computes the reference kernels', async () => {
    rmSync(outDir, { recursive: true, force: true });
    await build({ root, configFile: `${root}vite.config.js`, mode: 'lib', logLevel: 'error', build: { outDir, emptyOutDir: true } });
    const script = `
      const before = new Set(Object.getOwnPropertyNames(globalThis));
      const m = await import(${JSON.stringify(`${outDir}/three-separable-sss.js`)});
      // The subpath exports too: pmndrs postprocessing's pass, the React Three Fiber components.
      const pmndrs = await import(${JSON.stringify(`${outDir}/postprocessing.js`)});
      const react = await import(${JSON.stringify(`${outDir}/react.js`)});
      const stages = await import(${JSON.stringify(`${outDir}/stages.js`)});
      const internals = await import(${JSON.stringify(`${outDir}/internals.js`)});
      const added = Object.getOwnPropertyNames(globalThis).filter((k) => !before.has(k));
      const k17 = stages.computeKernel({ samples: 17, method: 'reference' });
      console.log(JSON.stringify({
        exports: Object.keys(m).sort(), stages: Object.keys(stages).sort(), added, typeofWindow: typeof window, typeofDocument: typeof document,
        pmndrs: Object.keys(pmndrs).sort(), react: Object.keys(react).sort(), internals: Object.keys(internals).sort(),
        planned: internals.planBlur({ method: 'footprint', samples: 'auto', scattering: true, marginalRadiusMm: 3, denseRadiusMm: 0, kernelReachMm: {} }, 2),
        centre17: Array.from(k17.slice(0, 4)),
        sizes: [11, 17, 25].map((n) => stages.referenceKernel(n).length / 4),
        chunk: stages.transmittanceChunk.includes('sssTransmittance('),
      }));`;
    const out = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '--no-deprecation', '-e', script], { encoding: 'utf8' }));
    expect(out.typeofWindow).toBe('undefined');
    expect(out.typeofDocument).toBe('undefined');
    expect(out.pmndrs).toEqual(['SubsurfaceScatteringPass']);
    expect(out.react).toEqual(['Subsurface', 'SubsurfaceComposer', 'useSubsurface', 'useSubsurfaceComposer', 'useSubsurfaceScattering']);
    expect(out.added).toEqual([]);
    // The unstable entry: the blur's plan runs in plain Node too (63 taps: the footprints' budget).
    expect(out.internals).toContain('planBlur');
    expect(out.planned).toEqual({ samples: 63, kernelPixels: 6, blur: true, fade: 1, tapBlend: null, passes: 'separable', groups: 1, groupings: null }); // a plan without profiles blurs with one kernel, fully (6 px of reach: past the fade)
    for (const name of ['profiles', 'transmittance', 'getProfile', 'SubsurfaceScattering']) expect(out.exports).toContain(name);
    for (const name of ['computeKernel', 'LightDepthTarget', 'transmittanceChunk', 'makeSubsurface', 'SubsurfaceBlurPass']) expect(out.stages).toContain(name);
    expect(out.chunk).toBe(true);
    expect(out.sizes).toEqual([11, 17, 25]);
    // The reference's published 17-tap centre weight (REFERENCE §3), offset 0.
    expect(out.centre17[0]).toBeCloseTo(0.536343, 6);
    expect(out.centre17[1]).toBeCloseTo(0.624624, 6);
    expect(out.centre17[2]).toBeCloseTo(0.748867, 6);
    expect(out.centre17[3]).toBe(0);
    rmSync(outDir, { recursive: true, force: true });
  }, 120_000);
});
