/**
 * Float64 CPU oracle of the screen-space blur, independent of the GPU path.
 *
 * Image conventions (shared with the GPU tests):
 * - images are row-major, rows bottom-up like GL: pixel (i, j), i = column, j = row, j = 0 is the bottom
 *   row, index j·width + i; colours are 3 floats per pixel;
 * - pixel (i, j) covers [i, i+1) × [j, j+1) in pixel coordinates, its centre is (i + 0.5, j + 0.5);
 * - `depth` is the linear view depth (world units, > 0 on surfaces), `widthWorld` the world length of one
 *   kernel millimetre at that pixel (0 = not a subsurface pixel);
 * - `projectionScale` = [P0, P5], the projection matrix's x and y scales (three.js elements[0], [5]).
 *
 * SAMPLING MODEL of `separableBlurOracle`: the numbered statement in docs/ARCHITECTURE.md ("Stage 3: the
 * sampling model"; REFERENCE §4 with the aspect bug fixed and the mask and depth rules made explicit),
 * which the GPU shader implements too. Here, in its terms: the centre of pixel (i, j) is
 * p = (i + 0.5, j + 0.5) and tap k ≥ 1 lies at p + a · offset_k · stepPx, a = (1, 0) for the horizontal
 * pass, (0, 1) for the vertical one; the horizontal pass's output is stored through `storeIntermediate`
 * (e.g. half-float rounding) before the vertical pass reads it; the skip (item 4) compares
 * stepPx · max_k |offset_k| with half a pixel; pixelWorld = 2·depth_c/(P·resolution) and
 * tilt = slope/pixelWorld (item 3).
 *
 * The older 'bilinear' tap filter (`tapFilter: 'bilinear'`) took a tap's mask and depth from the texel
 * containing it but its colour from plain bilinear filtering, so a tap within half a texel of a depth edge
 * blended up to half of the far side's colour (measured: 7 % of the far colour at a 17-tap skin depth edge,
 * stepPx 1.5, 'drop'); it is kept to measure that leak, and the GPU does not use it.
 *
 * `denseConvolutionOracle` is the ground truth the separable blur approximates: the full 2D convolution of
 * the piecewise-constant image (each pixel a constant square) with the radial profile, evaluated at
 * pixel centres, with the same mask and depth rules.
 * @module test/oracle/convolution
 */

import { vec2, vec3 } from 'gl-matrix';
import { normalIntervalProbability } from '../../src/math/specialFunctions.js';
import { integrateAdaptive } from '../../src/math/quadrature.js';
import { getProfile } from '../../src/profiles/presets.js';
import { kernelRadiusMm } from '../../src/profiles/kernel.js';

// The sampling model's numbers (not its code) are shared with the shaders: MIN_KERNEL_PIXELS (pixel
// skip), MAX_SLOPE (steeper neighbours count as another surface), PLANE_SLOPE_AGREEMENT and
// MAX_PLANE_SLOPE (one plane), SLOPE_FADE (the band over which each of those limits fades),
// ENERGY_LEFT ('footprint' stop).
import { ENERGY_LEFT, MAX_PLANE_SLOPE, MAX_SLOPE, MIN_KERNEL_PIXELS, PLANE_SLOPE_AGREEMENT, SLOPE_FADE } from '../../src/3-blur/samplingModel.js';

const FOLLOW_SURFACE_MODES = ['drop', 'lerp', 'off'];

/**
 * The sampling model's item 3 (shaders/common/surfaceSlope.glsl's rule): the depth change per pixel
 * along axis `axisIndex` at pixel (i, j), from its two neighbours: one plane (however steep) by how
 * well their one-sided slopes agree, else the one-sided slopes of the neighbours not steeper than
 * MAX_SLOPE; each limit fades over its band (fadeBelow). A neighbour counts where it is in the image
 * and on the surface (widthWorld > 0).
 * @param {{ width: number, height: number, depth: ArrayLike<number>, widthWorld: ArrayLike<number> }} image
 * @param {number} pixelWorld world units one pixel spans across the view at the pixel's depth
 */
