// The surface-space truth of subsurface scattering (pure float64, runs in Node and in the page):
// the light leaving each query point x is Σᵢ wᵢ ∫ Gᵢ(|x − y|) E(y) dA(y) over the whole mesh, with
// R(r) = Σᵢ wᵢ Gᵢ(r), Gᵢ(r) = exp(−r²/2vᵢ)/(2πvᵢ), the profile's 2D radial diffusion (d'Eon &
// Luebke 2007's Gaussians, test/oracle/closedForms.js) and E the diffuse light entering at y.
//
// r is the straight 3D distance, through the material: the dipole's BSSRDF is a function of
// |x − y| (Jensen et al. 2001), and where the surface curves gently (radius ≫ σ) it equals the
// distance along the surface within (σ/ρ)²; where it does not (an ear's rim, a lip), light does
// cross the tissue rather than run round it. (Across air, in an eyelid slit, it overestimates.)
//
// The integral is a sum over sub-triangles of the mesh: each triangle is split in four at its
// edges' midpoints, recursively, into congruent pieces of exactly a quarter of its area, so the
// samples' areas sum to the mesh's area and no per-Gaussian renormalisation is needed (the UV
// atlas's texels, the previous samples, had areas estimated from derivatives, and their uneven
// lattice at seams moved the truth by half the effect until each Gaussian was renormalised).
// Each Gaussian is summed over pieces no longer than EDGE_PER_SIGMA · σ along their longest edge
// (the midpoint rule's error for a piece of edge h is about h²/(24σ²) of its term and cancels to
// higher order over a smooth Gaussian), each piece carrying the mean of E over its area, E read at
// the centroids of its sub-pieces no longer than `lightEdgeMm` (finer than the light's own detail:
// the camera's pixels). A Gaussian narrower than LOCAL_SIGMA_PER_PIXEL of a query point's pixel
// footprint is kept local there, wᵢ E(x): the light is one value across that pixel, and the
// Gaussian's mass outside the pixel is below 4 · erfc(2/√2)/2 ≈ 9 % of its weight (half a pixel
// is 2σ), a share of the light of the pixel's neighbours that the pixel keeps instead. (At 0.2
// the eye close-up's narrowest Gaussian would be summed over pieces of 0.08 mm: 12 million.) The
// rule does not change with the samples' density: the bench's density check moves the sums only.
//
// The sums run piece by piece (streamed, nothing stored): each piece at a Gaussian's size is
// splatted to the query points within the Gaussian's cut-off radius.

/** A piece's light: r, g, b, the share of its area the camera sees, and r, g, b times that share. */
export const LIGHT_CHANNELS = 7;

/** sumOverPieces's ideal-blur sums where none are kept. */
const NO_BLUR_SUMS = Object.freeze({ area: null, seenArea: null, seenLight: null });

/** A Gaussian is summed over pieces whose longest edge is at most this times its σ. */
export const EDGE_PER_SIGMA = 1;

/** A Gaussian with σ below this fraction of a query point's pixel footprint is kept local there. */
export const LOCAL_SIGMA_PER_PIXEL = 0.25;

/** Each Gaussian's sum stops where it falls below this fraction of its peak (4.8 σ). */
export const GATHER_CUTOFF = 1e-5;

/**
 * @typedef {object} Triangles
 * @property {Float64Array} positionMm 9 per triangle: its corners, millimetres
 * @property {Float64Array} uv 6 per triangle: its corners' texture coordinates
 */

/** Each Gaussian's σ, sample edge and cut-off radius (mm), at a profile scale `widthMm`. */
function scaledGaussians(gaussians, widthMm, density) {
  return gaussians.map(([v, w]) => {
    const variance = v * widthMm * widthMm;
    const sigma = Math.sqrt(variance);
    return { variance, sigma, w, edgeMm: (EDGE_PER_SIGMA * sigma) / Math.sqrt(density), radiusMm: Math.sqrt(2 * variance * Math.log(1 / GATHER_CUTOFF)) };
  });
}

