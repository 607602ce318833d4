import { describe, it, expect } from 'vitest';
import { mat4, vec3 } from 'gl-matrix';
import {
  separableBlurOracle,
  denseConvolutionOracle,
  sampleBilinear,
  edgeResponse1D,
  kernelEdgeResponse1D,
  roundToHalfFloat,
} from '../oracle/convolution.js';
import { transmittanceOracle, thicknessFromLightDepth, transmittedFractionOracle } from '../oracle/transmittance.js';
import { computeKernel } from '../../src/profiles/kernel.js';
import { profiles } from '../../src/profiles/presets.js';
import { gaussianSumProfile } from '../../src/profiles/gaussianSum.js';
import { mulberry32 as random } from '../../demo/seededRandom.js';
import { frequenciesAt, gratingMargin, measuredTransfer } from '../oracle/gratingFit.js';
import { radialBlur } from '../browser/3-blur/accuracyCases.js';


/** An image whose pixels are filled by fn(i, j) → { colour, depth, widthWorld }. */
function makeImage(width, height, fn) {
  const n = width * height;
  const diffuse = new Float64Array(3 * n);
  const depth = new Float64Array(n);
  const widthWorld = new Float64Array(n);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const idx = j * width + i;
      const p = fn(i, j);
      diffuse.set(p.colour, 3 * idx);
      depth[idx] = p.depth;
      widthWorld[idx] = p.widthWorld;
    }
  }
  return { width, height, diffuse, depth, widthWorld };
}

/** A kernel with integer offsets 0, ±1, ..., ±m and the given symmetric weights (centre first). */
function integerKernel(weights) {
  const m = weights.length - 1;
  const out = new Float32Array(4 * (2 * m + 1));
  out.set([weights[0], weights[0], weights[0], 0], 0);
  let k = 1;
  for (let o = -m; o <= m; o++) {
    if (o === 0) continue;
    const w = weights[Math.abs(o)];
    out.set([w, w, w, o], 4 * k++);
  }
  return out;
}

const at = (out, width, i, j) => [out[3 * (j * width + i)], out[3 * (j * width + i) + 1], out[3 * (j * width + i) + 2]];

describe('sampleBilinear', () => {
  it('reproduces a linear ramp exactly inside the texel-centre hull, and clamps at the edges', () => {
    const width = 9;
    const height = 7;
    const img = makeImage(width, height, (i, j) => ({
      colour: [2 + 0.5 * (i + 0.5) - 0.25 * (j + 0.5), -1 + 3 * (j + 0.5), 0.125 * (i + 0.5) * 4],
      depth: 1,
      widthWorld: 1,
    }));
    const rnd = random(1);
    for (let n = 0; n < 200; n++) {
      const x = 0.5 + rnd() * (width - 1);
      const y = 0.5 + rnd() * (height - 1);
      const c = sampleBilinear(img.diffuse, width, height, x, y);
      expect(c[0]).toBeCloseTo(2 + 0.5 * x - 0.25 * y, 12);
      expect(c[1]).toBeCloseTo(-1 + 3 * y, 12);
      expect(c[2]).toBeCloseTo(0.5 * x, 12);
    }
    // clamp-to-edge: left of the first texel centre the value is the first texel's
    expect(sampleBilinear(img.diffuse, width, height, 0.1, 3.5)[2]).toBeCloseTo(0.25, 14);
    expect(sampleBilinear(img.diffuse, width, height, width - 0.01, 3.5)[2]).toBeCloseTo(0.5 * (width - 0.5), 14);
  });
});