export function surfaceSlopeOracle({ width, height, depth, widthWorld }, i, j, axisIndex, pixelWorld) {
  const centre = j * width + i;
  const side = (k) => {
    const [ii, jj] = axisIndex === 0 ? [Math.min(Math.max(i + k, 0), width - 1), j] : [i, Math.min(Math.max(j + k, 0), height - 1)];
    const t = jj * width + ii;
    return { slope: k < 0 ? depth[centre] - depth[t] : depth[t] - depth[centre], on: t !== centre && widthWorld[t] > 0 };
  };
  const [before, after] = [side(-1), side(1)];
  const steeper = Math.max(Math.abs(before.slope), Math.abs(after.slope));
  const plane = before.on && after.on ? fadeBelow(Math.abs(after.slope - before.slope), PLANE_SLOPE_AGREEMENT * steeper) * fadeBelow(steeper, MAX_PLANE_SLOPE * pixelWorld) : 0;
  const weight = (n) => (n.on ? fadeBelow(Math.abs(n.slope), MAX_SLOPE * pixelWorld) : 0);
  const [weightBefore, weightAfter] = [weight(before), weight(after)];
  // Their mean where both count; below a sum of 1 their weighted sum, which fades to 0 with them.
  const oneSided = (weightBefore * before.slope + weightAfter * after.slope) / Math.max(weightBefore + weightAfter, 1);
  return plane * 0.5 * (before.slope + after.slope) + (1 - plane) * oneSided;
}

/** The slope rule's fade (item 3): 1 up to limit / SLOPE_FADE, 0 from the limit, linear between; a limit of 0 is 1 at 0 only. */
function fadeBelow(value, limit) {
  const lo = limit / SLOPE_FADE;
  const hi = limit;
  if (hi <= lo) return value > 0 ? 0 : 1;
  return Math.min(Math.max((hi - value) / (hi - lo), 0), 1);
}

const newVec2 = () => new Float64Array(2); // gl-matrix's create() would give float32 storage
const newVec3 = () => new Float64Array(3);

function checkImageArgs({ width, height, diffuse, depth, widthWorld, projectionScale, followSurface, depthThresholdWorld }) {
  if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
    throw new RangeError(`width and height must be positive integers, got ${width} × ${height}`);
  }
  const n = width * height;
  if (!diffuse || diffuse.length !== 3 * n) throw new RangeError(`diffuse must hold width·height·3 = ${3 * n} values`);
  if (!depth || depth.length !== n) throw new RangeError(`depth must hold width·height = ${n} values`);
  if (!widthWorld || widthWorld.length !== n) throw new RangeError(`widthWorld must hold width·height = ${n} values`);
  if (!projectionScale || projectionScale.length !== 2) throw new TypeError('projectionScale must be [P0, P5]');
  if (!FOLLOW_SURFACE_MODES.includes(followSurface)) {
    throw new RangeError(`followSurface must be one of 'drop', 'lerp', 'off', got ${followSurface}`);
  }
  if (followSurface !== 'off' && !(depthThresholdWorld > 0)) {
    throw new RangeError(`depthThresholdWorld must be > 0 with followSurface '${followSurface}', got ${depthThresholdWorld}`);
  }
}

/**
 * Bilinear sample of an RGB image at pixel coordinates (x, y): texel centres at integer + 0.5,
 * clamp-to-edge addressing (what GL's LINEAR filter with CLAMP_TO_EDGE does).
 * @param {Float64Array|Float32Array} image width·height·3, rows bottom-up
 * @param {number} width
 * @param {number} height
 * @param {number} x
 * @param {number} y
 * @param {Float64Array} [out]
 * @returns {Float64Array} [r, g, b]
 */
export function sampleBilinear(image, width, height, x, y, out = newVec3()) {
  const u = x - 0.5;
  const v = y - 0.5;
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fx = u - i0;
  const fy = v - j0;
  const ia = Math.min(Math.max(i0, 0), width - 1);
  const ib = Math.min(Math.max(i0 + 1, 0), width - 1);
  const ja = Math.min(Math.max(j0, 0), height - 1);
  const jb = Math.min(Math.max(j0 + 1, 0), height - 1);
  for (let c = 0; c < 3; c++) {
    const bottom = image[(ja * width + ia) * 3 + c] * (1 - fx) + image[(ja * width + ib) * 3 + c] * fx;
    const top = image[(jb * width + ia) * 3 + c] * (1 - fx) + image[(jb * width + ib) * 3 + c] * fx;
    out[c] = bottom * (1 - fy) + top * fy;
  }
  return out;
}