/**
 * A uniform grid over points, cells of `cellMm`, each cell's points contiguous.
 * @param {Float64Array} pointsMm xyz per point
 * @param {number[]} members the indices of the points it holds
 */
export function pointGrid(pointsMm, members, cellMm) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const q of members) for (let a = 0; a < 3; a++) { min[a] = Math.min(min[a], pointsMm[3 * q + a]); max[a] = Math.max(max[a], pointsMm[3 * q + a]); }
  const dims = members.length ? min.map((m, a) => Math.floor((max[a] - m) / cellMm) + 1) : [0, 0, 0];
  const key = (i, j, k) => (k * dims[1] + j) * dims[0] + i;
  const cell = (x, a) => Math.floor((x - min[a]) / cellMm);
  const starts = new Uint32Array(dims[0] * dims[1] * dims[2] + 1);
  const keys = members.map((q) => key(cell(pointsMm[3 * q], 0), cell(pointsMm[3 * q + 1], 1), cell(pointsMm[3 * q + 2], 2)));
  for (const k of keys) starts[k + 1]++;
  for (let k = 1; k < starts.length; k++) starts[k] += starts[k - 1];
  const order = new Uint32Array(members.length);
  const fill = starts.slice(0, -1);
  keys.forEach((k, n) => { order[fill[k]++] = members[n]; });
  /**
   * Calls visit(point) for the points in the cells that the box of half-side r around (x, y, z)
   * touches: all within r of it (and some farther); stops when visit returns true, returning true.
   */
  const within = (x, y, z, r, visit) => {
    const i0 = Math.max(cell(x - r, 0), 0);
    const i1 = Math.min(cell(x + r, 0), dims[0] - 1);
    if (i0 > i1) return false;
    const j1 = Math.min(cell(y + r, 1), dims[1] - 1);
    const k1 = Math.min(cell(z + r, 2), dims[2] - 1);
    for (let k = Math.max(cell(z - r, 2), 0); k <= k1; k++) {
      for (let j = Math.max(cell(y - r, 1), 0); j <= j1; j++) {
        const to = starts[key(i1, j, k) + 1]; // the cells i0..i1 of a row are contiguous
        for (let s = starts[key(i0, j, k)]; s < to; s++) if (visit(order[s]) === true) return true;
      }
    }
    return false;
  };
  const stop = () => true;
  return { cellMm, within, any: (x, y, z, r) => within(x, y, z, r, stop) };
}

/**
 * Visits the mesh's pieces: each triangle split in four at its edges' midpoints, recursively, while
 * `split(piece)` says so. `leaf(piece)` returns the light of a piece that is not split (r, g, b
 * and, optionally, the share of it the camera sees, 1 if left out); a split piece's light is its
 * four children's mean (equal areas), LIGHT_CHANNELS numbers: r, g, b, the share seen, and the
 * light seen (r, g, b times that share). `emit(piece, light)` is called for every
 * piece, after its light. A piece (one object per depth, reused: read it in the call) has corners
 * a, b, c (mm, [x, y, z]) and their uvs ua, ub, uc, its area (mm²), longest edge (mm), centroid,
 * depth (0: a triangle of the mesh) and parent (null at depth 0); fields set on it by `split` stay
 * until its children are visited.
 * @param {Triangles} triangles
 * @param {{ split: (p: object) => boolean, leaf: (p: object) => ArrayLike<number>, emit: (p: object, light: Float64Array) => void }} visitor
 */
