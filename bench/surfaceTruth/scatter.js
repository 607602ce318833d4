// The surface-space truth of subsurface scattering (pure float64, runs in Node and in the page):
// the light leaving each query point x is Σⱼ R(|x − xⱼ|) Eⱼ Aⱼ over surface samples j of the whole
// mesh (its UV atlas texels: world position xⱼ, area Aⱼ, diffuse light Eⱼ), with the 3D distance,
// as the diffusion approximation on a surface does (d'Eon & Luebke 2007, Jensen et al. 2001).
// Screen-space methods see only what the camera sees, along the screen; this sees the surface.
//
// R is a sum of normalised 2D Gaussians, R(r) = Σᵢ wᵢ exp(−r²/2vᵢ)/(2πvᵢ) (d'Eon's skin: written out
// in test/oracle/closedForms.js's GAUSSIANS, not taken from the library). A Gaussian much narrower than the
// samples' spacing cannot be summed over them (it would alias on the lattice); it keeps its energy
// where the light arrived: wᵢ · E(x), E(x) the query point's own diffuse light. Wider ones are
// summed: on a locally regular lattice of spacing h the sum of a Gaussian of σ ≥ 0.6 h matches its
// integral within 2 exp(−2π²σ²/h²) ≈ 1e-3 (the trapezoid rule's aliasing term). Wide Gaussians
// are summed over a coarser set of samples (the atlas merged 4 × 4), which holds the same light
// and area: each Gaussian takes the coarsest set it is at least 0.6 spacings wide on. An atlas's
// spacing varies over the mesh (0.14-0.47 mm on the head: the face gets more of the uv square than
// the shoulders), so the choice is made per query point from the spacing around it; with the
// spacing of the whole atlas, the shoulders' light came out striped by ±8 %.
//
// Each summed Gaussian is divided by its own sampled weight there, Σⱼ G(|x − xⱼ|) Aⱼ (a Shepard
// estimate): the atlas's lattice is not regular (uv distortion, seams, the merged blocks' edges),
// and on the head that weight was off by 3-8 % at the 1st and 99th percentiles of the face's
// points, changing with the atlas's resolution by as much as the whole effect at 640x360. The
// exact weight of a Gaussian over a surface curved as gently as the head (radius ≫ σ) is 1 within
// 0.3 %: light lost round a curve is below that, light lost at a cut of the mesh is left out.

/** Summed Gaussians need σ ≥ SUMMED_SIGMA_PER_SPACING × the samples' spacing (error ≈ 1e-3, above). */
export const SUMMED_SIGMA_PER_SPACING = 0.6;

/** The gather stops where the widest summed Gaussian falls below this fraction of its peak. */
export const GATHER_CUTOFF = 1e-5;

/**
 * @typedef {object} SurfaceSamples
 * @property {Float64Array} positionMm xyz per sample, millimetres
 * @property {Float64Array} areaMm2 per sample, mm²
 * @property {Float64Array} light rgb per sample: the diffuse light leaving it before scattering
 */

/**
 * The sample set each Gaussian is summed over at a point where the sets' spacings are `spacingsMm`,
 * or −1: kept local (narrower than the finest set allows).
 * @param {[number, number[]][]} gaussians [varianceMm2, rgb weights] pairs
 * @param {number[]} spacingsMm each sample set's spacing there, finest first
 * @returns {number[]} a level per Gaussian
 */
export function levelsOf(gaussians, spacingsMm) {
  return gaussians.map(([v]) => {
    let level = -1;
    spacingsMm.forEach((h, l) => { if (Math.sqrt(v) >= SUMMED_SIGMA_PER_SPACING * h) level = l; });
    return level;
  });
}

/** A sample set's typical spacing, mm: √ of its median area. */
export const spacingOf = (samples) => Math.sqrt(medianOf(samples.areaMm2));

/** Around each query point, the samples' spacing, mm: √ of their mean area within `radiusMm`. */
export function localSpacing(samples, queryMm, radiusMm = 0.75) {
  const fallback = spacingOf(samples);
  const area = new Float64Array(queryMm.length / 3);
  const count = new Float64Array(queryMm.length / 3);
  forEachNeighbour(samples, queryMm, radiusMm, (q, n) => { area[q] += samples.areaMm2[n]; count[q]++; });
  return area.map((a, q) => (count[q] ? Math.sqrt(a / count[q]) : fallback));
}