/**
 * The 'bilinearPerTexel' tap: the mask and depth rules applied to each texel of the bilinear footprint.
 * Writes the tap colour into `out` and returns the kept fraction Σ_t b_t·keep_t (0: tap dropped).
 * @returns {number}
 */
function perTexelTap({ width, height, depth, mask, followSurface, depthThresholdWorld }, src, x, y, expectedDepth, centre, out) {
  const u = x - 0.5;
  const v = y - 0.5;
  const i0 = Math.floor(u);
  const j0 = Math.floor(v);
  const fx = u - i0;
  const fy = v - j0;
  let kept = 0;
  vec3.set(out, 0, 0, 0);
  const texel = newVec3();
  for (const [di, dj, b] of [
    [0, 0, (1 - fx) * (1 - fy)],
    [1, 0, fx * (1 - fy)],
    [0, 1, (1 - fx) * fy],
    [1, 1, fx * fy],
  ]) {
    if (b === 0) continue;
    const ii = Math.min(Math.max(i0 + di, 0), width - 1);
    const jj = Math.min(Math.max(j0 + dj, 0), height - 1);
    const t = jj * width + ii;
    if (!mask[t]) continue;
    vec3.set(texel, src[3 * t], src[3 * t + 1], src[3 * t + 2]);
    let keep = b;
    if (followSurface !== 'off') {
      const f = Math.min(Math.max(Math.abs(depth[t] - expectedDepth(ii, jj)) / depthThresholdWorld, 0), 1);
      if (followSurface === 'drop') keep *= 1 - f;
      else vec3.lerp(texel, texel, centre, f);
    }
    vec3.scaleAndAdd(out, out, texel, keep);
    kept += keep;
  }
  if (kept > 0) vec3.scale(out, out, 1 / kept);
  return kept;
}

/**
 * One 1D pass of the sampling model (see the module header).
 * @returns {Float64Array}
 */