export function forEachPiece(triangles, { split, leaf, emit }) {
  const { positionMm: p, uv } = triangles;
  const stack = [];
  const at = (depth) => {
    while (stack.length <= depth) {
      const parent = stack.length ? stack[stack.length - 1] : null;
      stack.push({
        a: new Float64Array(3), b: new Float64Array(3), c: new Float64Array(3), ua: new Float64Array(2), ub: new Float64Array(2), uc: new Float64Array(2),
        centroid: new Float64Array(3), light: new Float64Array(LIGHT_CHANNELS), areaMm2: 0, edgeMm: 0, depth: stack.length, parent,
      });
    }
    return stack[depth];
  };
  // Sets the piece at `depth` to the triangle (corners x, y, z of a, b, c and their uvs) and visits it.
  const visit = (depth, ax, ay, az, bx, by, bz, cx, cy, cz, uax, uay, ubx, uby, ucx, ucy, areaMm2) => {
    const piece = at(depth);
    piece.a[0] = ax; piece.a[1] = ay; piece.a[2] = az;
    piece.b[0] = bx; piece.b[1] = by; piece.b[2] = bz;
    piece.c[0] = cx; piece.c[1] = cy; piece.c[2] = cz;
    piece.ua[0] = uax; piece.ua[1] = uay; piece.ub[0] = ubx; piece.ub[1] = uby; piece.uc[0] = ucx; piece.uc[1] = ucy;
    piece.centroid[0] = (ax + bx + cx) / 3; piece.centroid[1] = (ay + by + cy) / 3; piece.centroid[2] = (az + bz + cz) / 3;
    piece.areaMm2 = areaMm2;
    piece.edgeMm = Math.sqrt(Math.max((ax - bx) ** 2 + (ay - by) ** 2 + (az - bz) ** 2, (bx - cx) ** 2 + (by - cy) ** 2 + (bz - cz) ** 2, (cx - ax) ** 2 + (cy - ay) ** 2 + (cz - az) ** 2));
    const { light } = piece;
    if (split(piece)) {
      // Midpoints (ab, bc, ca) in locals: the children reuse the next depth's piece.
      const abx = (ax + bx) / 2; const aby = (ay + by) / 2; const abz = (az + bz) / 2;
      const bcx = (bx + cx) / 2; const bcy = (by + cy) / 2; const bcz = (bz + cz) / 2;
      const cax = (cx + ax) / 2; const cay = (cy + ay) / 2; const caz = (cz + az) / 2;
      const uabx = (uax + ubx) / 2; const uaby = (uay + uby) / 2; const ubcx = (ubx + ucx) / 2;
      const ubcy = (uby + ucy) / 2; const ucax = (ucx + uax) / 2; const ucay = (ucy + uay) / 2;
      const q = areaMm2 / 4;
      // Each child's light is read before the next child reuses its piece.
      let e = visit(depth + 1, ax, ay, az, abx, aby, abz, cax, cay, caz, uax, uay, uabx, uaby, ucax, ucay, q);
      for (let k = 0; k < LIGHT_CHANNELS; k++) light[k] = e[k];
      e = visit(depth + 1, abx, aby, abz, bx, by, bz, bcx, bcy, bcz, uabx, uaby, ubx, uby, ubcx, ubcy, q);
      for (let k = 0; k < LIGHT_CHANNELS; k++) light[k] += e[k];
      e = visit(depth + 1, cax, cay, caz, bcx, bcy, bcz, cx, cy, cz, ucax, ucay, ubcx, ubcy, ucx, ucy, q);
      for (let k = 0; k < LIGHT_CHANNELS; k++) light[k] += e[k];
      e = visit(depth + 1, abx, aby, abz, bcx, bcy, bcz, cax, cay, caz, uabx, uaby, ubcx, ubcy, ucax, ucay, q);
      for (let k = 0; k < LIGHT_CHANNELS; k++) light[k] = (light[k] + e[k]) / 4;
    } else {
      const e = leaf(piece);
      const seen = e.length > 3 ? e[3] : 1;
      light[0] = e[0]; light[1] = e[1]; light[2] = e[2];
      light[3] = seen; light[4] = seen * e[0]; light[5] = seen * e[1]; light[6] = seen * e[2];
    }
    emit(piece, light);
    return light;
  };
  for (let t = 0; t < p.length / 9; t++) {
    const k = 9 * t;
    const u = 6 * t;
    const area = triangleArea([p[k], p[k + 1], p[k + 2]], [p[k + 3], p[k + 4], p[k + 5]], [p[k + 6], p[k + 7], p[k + 8]]);
    visit(0, p[k], p[k + 1], p[k + 2], p[k + 3], p[k + 4], p[k + 5], p[k + 6], p[k + 7], p[k + 8], uv[u], uv[u + 1], uv[u + 2], uv[u + 3], uv[u + 4], uv[u + 5], area);
  }
}