describe('separableBlurOracle', () => {
  const kernel = computeKernel({ samples: 17, profile: 'skin' });

  it('keeps a constant image constant for every follow-surface mode, mask and depth pattern', () => {
    const rnd = random(7);
    const constant = [0.3, 0.7, 1.2];
    const img = makeImage(32, 24, () => ({
      colour: constant,
      depth: 1 + 0.5 * rnd(),
      widthWorld: rnd() < 0.15 ? 0 : 0.05 + 0.1 * rnd(),
    }));
    for (const followSurface of ['off', 'drop', 'lerp']) {
      for (const tapFilter of ['bilinear', 'bilinearPerTexel']) {
        const out = separableBlurOracle({ ...img, kernel, projectionScale: [1.3, 2.1], followSurface, depthThresholdWorld: 0.1, tapFilter });
        let worst = 0;
        for (let n = 0; n < out.length; n++) worst = Math.max(worst, Math.abs(out[n] - constant[n % 3]));
        expect(worst).toBeLessThan(1e-12);
      }
    }
  });

  it('blurs a point into the product of the two 1D kernels (bilinear taps), on a large image', () => {
    const size = 121;
    const c0 = 60;
    const k = computeKernel({ samples: 13, profile: gaussianSumProfile('g', [{ varianceMm2: 0.5, weights: [1, 1, 1] }]) });
    const P = [1.1, 0.8];
    const widthWorld = 0.031;
    const img = makeImage(size, size, (i, j) => ({ colour: i === c0 && j === c0 ? [1, 2, 3] : [0, 0, 0], depth: 1, widthWorld }));
    const out = separableBlurOracle({ ...img, kernel: k, projectionScale: P, followSurface: 'off' });
    const step = [((widthWorld * P[0]) / 2) * size, ((widthWorld * P[1]) / 2) * size];
    const hat = (d) => Math.max(0, 1 - Math.abs(d));
    const profile1D = (i, axis, c) => {
      let s = 0;
      let wsum = 0;
      for (let t = 0; t < k.length / 4; t++) {
        s += k[4 * t + c] * hat(i + 0.5 + k[4 * t + 3] * step[axis] - (c0 + 0.5));
        wsum += k[4 * t + c];
      }
      return s / wsum;
    };
    let worst = 0;
    let total = 0;
    for (let j = 0; j < size; j++) {
      for (let i = 0; i < size; i++) {
        for (let c = 0; c < 3; c++) {
          const expected = (c + 1) * profile1D(i, 0, c) * profile1D(j, 1, c);
          worst = Math.max(worst, Math.abs(out[3 * (j * size + i) + c] - expected));
          total += out[3 * (j * size + i) + c];
        }
      }
    }
    expect(worst).toBeLessThan(1e-12);
    expect(total).toBeCloseTo(6, 6); // energy preserved: the point's 1 + 2 + 3
  });

  it('reproduces a linear ramp exactly where all taps are inside (symmetric kernel)', () => {
    const width = 40;
    const height = 30;
    const img = makeImage(width, height, (i, j) => ({ colour: [i + 0.5, 2 * (j + 0.5), 1 + 0.1 * (i + j + 1)], depth: 1, widthWorld: 0.02 }));
    const out = separableBlurOracle({ ...img, kernel, projectionScale: [1, 1], followSurface: 'off' });
    const reachX = Math.ceil(((0.02 * 1) / 2) * width * 1.4) + 1; // skin kernel radius ≈ 1.37 mm
    const reachY = Math.ceil(((0.02 * 1) / 2) * height * 1.4) + 1;
    for (let j = reachY; j < height - reachY; j++) {
      for (let i = reachX; i < width - reachX; i++) {
        const c = at(out, width, i, j);
        expect(c[0]).toBeCloseTo(i + 0.5, 11);
        expect(c[1]).toBeCloseTo(2 * (j + 0.5), 11);
        expect(c[2]).toBeCloseTo(1 + 0.1 * (i + j + 1), 11);
      }
    }
  });

  it("'drop' and 'lerp' let nothing across a depth edge beyond the threshold when taps sit on texel centres", () => {
    const k = integerKernel([0.5, 0.1875, 0.0625]); // dyadic: exact in float32
    const width = 20;
    // widthWorld·P0/(2·depth)·width = 1 px per kernel-mm on the near side: taps land on texel centres
    const img = makeImage(width, 3, (i) => ({ colour: i < 10 ? [1, 0, 0] : [0, 1, 1], depth: i < 10 ? 1 : 1.5, widthWorld: i < 10 ? 0.1 : 0.15 }));
    for (const followSurface of ['drop', 'lerp']) {
      const out = separableBlurOracle({ ...img, kernel: k, projectionScale: [1, 2 / 3], followSurface, depthThresholdWorld: 0.25 });
      for (let i = 0; i < width; i++) expect(at(out, width, i, 1)).toEqual(i < 10 ? [1, 0, 0] : [0, 1, 1]);
    }
    // and below the threshold they do mix: f = 0.5/1 → half weight
    const partial = separableBlurOracle({ ...img, kernel: k, projectionScale: [1, 2 / 3], followSurface: 'drop', depthThresholdWorld: 1 });
    // pixel 9: taps at 10 and 11 are on the far side with f = 0.5/1, so their weights are halved
    const g = at(partial, width, 9, 1)[1];
    expect(g).toBeCloseTo((0.1875 * 0.5 + 0.0625 * 0.5) / (0.5 + 0.1875 + 0.0625 + 0.1875 * 0.5 + 0.0625 * 0.5), 14);
  });

  it('the plain bilinear tap filter leaks far colour through taps within half a texel of a depth edge; the GPU\'s per-texel filter (default) has none', () => {
    const width = 60;
    const edge = 30;
    const img = makeImage(width, 1, (i) => ({ colour: i < edge ? [1, 0, 0] : [0, 1, 1], depth: i < edge ? 1 : 1.5, widthWorld: 0.05 }));
    const out = separableBlurOracle({ ...img, kernel, projectionScale: [1, 1], followSurface: 'drop', depthThresholdWorld: 0.2, tapFilter: 'bilinear' });
    const stepPx = (0.05 / 2) * width;
    let worst = 0;
    for (let i = 0; i < edge; i++) {
      for (let c = 0; c < 3; c++) {
        let leak = 0;
        let weights = kernel[c];
        for (let k = 1; k < kernel.length / 4; k++) {
          const x = i + 0.5 + kernel[4 * k + 3] * stepPx;
          if (x < 0 || x >= edge) continue; // outside, or on the far side and dropped (f = 1)
          weights += kernel[4 * k + c];
          leak += kernel[4 * k + c] * Math.max(0, x - (edge - 0.5)); // bilinear share of texel `edge`
        }
        const farColour = c === 0 ? 0 : 1;
        const expected = c === 0 ? 1 - leak / weights : (farColour * leak) / weights;
        worst = Math.max(worst, Math.abs(out[3 * i + c] - expected));
      }
    }
    expect(worst).toBeLessThan(1e-12);
    // measured size of the leak (reported): up to ~7 % of the far colour next to the edge
    const maxLeak = Math.max(...Array.from({ length: edge }, (_, i) => out[3 * i + 1]));
    expect(maxLeak).toBeGreaterThan(0.05);
    expect(maxLeak).toBeLessThan(0.1);
    // the per-texel filter, the default and the GPU's, has none
    const perTexel = separableBlurOracle({ ...img, kernel, projectionScale: [1, 1], followSurface: 'drop', depthThresholdWorld: 0.2 });
    for (let i = 0; i < edge; i++) {
      const [r, g, b] = at(perTexel, width, i, 0);
      expect(r).toBeCloseTo(1, 14);
      expect(g).toBe(0);
      expect(b).toBe(0);
    }
  });

  it('drops taps on non-subsurface pixels and outside the image, copies non-subsurface pixels', () => {
    const k = integerKernel([0.5, 0.125, 0.125]);
    const width = 12;
    const img = makeImage(width, 1, (i) => ({ colour: i < 4 ? [100, 100, 100] : [i, 0, 1], depth: 1, widthWorld: i < 4 ? 0 : 2 / width }));
    const out = separableBlurOracle({ ...img, kernel: k, projectionScale: [1, 1], followSurface: 'off' });
    for (let i = 0; i < 4; i++) expect(at(out, width, i, 0)).toEqual([100, 100, 100]);
    // pixel 4: taps at 2, 3 (masked) dropped; 5, 6 kept
    expect(at(out, width, 4, 0)[0]).toBeCloseTo((0.5 * 4 + 0.125 * 5 + 0.125 * 6) / 0.75, 13);
    // pixel 11: taps at 12, 13 are outside the image
    expect(at(out, width, 11, 0)[0]).toBeCloseTo((0.5 * 11 + 0.125 * 10 + 0.125 * 9) / 0.75, 13);
  });

  it('skips pixels whose kernel spans less than half a pixel', () => {
    const rnd = random(3);
    const img = makeImage(16, 16, () => ({ colour: [rnd(), rnd(), rnd()], depth: 2, widthWorld: 0.001 }));
    const out = separableBlurOracle({ ...img, kernel, projectionScale: [1, 1], followSurface: 'off' });
    expect(Array.from(out)).toEqual(Array.from(img.diffuse));
  });

  it('applies storeIntermediate to every value between the passes', () => {
    const rnd = random(5);
    const img = makeImage(10, 8, () => ({ colour: [rnd(), rnd(), rnd()], depth: 1, widthWorld: 0.2 }));
    let calls = 0;
    const base = { ...img, kernel, projectionScale: [1, 1], followSurface: 'off' };
    const half = separableBlurOracle({ ...base, storeIntermediate: (x) => (calls++, roundToHalfFloat(x)) });
    const full = separableBlurOracle(base);
    expect(calls).toBe(10 * 8 * 3);
    let worst = 0;
    for (let n = 0; n < full.length; n++) worst = Math.max(worst, Math.abs(half[n] - full[n]));
    expect(worst).toBeGreaterThan(0);
    expect(worst).toBeLessThan(1e-3); // half float: 11-bit mantissa
  });
});