/** The median of a typed array (a copy is sorted). */
export function medianOf(values) {
  const sorted = Float64Array.from(values).sort();
  const n = sorted.length;
  return n % 2 ? sorted[(n - 1) / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

/**
 * Merges an atlas's samples block × block texels at a time into a coarser set holding the same
 * light and area: each merged sample sits at the area-weighted mean position with the area-weighted
 * mean light. Texels of a block lying more than `joinMm` from its first texel (another uv island:
 * neighbours in the atlas, apart on the mesh) are kept as samples of their own.
 * @param {import('./scatter.js').SurfaceSamples & { texel: Uint32Array }} samples texel: each sample's index in the atlas
 * @param {number} size the atlas's side, texels
 * @param {number} [block=4]
 * @param {number} [joinMm]
 * @returns {SurfaceSamples}
 */
export function coarsen(samples, size, block = 4, joinMm = 2 * block * spacingOf(samples)) {
  const blocksPerSide = Math.ceil(size / block);
  const members = new Map();
  samples.texel.forEach((t, n) => {
    const key = Math.floor((t / size) / block) * blocksPerSide + Math.floor((t % size) / block);
    if (!members.has(key)) members.set(key, []);
    members.get(key).push(n);
  });
  const out = { positionMm: [], areaMm2: [], light: [] };
  const p = samples.positionMm;
  const emit = (group) => {
    let area = 0;
    const pos = [0, 0, 0];
    const light = [0, 0, 0];
    for (const n of group) {
      const a = samples.areaMm2[n];
      area += a;
      for (let c = 0; c < 3; c++) { pos[c] += a * p[3 * n + c]; light[c] += a * samples.light[3 * n + c]; }
    }
    out.positionMm.push(...pos.map((x) => x / area));
    out.light.push(...light.map((x) => x / area));
    out.areaMm2.push(area);
  };
  const j2 = joinMm * joinMm;
  for (const group of members.values()) {
    const seed = group[0];
    const near = [];
    for (const n of group) {
      const d2 = (p[3 * n] - p[3 * seed]) ** 2 + (p[3 * n + 1] - p[3 * seed + 1]) ** 2 + (p[3 * n + 2] - p[3 * seed + 2]) ** 2;
      if (d2 <= j2) near.push(n);
      else emit([n]);
    }
    emit(near);
  }
  return { positionMm: Float64Array.from(out.positionMm), areaMm2: Float64Array.from(out.areaMm2), light: Float64Array.from(out.light) };
}

/** A uniform grid over sample positions, cells of `cellMm`: the samples of each cell, contiguous. */
function buildGrid(positionMm, cellMm) {
  const n = positionMm.length / 3;
  const min = [Infinity, Infinity, Infinity];
  for (let i = 0; i < n; i++) for (let a = 0; a < 3; a++) min[a] = Math.min(min[a], positionMm[3 * i + a]);
  const cellOf = (x, a) => Math.floor((x - min[a]) / cellMm);
  let dims = [0, 0, 0];
  for (let i = 0; i < n; i++) for (let a = 0; a < 3; a++) dims[a] = Math.max(dims[a], cellOf(positionMm[3 * i + a], a) + 1);
  const key = (cx, cy, cz) => (cz * dims[1] + cy) * dims[0] + cx;
  const counts = new Uint32Array(dims[0] * dims[1] * dims[2] + 1);
  const keys = new Uint32Array(n);
  for (let i = 0; i < n; i++) {
    keys[i] = key(cellOf(positionMm[3 * i], 0), cellOf(positionMm[3 * i + 1], 1), cellOf(positionMm[3 * i + 2], 2));
    counts[keys[i] + 1]++;
  }
  for (let k = 1; k < counts.length; k++) counts[k] += counts[k - 1]; // start of each cell
  const order = new Uint32Array(n);
  const fill = counts.slice(0, -1);
  for (let i = 0; i < n; i++) order[fill[keys[i]]++] = i;
  return { min, dims, cellMm, starts: counts, order, cellOf, key };
}

/**
 * Calls visit(query, sample, squaredDistanceMm2) for every sample within radiusMm of each query point.
 * @param {SurfaceSamples} samples @param {Float64Array} queryMm @param {number} radiusMm
 * @param {(q: number, n: number, d2: number) => void} visit
 */
function forEachNeighbour(samples, queryMm, radiusMm, visit) {
  const grid = buildGrid(samples.positionMm, radiusMm);
  const p = samples.positionMm;
  const r2max = radiusMm * radiusMm;
  const [dx, dy, dz] = grid.dims;
  for (let q = 0; q < queryMm.length / 3; q++) {
    const x = queryMm[3 * q];
    const y = queryMm[3 * q + 1];
    const z = queryMm[3 * q + 2];
    const cx = grid.cellOf(x, 0);
    const cy = grid.cellOf(y, 1);
    const cz = grid.cellOf(z, 2);
    for (let k = Math.max(cz - 1, 0); k <= Math.min(cz + 1, dz - 1); k++) {
      for (let j = Math.max(cy - 1, 0); j <= Math.min(cy + 1, dy - 1); j++) {
        for (let i = Math.max(cx - 1, 0); i <= Math.min(cx + 1, dx - 1); i++) {
          const cell = grid.key(i, j, k);
          for (let s = grid.starts[cell]; s < grid.starts[cell + 1]; s++) {
            const n = grid.order[s];
            const ex = p[3 * n] - x;
            const ey = p[3 * n + 1] - y;
            const ez = p[3 * n + 2] - z;
            const d2 = ex * ex + ey * ey + ez * ez;
            if (d2 <= r2max) visit(q, n, d2);
          }
        }
      }
    }
  }
}

/**
 * The surface truth at each query point.
 * @param {object} o
 * @param {SurfaceSamples[]} o.levels the whole surface, finest first (each set covers all of it)
 * @param {Float64Array} o.queryMm xyz per query point, millimetres
 * @param {Float64Array} o.queryLight rgb per query point: its own diffuse light (for the local Gaussians)
 * @param {[number, number[]][]} o.gaussians the profile, [varianceMm2, rgb weights]
 * @param {number} [o.widthMm=1] millimetres of material per profile millimetre (variances scale by its square)
 * @returns {{ light: Float64Array, spacingsMm: number[], localShare: number[] }} localShare: per
 *   Gaussian, the fraction of query points where it was kept local
 */
export function surfaceTruth({ levels, queryMm, queryLight, gaussians, widthMm = 1 }) {
  const scaled = gaussians.map(([v, w]) => [v * widthMm * widthMm, w]);
  const spacingsMm = levels.map(spacingOf);
  const queries = queryMm.length / 3;
  // Each point's spacings: its fine spacing, times how much coarser each set is overall.
  const fine = localSpacing(levels[0], queryMm);
  const assigned = new Int8Array(queries * scaled.length);
  const localCount = new Float64Array(scaled.length);
  const light = new Float64Array(3 * queries);
  for (let q = 0; q < queries; q++) {
    const at = levelsOf(scaled, spacingsMm.map((h) => (fine[q] * h) / spacingsMm[0]));
    at.forEach((level, m) => {
      assigned[q * scaled.length + m] = level;
      if (level >= 0) return;
      localCount[m]++;
      for (let c = 0; c < 3; c++) light[3 * q + c] += scaled[m][1][c] * queryLight[3 * q + c];
    });
  }
  levels.forEach((samples, l) => {
    const here = scaled.map((_, m) => m).filter((m) => assigned.some((level, k) => k % scaled.length === m && level === l));
    if (here.length) gather(samples, scaled, here, (q, m) => assigned[q * scaled.length + m] === l, queryMm, light);
  });
  return { light, spacingsMm, localShare: Array.from(localCount, (n) => n / queries) };
}

/**
 * Adds Σᵢ wᵢ Σⱼ Gᵢ(|x − xⱼ|) Eⱼ Aⱼ / Σⱼ Gᵢ(|x − xⱼ|) Aⱼ over `samples` to `light` at each query
 * point, for the Gaussians `indices` that `uses(query, index)` assigns to this set there.
 */
function gather(samples, gaussians, indices, uses, queryMm, light) {
  const widest = Math.max(...indices.map((m) => gaussians[m][0]));
  const radiusMm = Math.sqrt(2 * widest * Math.log(1 / GATHER_CUTOFF));
  const inverse = gaussians.map(([v]) => -1 / (2 * v));
  const { areaMm2: area, light: e } = samples;
  const k = indices.length;
  // Per query point and Gaussian: Σ G A, and Σ G E A per channel.
  const weight = new Float64Array(k);
  const sums = new Float64Array(3 * k);
  let current = -1;
  let active = [];
  const flush = () => {
    if (current < 0) return;
    for (const j of active) {
      if (!(weight[j] > 0)) continue;
      const w = gaussians[indices[j]][1];
      for (let c = 0; c < 3; c++) light[3 * current + c] += (w[c] * sums[3 * j + c]) / weight[j];
    }
    weight.fill(0);
    sums.fill(0);
  };
  forEachNeighbour(samples, queryMm, radiusMm, (q, n, d2) => {
    if (q !== current) {
      flush();
      current = q;
      active = indices.map((m, j) => (uses(q, m) ? j : -1)).filter((j) => j >= 0);
    }
    const a = area[n];
    for (const j of active) {
      const ga = Math.exp(d2 * inverse[indices[j]]) * a; // the norm 1/(2πv) cancels in the ratio
      weight[j] += ga;
      sums[3 * j] += ga * e[3 * n];
      sums[3 * j + 1] += ga * e[3 * n + 1];
      sums[3 * j + 2] += ga * e[3 * n + 2];
    }
  });
  flush();
}