/** The area of the triangle a, b, c (mm²). */
export function triangleArea(a, b, c) {
  const e = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const f = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  return Math.hypot(e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]) / 2;
}

/**
 * The surface truth at each query point.
 * @param {object} o
 * @param {Triangles} o.triangles the whole subsurface mesh, world millimetres
 * @param {(x: number[], uv: number[]) => number[]} o.lightAt the diffuse light entering at a surface
 *   point (r, g, b) and, for the ideal blurs, a fourth number: 1 where the camera sees it, 0
 *   where it does not (1 if left out)
 * @param {Float64Array} o.queryMm xyz per query point, millimetres
 * @param {Float64Array} o.queryLight rgb per query point: its own light (for the local Gaussians)
 * @param {Float64Array} o.queryPixelMm per query point: its pixel's footprint, mm (the local rule)
 * @param {[number, number[]][]} o.gaussians the profile, [varianceMm2, rgb weights]
 * @param {number} [o.widthMm=1] millimetres of material per profile millimetre
 * @param {number} [o.lightEdgeMm] the longest edge of a piece whose light is read at its centroid
 * @param {number} [o.density=1] samples per area relative to the rule above (2: √2 shorter edges,
 *   twice the samples); the local rule does not change with it (the pixels' light is what it is)
 * @param {boolean} [o.idealBlurs=false] also return the ideal blurs of what is seen (idealBlursOf)
 * @returns {{ light: Float64Array, localShare: number[], pieces: number[], lightReads: number, idealBlurs?: { seen: Float64Array, seenTrueArea: Float64Array } }}
 *   per Gaussian: the share of query points where it was kept local, and the pieces summed
 */
export function surfaceTruth({ triangles, lightAt, queryMm, queryLight, queryPixelMm, gaussians, widthMm = 1, lightEdgeMm = Infinity, density = 1, idealBlurs = false }) {
  const scaled = scaledGaussians(gaussians, widthMm, density);
  const queries = queryMm.length / 3;
  const light = new Float64Array(3 * queries);
  const localShare = [];
  // Per Gaussian: the query points that sum it (a grid of them), the others keeping it local.
  const grids = scaled.map((g) => {
    const members = [];
    for (let q = 0; q < queries; q++) {
      if (g.sigma >= LOCAL_SIGMA_PER_PIXEL * queryPixelMm[q] || !(queryPixelMm[q] > 0)) { members.push(q); continue; }
      for (let c = 0; c < 3; c++) light[3 * q + c] += g.w[c] * queryLight[3 * q + c];
    }
    localShare.push(1 - members.length / queries);
    return members.length ? pointGrid(queryMm, members, g.radiusMm / 2) : null;
  });
  const blurSums = idealBlurs ? grids.map((grid) => (grid ? { area: new Float64Array(queries), seenArea: new Float64Array(queries), seenLight: new Float64Array(3 * queries) } : null)) : null;
  const { pieces, lightReads } = sumOverPieces({ triangles, lightAt, queryMm, scaled, grids, light, lightEdge: lightEdgeMm / Math.sqrt(density), blurSums });
  return { light, localShare, pieces, lightReads, ...(idealBlurs ? { idealBlurs: idealBlursOf(scaled, blurSums, queryLight) } : {}) };
}