function blurPass(args, src, axisIndex) {
  const { width, height, depth, widthWorld, mask, kernel, projectionScale, followSurface, depthThresholdWorld, tapFilter, footprint, foreshorten } = args;
  const taps = kernel.length / 4;
  const maxOffsetMm = kernelRadiusMm(kernel);
  const P = projectionScale[axisIndex];
  const resolution = axisIndex === 0 ? width : height;
  const axis = axisIndex === 0 ? vec2.fromValues(1, 0) : vec2.fromValues(0, 1);
  const out = new Float64Array(src.length);
  const p = newVec2();
  const pk = newVec2();
  const centre = newVec3();
  const colour = newVec3();
  const weight = newVec3();
  const sum = newVec3();
  const weightSum = newVec3();
  const term = newVec3();
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const idx = j * width + i;
      vec3.set(centre, src[3 * idx], src[3 * idx + 1], src[3 * idx + 2]);
      const wc = widthWorld[idx];
      const zc = depth[idx];
      let stepPx = wc === 0 ? 0 : ((wc * P) / (2 * zc)) * resolution;
      // Grazing angles (header, step 2b): slope per pixel from the same-surface neighbours.
      let slope = 0;
      if (foreshorten && wc !== 0) {
        const pixelWorld = (2 * zc) / (P * resolution);
        slope = surfaceSlopeOracle({ width, height, depth, widthWorld }, i, j, axisIndex, pixelWorld);
        const tilt = slope / pixelWorld;
        stepPx /= Math.sqrt(1 + tilt * tilt);
      }
      // Depth the centre's plane predicts at texel (ii, jj) (zc itself without foreshortening).
      const expectedDepth = (ii, jj) => zc + slope * (axisIndex === 0 ? ii - i : jj - j);
      if (!mask[idx] || stepPx * maxOffsetMm < MIN_KERNEL_PIXELS) {
        out.set(centre, 3 * idx);
        continue;
      }
      vec2.set(p, i + 0.5, j + 0.5);
      // One tap at `offsetPx` along the axis with kernel weight `w` (see the header, steps 4-5).
      const addTap = (offsetPx, w) => {
        vec2.scaleAndAdd(pk, p, axis, offsetPx);
        if (!(pk[0] >= 0 && pk[0] < width && pk[1] >= 0 && pk[1] < height)) return;
        vec3.copy(weight, w);
        if (tapFilter === 'bilinearPerTexel') {
          const keep = perTexelTap(args, src, pk[0], pk[1], expectedDepth, centre, colour);
          if (keep === 0) return;
          vec3.scale(weight, weight, keep);
        } else {
          const tidx = Math.floor(pk[1]) * width + Math.floor(pk[0]);
          if (!mask[tidx]) return;
          sampleBilinear(src, width, height, pk[0], pk[1], colour);
          if (followSurface !== 'off') {
            const f = Math.min(Math.max(Math.abs(depth[tidx] - expectedDepth(Math.floor(pk[0]), Math.floor(pk[1]))) / depthThresholdWorld, 0), 1);
            if (followSurface === 'drop') vec3.scale(weight, weight, 1 - f);
            else vec3.lerp(colour, colour, centre, f);
          }
        }
        vec3.add(sum, sum, vec3.multiply(term, weight, colour));
        vec3.add(weightSum, weightSum, weight);
      };
      if (!footprint) {
        vec3.set(weightSum, kernel[0], kernel[1], kernel[2]);
        vec3.multiply(sum, weightSum, centre);
        for (let k = 1; k < taps; k++) addTap(kernel[4 * k + 3] * stepPx, kernel.subarray(4 * k, 4 * k + 3));
      } else {
        // 'footprint' (header): the centre pixel, then footprints snapped to pixels, then the tail.
        const G = (xMm) => footprint.profile.marginalIntegral(0, xMm);
        // The table row nearest this pixel's scale; per footprint (outer edge, sample offset), mm.
        const { data, columns, rows } = footprint.table;
        const { min, perOctave } = footprint.scales;
        const row = Math.min(Math.max(Math.floor(Math.log2(stepPx / min) * perOctave + 0.5), 0), rows - 1);
        let below = G(0.5 / stepPx);
        vec3.set(weightSum, 2 * below[0], 2 * below[1], 2 * below[2]);
        vec3.multiply(sum, weightSum, centre);
        let lastEdge = 0;
        for (let j = 0; j < columns; j++) {
          if (below.every((g) => g > 0.5 - ENERGY_LEFT)) break;
          const edgeMm = data[2 * (row * columns + j)];
          const offsetMm = data[2 * (row * columns + j) + 1];
          const last = j === columns - 1 || edgeMm === Infinity;
          const edge = last ? lastEdge + 1 : Math.max(Math.floor(edgeMm * stepPx + 0.5), lastEdge + 1);
          const energy = last ? [0.5, 0.5, 0.5] : G((edge + 0.5) / stepPx);
          const w = energy.map((e, c) => e - below[c]);
          let offsetPx = Math.max(offsetMm * stepPx, lastEdge + 1);
          if (!last) offsetPx = Math.min(offsetPx, edge);
          addTap(offsetPx, w);
          addTap(-offsetPx, w);
          if (last) break;
          below = energy;
          lastEdge = edge;
        }
      }
      for (let c = 0; c < 3; c++) {
        const blurred = sum[c] / weightSum[c];
        // 'footprint' mode mixes with no scattering by `strength`, as the shader does.
        const s = footprint?.strength?.[c] ?? 1;
        out[3 * idx + c] = footprint ? centre[c] + (blurred - centre[c]) * s : blurred;
      }
    }
  }
  return out;
}