describe('roundToHalfFloat', () => {
  it('rounds to nearest even half float, with subnormals and overflow', () => {
    expect(roundToHalfFloat(1 / 3)).toBe(0.333251953125);
    expect(roundToHalfFloat(65504)).toBe(65504);
    expect(roundToHalfFloat(65519)).toBe(65504);
    expect(roundToHalfFloat(65520)).toBe(Infinity);
    expect(roundToHalfFloat(-1e6)).toBe(-Infinity);
    expect(roundToHalfFloat(2 ** -24)).toBe(2 ** -24);
    expect(roundToHalfFloat(2 ** -25)).toBe(0); // tie, to even (0)
    expect(roundToHalfFloat(1 + 2 ** -11)).toBe(1); // tie, to even
    expect(roundToHalfFloat(1 + 3 * 2 ** -11)).toBe(1 + 2 ** -9);
    expect(roundToHalfFloat(-2.5)).toBe(-2.5);
    expect(roundToHalfFloat(0)).toBe(0);
  });
});

describe('denseConvolutionOracle', () => {
  /** A vertical step edge at x = edgePx (1 on the left), constant depth; returns the middle row and the scale. */
  function edgeRow(profile, sxPxPerMm, width, height, edgePx, coverage) {
    const depth = 1;
    const P = [1, 1];
    const widthWorld = (2 * depth * sxPxPerMm) / (P[0] * width);
    const img = makeImage(width, height, (i) => ({ colour: i < edgePx ? [1, 1, 1] : [0, 0, 0], depth, widthWorld }));
    const scaleY = ((widthWorld * P[1]) / (2 * depth)) * height;
    const out = denseConvolutionOracle({ ...img, profile, projectionScale: P, coverage });
    const j = (height - 1) / 2;
    return { row: Array.from({ length: width }, (_, i) => at(out, width, i, j)), scaleY };
  }

  it('the response to a half-plane edge along the x axis is the marginal\'s edge response (Gaussian sum, exact pixels)', () => {
    const sx = 2;
    const radiusPx = Math.ceil(profiles.skin.radiusMm(0.99999)[0] * 2);
    const { row } = edgeRow('skin', sx, 80, 2 * radiusPx + 5, 40, 0.99999);
    let worst = 0;
    row.forEach((rgb, i) => {
      const exact = edgeResponse1D('skin', (i + 0.5 - 40) / sx);
      rgb.forEach((v, c) => (worst = Math.max(worst, Math.abs(v - exact[c]))));
    });
    expect(worst).toBeLessThan(1e-3);
  });

  it('the same holds for Burley through the polar-quadrature pixel energies', () => {
    const sx = 1.5;
    const radiusPx = Math.ceil(profiles.skinBurley.radiusMm(0.99999)[0] * sx);
    const { row } = edgeRow('skinBurley', sx, 90, 2 * radiusPx + 3, 45, 0.99999);
    let worst = 0;
    row.forEach((rgb, i) => {
      const exact = edgeResponse1D('skinBurley', (i + 0.5 - 45) / sx);
      rgb.forEach((v, c) => (worst = Math.max(worst, Math.abs(v - exact[c]))));
    });
    expect(worst).toBeLessThan(1e-3);
  });

  it('exact Gaussian pixel energies and the generic polar quadrature agree', () => {
    const rnd = random(11);
    const img = makeImage(14, 12, () => ({ colour: [rnd(), rnd(), rnd()], depth: 1, widthWorld: 0.35 }));
    const generic = { ...profiles.skin, gaussians: undefined };
    const a = denseConvolutionOracle({ ...img, profile: 'skin', projectionScale: [1, 1.2] });
    const b = denseConvolutionOracle({ ...img, profile: generic, projectionScale: [1, 1.2] });
    let worst = 0;
    for (let n = 0; n < a.length; n++) worst = Math.max(worst, Math.abs(a[n] - b[n]));
    expect(worst).toBeLessThan(1e-10);
  });

  it("'drop' leaks nothing across a depth edge beyond the threshold; masked pixels never contribute", () => {
    const width = 40;
    const img = makeImage(width, 21, (i) => ({
      colour: i < 15 ? [5, 5, 5] : i < 25 ? [1, 0, 0] : [0, 1, 1],
      depth: i < 25 ? 1 : 1.6,
      widthWorld: i < 15 ? 0 : 0.1,
    }));
    const out = denseConvolutionOracle({ ...img, profile: 'marble', projectionScale: [1, 1], followSurface: 'drop', depthThresholdWorld: 0.5 });
    for (let j = 0; j < 21; j++) {
      for (let i = 15; i < 25; i++) expect(at(out, width, i, j)).toEqual([1, 0, 0]);
      for (let i = 25; i < width; i++) expect(at(out, width, i, j)).toEqual([0, 1, 1]);
      for (let i = 0; i < 15; i++) expect(at(out, width, i, j)).toEqual([5, 5, 5]);
    }
  });

  it('keeps a constant image constant', () => {
    const rnd = random(13);
    // a few distinct depths (one pixel-energy table each) keep this fast
    const img = makeImage(20, 16, () => ({ colour: [0.2, 0.4, 0.8], depth: 1 + 0.1 * Math.floor(3 * rnd()), widthWorld: rnd() < 0.2 ? 0 : 0.3 }));
    for (const followSurface of ['off', 'drop', 'lerp']) {
      const out = denseConvolutionOracle({ ...img, profile: 'skin', projectionScale: [1, 1], followSurface, depthThresholdWorld: 0.1 });
      let worst = 0;
      for (let n = 0; n < out.length; n++) worst = Math.max(worst, Math.abs(out[n] - [0.2, 0.4, 0.8][n % 3]));
      expect(worst).toBeLessThan(1e-12);
    }
  });
});