/**
 * Ideal blurs of what a view sees, from the per-Gaussian sums (sumOverPieces's blurSums):
 * - `seen`: each summed Gaussian's mean of the light over the surface the camera sees, weighted
 *   by the Gaussian at the 3D distance and the true area: an ideal normalised screen blur (an
 *   exact kernel, a perfect depth rule, summing to 1 over the surface it keeps as every screen
 *   blur's kernel does). Not a bound: a real blur's own errors can land nearer the truth;
 * - `seenTrueArea`: the light seen, with the area the camera does not see filled with that mean:
 *   a screen method that also knew the surface's true area within reach (more than a plane's in
 *   a fold, less round a convex edge) but not the light the camera cannot see.
 * A Gaussian kept local is the same in both as in the truth; where a Gaussian reaches no surface
 * the camera sees, its mean is the point's own light (times its whole area in `seenTrueArea`).
 */
function idealBlursOf(scaled, blurSums, queryLight) {
  const queries = queryLight.length / 3;
  const seen = new Float64Array(3 * queries);
  const seenTrueArea = new Float64Array(3 * queries);
  scaled.forEach(({ w }, m) => {
    const sums = blurSums[m];
    for (let q = 0; q < queries; q++) {
      for (let c = 0; c < 3; c++) {
        const own = queryLight[3 * q + c];
        if (!sums || !(sums.area[q] > 0)) { // kept local here (or at every point): as the truth
          seen[3 * q + c] += w[c] * own;
          seenTrueArea[3 * q + c] += w[c] * own;
          continue;
        }
        const mean = sums.seenArea[q] > 0 ? sums.seenLight[3 * q + c] / sums.seenArea[q] : own;
        seen[3 * q + c] += w[c] * mean;
        seenTrueArea[3 * q + c] += w[c] * (sums.seenLight[3 * q + c] + (sums.area[q] - sums.seenArea[q]) * mean);
      }
    }
  });
  return { seen, seenTrueArea };
}

/**
 * near(m, piece): whether a point summing Gaussian m may lie within its radius + 2 edges of the
 * piece's centroid (a child's centroid lies within one edge of its parent's: a piece reached is
 * never missed), asked of this Gaussian's grid or, for a large piece, of the first coarser one
 * (its points include these) whose cells are at least a third of the reach.
 */
function nearTest(scaled, grids, summed) {
  const askers = scaled.map((g) => summed.filter((k) => scaled[k].sigma >= g.sigma).map((k) => grids[k]));
  return (m, piece) => {
    const reach = scaled[m].radiusMm + 2 * piece.edgeMm;
    const list = askers[m];
    let grid = list[list.length - 1];
    for (const candidate of list) if (candidate.cellMm * 3 >= reach) { grid = candidate; break; }
    return grid.any(piece.centroid[0], piece.centroid[1], piece.centroid[2], reach);
  };
}

/**
 * Adds each summed Gaussian's sum over the mesh's pieces to `light` at the query points that sum
 * it (`grids[m]`, null where none does); returns the pieces summed per Gaussian and the light reads.
 * With `blurSums` (per Gaussian, null where it is not summed) it also adds, per query point, the
 * Gaussian's area weight Σ G·A (`area`), its part on the surface the camera sees (`seenArea`) and
 * the light seen (`seenLight`, r, g, b), unweighted by the profile.
 */