/**
 * The separable blur exactly as the GPU implements it (sampling model in the module header):
 * horizontal pass, `storeIntermediate` on every stored value, vertical pass.
 * @param {object} args
 * @param {number} args.width
 * @param {number} args.height
 * @param {Float64Array} args.diffuse width·height·3, rows bottom-up
 * @param {Float64Array} args.depth width·height linear view depth, world units
 * @param {Float64Array} args.widthWorld width·height world units per kernel-mm, 0 = not subsurface
 * @param {Float32Array} args.kernel from computeKernel
 * @param {number[]} args.projectionScale [P0, P5]
 * @param {'drop'|'lerp'|'off'} [args.followSurface='off']
 * @param {number} [args.depthThresholdWorld] > 0 unless followSurface is 'off'
 * @param {(x: number) => number} [args.storeIntermediate] applied to each value stored between the passes
 * @param {{ profile: object, table: { data: ArrayLike<number>, columns: number, rows: number },
 *   scales: { min: number, perOctave: number }, strength?: number[] }} [args.footprint] the GPU's 'footprint'
 *   kernel mode instead of the kernel's fixed taps: per pixel, the table row r = clamp(round(log2(stepPx / min)
 *   · perOctave), 0, rows − 1) gives per footprint j an outer edge and a sample offset (mm, pairs); the
 *   centre pixel weighs 2·G(0.5 px), then footprint j covers the pixels (lastEdge, edge_j] with
 *   edge_j = max(round(edge_j mm · stepPx), lastEdge + 1), weighs G(edge_j + 0.5 px) − G(lastEdge + 0.5 px)
 *   and is sampled at clamp(offset_j mm · stepPx, lastEdge + 1, edge_j); the last footprint (the last
 *   column, or an infinite edge) takes 0.5 − G and is sampled at max(offset · stepPx, lastEdge + 1); it stops
 *   once every channel's G exceeds 0.5 − 1e-5.
 *   G(x) = profile.marginalIntegral(0, x), in float64 (the GPU reads it from a table).
 * @param {ArrayLike<number>} [args.mask] width·height, nonzero on subsurface pixels (the GPU's diffuse alpha);
 *   default: widthWorld > 0. A masked pixel with width 0 (strength 0) keeps its colour and still serves as a tap.
 * @param {boolean} [args.foreshorten=false] the grazing-angle correction (header, step 2b); the GPU's default is on
 * @param {'bilinear'|'bilinearPerTexel'} [args.tapFilter='bilinearPerTexel'] 'bilinearPerTexel' is the GPU model
 *   (header); 'bilinear' takes a tap's mask and depth from its nearest texel and its colour from plain
 *   bilinear filtering, which lets colour leak across depth edges (kept to measure that leak)
 * @returns {Float64Array} width·height·3
 */
export function separableBlurOracle(args) {
  const full = { followSurface: 'off', storeIntermediate: (x) => x, tapFilter: 'bilinearPerTexel', ...args };
  // The mask: the diffuse light's alpha on the GPU; by default, the pixels with a width.
  full.mask ??= Float64Array.from(full.widthWorld, (w) => (w > 0 ? 1 : 0));
  checkImageArgs(full);
  if (!['bilinear', 'bilinearPerTexel'].includes(full.tapFilter)) {
    throw new RangeError(`tapFilter must be one of 'bilinear', 'bilinearPerTexel', got ${full.tapFilter}`);
  }
  const horizontal = blurPass(full, full.diffuse, 0);
  for (let n = 0; n < horizontal.length; n++) horizontal[n] = full.storeIntermediate(horizontal[n]);
  return blurPass(full, horizontal, 1);
}

/**
 * Per-pixel profile energies on a pixel lattice: entry (di, dj) = ∫∫ R over the pixel square centred at
 * (di/sx, dj/sy) mm, for |di| ≤ rx, |dj| ≤ ry.
 * - Gaussian sums: exact, the 2D Gaussian factorises, ∫∫ = Σ w · P_x · P_y with erf differences.
 * - otherwise: Q(x, y) = ∫_0^x ∫_0^y R dA at the lattice corners, pixel = Q(x1,y1) − Q(x0,y1) − Q(x1,y0) + Q(x0,y0).
 *   In polar coordinates about the origin, ∫_0^ρ R(r) r dr = cdf(ρ)/2π, so for a, b > 0
 *   Q(a, b) = (1/2π) [∫_0^θ* cdf(a/cos θ) dθ + ∫_θ*^{π/2} cdf(b/sin θ) dθ], θ* = atan2(b, a):
 *   smooth 1D integrals (adaptive Gauss-Legendre, 1e-14 absolute), no trouble with Burley's 1/r centre.
 * @returns {Float64Array} (2rx+1)(2ry+1)·3, index ((dj + ry)(2rx+1) + di + rx)·3 + c
 */