describe('edge responses', () => {
  it('edgeResponse1D is 1/2 at the edge, → 1 inside, → 0 outside; kernelEdgeResponse1D counts taps', () => {
    edgeResponse1D('skin', 0).forEach((v) => expect(v).toBeCloseTo(0.5, 12));
    edgeResponse1D('milk', -200).forEach((v) => expect(v).toBeGreaterThan(0.999));
    edgeResponse1D('skinBurley', 30).forEach((v) => expect(v).toBeLessThan(1e-6));
    const k = integerKernel([0.5, 0.25]);
    expect(kernelEdgeResponse1D(k, 0)).toEqual([0.5, 0.5, 0.5]);
    expect(kernelEdgeResponse1D(k, 0.5)).toEqual([0.25, 0.25, 0.25]);
    expect(kernelEdgeResponse1D(k, -2)).toEqual([1, 1, 1]);
  });
});

describe('transmittance oracle', () => {
  it('evaluates the profile at thickness·(1 − translucency)/widthMm', () => {
    expect(transmittanceOracle({ thicknessMm: 0 })).toEqual(profiles.skin.transmittance(0));
    const t = transmittanceOracle({ thicknessMm: 2, profile: 'skinBurley', widthMm: 4, translucency: 0.5 });
    t.forEach((v, c) => expect(v).toBeCloseTo(profiles.skinBurley.transmittance(0.25)[c], 15));
    transmittanceOracle({ thicknessMm: 50, translucency: 1 }).forEach((v) => expect(v).toBeCloseTo(1, 15));
    expect(transmittanceOracle({ thicknessMm: Infinity })).toEqual([0, 0, 0]);
    // thick parts (a skull, ~ 10 mm) transmit nothing, thin ones (an ear, ~1 mm) transmit red
    expect(Math.max(...transmittanceOracle({ thicknessMm: 10 }))).toBeLessThan(1e-3);
    const ear = transmittanceOracle({ thicknessMm: 1 });
    expect(ear[0]).toBeGreaterThan(0.1);
    expect(ear[0]).toBeGreaterThan(10 * ear[2]);
    expect(() => transmittanceOracle({ thicknessMm: -1 })).toThrow(/thicknessMm/);
  });

  it('measures the thickness behind a point from a linear light depth map (gl-matrix light transform)', () => {
    // a light at (10, 1, 0) looking at the origin; a slab |x| ≤ 1 seen from the light along −x
    const view = mat4.lookAt(new Float64Array(16), [10, 1, 0], [0, 1, 0], [0, 1, 0]);
    const mapDepth = () => 9; // the lit face x = 1 is 9 units from the light everywhere on the map
    const back = thicknessFromLightDepth({
      lightViewMatrix: view,
      pointWorld: [-1, 1.3, 0.2],
      normalWorld: [-2, 0, 0], // not normalised on purpose
      shrinkWorld: 0.1,
      mapDepth,
    });
    // the map is read at the shrunk point (x = −0.9), the thickness measured from the point itself:
    // light depth 11 minus 9 (the shrink moves where the map is read, it does not shorten the thickness)
    expect(back).toBeCloseTo(2, 12);
    // a point in front of the recorded surface is that surface, lit directly: nothing comes through
    expect(thicknessFromLightDepth({ lightViewMatrix: view, pointWorld: [1.5, 1, 0], normalWorld: [1, 0, 0], mapDepth })).toBe(Infinity);
    // with a projection, the map is looked up at the projected uv; 0 there means nothing → Infinity
    const projection = mat4.perspective(new Float64Array(16), Math.PI / 4, 1, 0.1, 100);
    let seenUv;
    const withProjection = thicknessFromLightDepth({
      lightViewMatrix: view,
      lightProjectionMatrix: projection,
      pointWorld: [-1, 1, 0],
      normalWorld: [-1, 0, 0],
      shrinkWorld: 0,
      mapDepth: (position, uv) => {
        seenUv = uv;
        expect(vec3.length(position)).toBeCloseTo(11, 12);
        return 9;
      },
    });
    expect(withProjection).toBeCloseTo(2, 12);
    expect(seenUv[0]).toBeCloseTo(0.5, 12); // on the light's axis
    expect(seenUv[1]).toBeCloseTo(0.5, 12);
    const nothing = thicknessFromLightDepth({ lightViewMatrix: view, pointWorld: [-1, 1, 0], normalWorld: [-1, 0, 0], mapDepth: () => 0 });
    expect(nothing).toBe(Infinity);
    const outside = thicknessFromLightDepth({
      lightViewMatrix: view,
      lightProjectionMatrix: projection,
      pointWorld: [0, 1, 50],
      normalWorld: [-1, 0, 0],
      mapDepth: () => 9,
    });
    expect(outside).toBe(Infinity);
  });

  it('a surface of no thickness (a sheet): its far side reads thickness 0 at every angle and lets T(0) = 1 through; its lit side is a lit surface', () => {
    // The sheet z = 0; a directional light behind it (−z), turned by `a` about y; the camera in front (+z).
    const shrinkWorld = 0.06;
    const texelWorld = 0.02;
    for (const degrees of [0, 30, 60, 80, 89]) {
      const a = (degrees * Math.PI) / 180;
      const toLight = [Math.sin(a), 0, -Math.cos(a)];
      const view = mat4.lookAt(new Float64Array(16), toLight.map((v) => 10 * v), [0, 0, 0], [0, 1, 0]);
      // The sheet's depth along the light's ray through a light-view position (the map, exactly).
      const sheetDepth = (position) => {
        const world = vec3.transformMat4(new Float64Array(3), position, mat4.invert(new Float64Array(16), view));
        const onSheet = vec3.scaleAndAdd(new Float64Array(3), world, toLight, -world[2] / toLight[2]);
        return -vec3.transformMat4(new Float64Array(3), onSheet, view)[2];
      };
      const point = [0.3, -0.2, 0];
      const depth = -vec3.transformMat4(new Float64Array(3), point, view)[2];
      const far = (mapDepth) => thicknessFromLightDepth({ lightViewMatrix: view, pointWorld: point, normalWorld: [0, 0, 1], shrinkWorld, toLightWorld: toLight, texelWorld, mapDepth });
      expect(far(sheetDepth), `${degrees}°`).toBe(0);
      // A curved sheet's next triangle up to a twentieth of a texel's width off the plane is still the
      // sheet; past it, behind the point: nothing; in front: material, thickness measured from the point.
      expect(far((p) => sheetDepth(p) + 0.049 * texelWorld)).toBe(0);
      expect(far((p) => sheetDepth(p) + 0.051 * texelWorld)).toBe(Infinity);
      const inFront = far((p) => sheetDepth(p) - 0.051 * texelWorld);
      const stored = sheetDepth(vec3.transformMat4(new Float64Array(3), vec3.scaleAndAdd(new Float64Array(3), point, [0, 0, 1], -shrinkWorld), view)) - 0.051 * texelWorld;
      if (depth - stored > 0) expect(inFront).toBeCloseTo(depth - stored, 12);
      else expect(inFront).toBe(Infinity);
      // Seen from the lit side the shrink reads the sheet shrink · (1/cos a − cos a) in front: a lit surface.
      const c = Math.cos(a);
      const lit = thicknessFromLightDepth({ lightViewMatrix: view, pointWorld: point, normalWorld: [0, 0, -1], shrinkWorld, toLightWorld: toLight, texelWorld, mapDepth: sheetDepth });
      if (degrees === 0) expect(lit === Infinity || lit < 1e-12).toBe(true);
      else expect(lit).toBeCloseTo(shrinkWorld * (1 / c - c), 9);
    }
    // Through no thickness every profile lets all of it through, unfaded on the far side; the lit side's fade takes it all.
    for (const profile of ['skin', 'skinBurley', 'marble', 'milk']) {
      transmittedFractionOracle({ thicknessMm: 0, profile, shrinkMm: 0.6, farSide: true }).forEach((v) => expect(v).toBeCloseTo(1, 9));
      expect(transmittedFractionOracle({ thicknessMm: 0, profile, shrinkMm: 0.6 })).toEqual([0, 0, 0]);
    }
  });
});