function sumOverPieces({ triangles, lightAt, queryMm, scaled, grids, light, lightEdge, blurSums = null }) {
  const summed = scaled.map((g, m) => m).filter((m) => grids[m]);
  const pieces = scaled.map(() => 0);
  let lightReads = 0;
  const near = nearTest(scaled, grids, summed);
  const uv = [0, 0];
  const none = [0, 0, 0, 0];
  // One splat: the piece's light e at (x, y, z) into the points within Gaussian m's radius.
  let sx = 0; let sy = 0; let sz = 0; let sr = 0; let sg = 0; let sb = 0; let sVariance = 1; let sR2 = 0; let sNorm = 0; let sw = none;
  let sSeen = 0; let sSeenR = 0; let sSeenG = 0; let sSeenB = 0;
  let sArea = null; let sSeenArea = null; let sSeenLight = null; // the Gaussian's ideal-blur sums, or null
  const splat = (q) => {
    const d2 = (queryMm[3 * q] - sx) ** 2 + (queryMm[3 * q + 1] - sy) ** 2 + (queryMm[3 * q + 2] - sz) ** 2;
    if (d2 > sR2) return;
    const g = sNorm * Math.exp(-d2 / (2 * sVariance));
    light[3 * q] += sw[0] * g * sr;
    light[3 * q + 1] += sw[1] * g * sg;
    light[3 * q + 2] += sw[2] * g * sb;
    if (sArea !== null) { // the Gaussian's own sums for the ideal blurs (unweighted)
      sArea[q] += g;
      sSeenArea[q] += g * sSeen;
      sSeenLight[3 * q] += g * sSeenR;
      sSeenLight[3 * q + 1] += g * sSeenG;
      sSeenLight[3 * q + 2] += g * sSeenB;
    }
  };
  const readAt = (piece, out) => {
    lightReads++;
    const { ua, ub, uc } = piece;
    uv[0] = (ua[0] + ub[0] + uc[0]) / 3;
    uv[1] = (ua[1] + ub[1] + uc[1]) / 3;
    const e = lightAt(piece.centroid, uv);
    out[0] = e[0]; out[1] = e[1]; out[2] = e[2]; out[3] = e.length > 3 ? e[3] : 1;
    return out;
  };
  forEachPiece(triangles, {
    // A piece is summed for the Gaussians at its size in reach. It is split while it is larger
    // than a Gaussian in reach, or while its light is wanted (it or a parent is summed) and it is
    // larger than the light's edge for the finest Gaussian summed there (half that Gaussian's
    // edge, never below lightEdgeMm). At the light's edge its light is read once: smaller pieces
    // (split for a fine Gaussian) share it, the light having no detail below that.
    split(piece) {
      const { edgeMm, parent } = piece;
      piece.sums = piece.sums ?? [];
      piece.sums.length = 0;
      piece.needEdgeMm = parent ? parent.needEdgeMm : Infinity;
      for (const m of summed) {
        const h = scaled[m].edgeMm;
        if (edgeMm <= h && (piece.depth === 0 || edgeMm > h / 2) && near(m, piece)) {
          piece.sums.push(m);
          piece.needEdgeMm = Math.min(piece.needEdgeMm, Math.max(lightEdge, h / 2));
        }
      }
      piece.wanted = piece.sums.length > 0 || (parent !== null && parent.wanted);
      piece.shared = parent !== null && parent.shared !== null ? parent.shared : null;
      let split = piece.wanted && edgeMm > piece.needEdgeMm;
      if (!split) for (const m of summed) if (scaled[m].edgeMm < edgeMm && near(m, piece)) { split = true; break; }
      if (split && piece.shared === null && edgeMm <= lightEdge) piece.shared = readAt(piece, piece.read ??= new Float64Array(4));
      return split;
    },
    leaf(piece) {
      if (piece.shared !== null) return piece.shared;
      return piece.wanted ? readAt(piece, piece.read ??= new Float64Array(4)) : none;
    },
    emit(piece, e) {
      for (const m of piece.sums) {
        pieces[m]++;
        ({ variance: sVariance, w: sw } = scaled[m]);
        sR2 = scaled[m].radiusMm ** 2;
        sNorm = piece.areaMm2 / (2 * Math.PI * sVariance);
        sx = piece.centroid[0]; sy = piece.centroid[1]; sz = piece.centroid[2];
        sr = e[0]; sg = e[1]; sb = e[2];
        sSeen = e[3]; sSeenR = e[4]; sSeenG = e[5]; sSeenB = e[6];
        ({ area: sArea, seenArea: sSeenArea, seenLight: sSeenLight } = blurSums ? blurSums[m] : NO_BLUR_SUMS);
        grids[m].within(sx, sy, sz, scaled[m].radiusMm, splat);
      }
    },
  });
  return { pieces, lightReads };
}