function pixelEnergyTable(profile, sx, sy, rx, ry) {
  const nx = 2 * rx + 1;
  const ny = 2 * ry + 1;
  const table = new Float64Array(nx * ny * 3);
  if (profile.gaussians) {
    const px = profile.gaussians.map((g) =>
      Array.from({ length: nx }, (_, k) => normalIntervalProbability((k - rx - 0.5) / sx, (k - rx + 0.5) / sx, g.varianceMm2)),
    );
    const py = profile.gaussians.map((g) =>
      Array.from({ length: ny }, (_, k) => normalIntervalProbability((k - ry - 0.5) / sy, (k - ry + 0.5) / sy, g.varianceMm2)),
    );
    for (let dj = 0; dj < ny; dj++) {
      for (let di = 0; di < nx; di++) {
        for (let c = 0; c < 3; c++) {
          let e = 0;
          profile.gaussians.forEach((g, n) => {
            e += g.weights[c] * px[n][di] * py[n][dj];
          });
          table[(dj * nx + di) * 3 + c] = e;
        }
      }
    }
    return table;
  }
  const cdf = profile.cdf ?? ((r) => profile.transmittance(r).map((t) => 1 - t));
  const options = { dim: 3, absTol: 1e-15, relTol: 1e-13 };
  const qPositive = (a, b) => {
    if (a === 0 || b === 0) return [0, 0, 0];
    const thetaStar = Math.atan2(b, a);
    const lower = integrateAdaptive((t) => cdf(a / Math.cos(t)), 0, thetaStar, options);
    const upper = integrateAdaptive((t) => cdf(b / Math.sin(t)), thetaStar, Math.PI / 2, options);
    return lower.map((v, c) => (v + upper[c]) / (2 * Math.PI));
  };
  // corners (k − 0.5)/s for k = −r..r+1; Q is odd in each coordinate
  const cx = Array.from({ length: nx + 1 }, (_, k) => (k - rx - 0.5) / sx);
  const cy = Array.from({ length: ny + 1 }, (_, k) => (k - ry - 0.5) / sy);
  const Q = [];
  for (let m = 0; m <= ny; m++) {
    const row = [];
    for (let k = 0; k <= nx; k++) {
      const s = Math.sign(cx[k]) * Math.sign(cy[m]);
      row.push(qPositive(Math.abs(cx[k]), Math.abs(cy[m])).map((v) => s * v));
    }
    Q.push(row);
  }
  for (let dj = 0; dj < ny; dj++) {
    for (let di = 0; di < nx; di++) {
      for (let c = 0; c < 3; c++) {
        table[(dj * nx + di) * 3 + c] = Q[dj + 1][di + 1][c] - Q[dj + 1][di][c] - Q[dj][di + 1][c] + Q[dj][di][c];
      }
    }
  }
  return table;
}

/**
 * Brute-force 2D convolution with the full radial profile (ground truth for the separable blur).
 * For each subsurface pixel c: sx, sy = pixels per mm along x and y from c's depth and widthWorld (same
 * scale formula as the separable model); every pixel whose centre lies within the radius holding
 * `coverage` of the energy (largest channel, in mm) contributes its colour with weight = the profile's
 * energy over that pixel's square (exact for Gaussian sums, 1e-14 quadrature otherwise; see
 * pixelEnergyTable). Pixels outside the image or with widthWorld 0 are dropped; depth rules as the
 * separable model ('drop' scales the weight by 1 − f, 'lerp' mixes the colour toward the centre's);
 * the sum is renormalised per channel. Non-subsurface pixels are copied.
 * @param {object} args
 * @param {number} args.width
 * @param {number} args.height
 * @param {Float64Array} args.diffuse
 * @param {Float64Array} args.depth
 * @param {Float64Array} args.widthWorld
 * @param {string|object} args.profile name or profile object
 * @param {number[]} args.projectionScale [P0, P5]
 * @param {number} [args.coverage=0.997]
 * @param {'drop'|'lerp'|'off'} [args.followSurface='off']
 * @param {number} [args.depthThresholdWorld]
 * @returns {Float64Array} width·height·3
 */