describe('the accuracy suite\'s measurements (test/oracle/gratingFit.js, radialBlur)', () => {
  /** A grating image along x or y (`angleDeg` 0 or 90) at s px/mm: 0.5 + Σ a_k cos(2π f_k u), the same as RGBA. */
  const gratingImage = (width, height, s, angleDeg, frequencies, amplitudes) => {
    const image = new Float32Array(width * height * 4);
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const u = (angleDeg === 0 ? x + 0.5 - width / 2 : y + 0.5 - height / 2) / s;
        const v = 0.5 + frequencies.reduce((sum, f, k) => sum + amplitudes[k] * Math.cos(2 * Math.PI * f * u + 0.7 * k), 0);
        image.fill(v, (y * width + x) * 4, (y * width + x) * 4 + 4);
      }
    }
    return image;
  };

  it('a strip across an axis-aligned grating measures a known transfer exactly; a strip at another angle, or a small square, is refused', () => {
    const s = 2;
    const frequencies = frequenciesAt(s);
    const transfer = frequencies.map((f) => Math.exp(-f)); // any known attenuation per frequency
    for (const angleDeg of [0, 90]) {
      const [width, height] = angleDeg === 0 ? [256, 16] : [16, 256];
      const before = gratingImage(width, height, s, angleDeg, frequencies, frequencies.map(() => 0.1));
      const after = gratingImage(width, height, s, angleDeg, frequencies, transfer.map((t) => 0.1 * t));
      const measured = measuredTransfer({ width, height, before, after }, frequencies, s, angleDeg);
      for (let c = 0; c < 3; c++) measured[c].forEach((m, k) => expect(m).toBeCloseTo(transfer[k], 5));
      expect(() => measuredTransfer({ width, height, before, after }, frequencies, s, 45)).toThrow(RangeError);
      expect(() => measuredTransfer({ width, height, before, after }, frequencies, s, 90 - angleDeg)).toThrow(RangeError);
    }
    const small = gratingImage(64, 64, s, 0, frequencies, frequencies.map(() => 0.1));
    expect(() => measuredTransfer({ width: 64, height: 64, before: small, after: small }, frequencies, s, 0)).toThrow(/at least 96 px/);
    // A side keeps the kernel's reach (9 mm) from the border, at most all but the central 80 px.
    expect(gratingMargin(2, 256)).toBe(18);
    expect(gratingMargin(10, 256)).toBe(88);
  });

  it('radialBlur over a region is the whole image\'s result there, to the bit', () => {
    const size = 64;
    const next = random(7);
    const image = Float32Array.from({ length: size * size * 4 }, () => next());
    const region = { x0: 20, x1: 40, y0: 24, y1: 36 };
    const whole = radialBlur(image, size, size, 'skin', 3);
    const part = radialBlur(image, size, size, 'skin', 3, region);
    let compared = 0;
    for (let y = 0; y < size; y++) {
      for (let x = 0; x < size; x++) {
        const inside = x >= region.x0 && x < region.x1 && y >= region.y0 && y < region.y1;
        for (let c = 0; c < 3; c++) {
          const i = (y * size + x) * 3 + c;
          if (inside) {
            expect(part[i]).toBe(whole[i]);
            compared++;
          } else expect(part[i]).toBe(0);
        }
      }
    }
    expect(compared).toBe(20 * 12 * 3);
  });
});