export function denseConvolutionOracle(args) {
  const full = { coverage: 0.997, followSurface: 'off', ...args };
  checkImageArgs(full);
  const { width, height, diffuse, depth, widthWorld, projectionScale, coverage, followSurface, depthThresholdWorld } = full;
  const profile = getProfile(full.profile);
  const radiusMm = Math.max(...profile.radiusMm(coverage));
  const tables = new Map(); // one table per distinct pixel scale
  const out = new Float64Array(diffuse.length);
  const centre = newVec3();
  const colour = newVec3();
  const weight = newVec3();
  const sum = newVec3();
  const weightSum = newVec3();
  const term = newVec3();
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const idx = j * width + i;
      vec3.set(centre, diffuse[3 * idx], diffuse[3 * idx + 1], diffuse[3 * idx + 2]);
      const wc = widthWorld[idx];
      if (wc === 0) {
        out.set(centre, 3 * idx);
        continue;
      }
      const zc = depth[idx];
      const sx = ((wc * projectionScale[0]) / (2 * zc)) * width;
      const sy = ((wc * projectionScale[1]) / (2 * zc)) * height;
      const rx = Math.floor(radiusMm * sx);
      const ry = Math.floor(radiusMm * sy);
      const key = `${sx},${sy}`;
      let table = tables.get(key);
      if (!table) {
        table = pixelEnergyTable(profile, sx, sy, rx, ry);
        tables.set(key, table);
      }
      const nx = 2 * rx + 1;
      vec3.set(sum, 0, 0, 0);
      vec3.set(weightSum, 0, 0, 0);
      for (let dj = -ry; dj <= ry; dj++) {
        const jj = j + dj;
        if (jj < 0 || jj >= height) continue;
        for (let di = -rx; di <= rx; di++) {
          const ii = i + di;
          if (ii < 0 || ii >= width) continue;
          const xMm = di / sx;
          const yMm = dj / sy;
          if (xMm * xMm + yMm * yMm > radiusMm * radiusMm) continue;
          const tidx = jj * width + ii;
          if (widthWorld[tidx] === 0) continue;
          const t = ((dj + ry) * nx + di + rx) * 3;
          vec3.set(weight, table[t], table[t + 1], table[t + 2]);
          vec3.set(colour, diffuse[3 * tidx], diffuse[3 * tidx + 1], diffuse[3 * tidx + 2]);
          if (followSurface !== 'off' && tidx !== idx) {
            const f = Math.min(Math.max(Math.abs(depth[tidx] - zc) / depthThresholdWorld, 0), 1);
            if (followSurface === 'drop') vec3.scale(weight, weight, 1 - f);
            else vec3.lerp(colour, colour, centre, f);
          }
          vec3.add(sum, sum, vec3.multiply(term, weight, colour));
          vec3.add(weightSum, weightSum, weight);
        }
      }
      for (let c = 0; c < 3; c++) out[3 * idx + c] = sum[c] / weightSum[c];
    }
  }
  return out;
}

/**
 * Exact response of a straight step edge under a radial profile: the image is 1 on the side x < 0 and 0
 * on x > 0 (edge along y); at signed distance xMm the output is ∫ I(x + t) a(t) dt = ∫_{t < −x} a(t) dt
 * = marginalIntegral(x, ∞) (a is even).
 * @param {string|object} profile
 * @param {number} xMm
 * @returns {number[]} [r, g, b]
 */
export function edgeResponse1D(profile, xMm) {
  return getProfile(profile).marginalIntegral(xMm, Infinity);
}

/**
 * The same step edge under a discrete 1D kernel with point taps: output(x) = Σ_{k: x + offset_k < 0} w_k
 * (a tap exactly on the edge counts half).
 * @param {Float32Array|number[]} kernel from computeKernel
 * @param {number} xMm
 * @returns {number[]} [r, g, b]
 */
export function kernelEdgeResponse1D(kernel, xMm) {
  const out = [0, 0, 0];
  for (let k = 0; k < kernel.length / 4; k++) {
    const position = xMm + kernel[4 * k + 3];
    const share = position < 0 ? 1 : position === 0 ? 0.5 : 0;
    for (let c = 0; c < 3; c++) out[c] += share * kernel[4 * k + c];
  }
  return out;
}

/**
 * Rounds a number to the nearest IEEE half float (round half to even, subnormals, overflow to ±Infinity):
 * a `storeIntermediate` hook emulating a HalfFloatType render target between the passes.
 * @param {number} x
 * @returns {number}
 */
export function roundToHalfFloat(x) {
  if (x === 0 || !Number.isFinite(x)) return x;
  const a = Math.abs(x);
  if (a >= 65520) return Math.sign(x) * Infinity; // 65504 is the largest half; ties at 65520 round up
  let e = Math.floor(Math.log2(a));
  if (2 ** e > a) e -= 1;
  else if (2 ** (e + 1) <= a) e += 1;
  const quantum = e < -14 ? 2 ** -24 : 2 ** (e - 10);
  const v = a / quantum;
  let r = Math.round(v);
  if (r - v === 0.5 && r % 2 === 1) r -= 1; // Math.round rounds ties up: make them even
  return Math.sign(x) * r * quantum;
}
