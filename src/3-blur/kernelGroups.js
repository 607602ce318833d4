// The isotropic blur's groups (pure, runs in Node). A horizontal then vertical blur with the 1D
// kernel a gives the 2D kernel a(x)·a(y), whose transfer at frequency f and angle θ is
// A(f cos θ)·A(f sin θ) (A: a's Fourier transform), not the radial profile's M(f) = A(f): on the
// diagonal A(f/√2)², 0.18 below M(f) for d'Eon skin's red at 0.8 cycles/mm. A 2D Gaussian is
// exactly separable, and a profile is a sum of them (its own, or gaussianFit.js's fit). Blurring
// groups of them separately and summing, Σ_g a_g(x)·a_g(y) / W_g (a_g: the group's marginal, W_g
// its energy), leaves only the cross terms inside each group: its transfer is
//   T(f, θ) = Σ_g A_g(f cos θ)·A_g(f sin θ) / W_g,   exactly A(f) along the axes (θ = 0, 90°).
// The groups are contiguous runs of the Gaussians sorted by variance, chosen per channel (each
// channel of a group is its own blur) to make the worst |T − M| least over the angles and the
// frequencies a scale shows; 'auto' takes the fewest groups within ISOTROPY_ERROR.
// The WebGL blur (method 'footprint', shaders/3-blur/kernelGroups.glsl) splits each footprint's
// exact marginal energy between the groups by footprintGroupFractions (below), taken at the
// footprint table row's scale, and carries the groups between its passes packed as halves: the
// same taps and fetches as one group, with the vertical pass reading the third and fourth groups'
// texel only when the frame has more than two. (A first design, one half-float attachment per group and the group energies
// from erf per Gaussian and tap, measured 7.1x the one-group blur's time.)
// test/node/3-blur/kernelGroups.test.js holds the closed forms.
import { gaussianSumOf } from '../profiles/gaussianFit.js';
import { FOOTPRINT_ROWS, footprintRowOf, footprintRowScale } from '../profiles/footprints.js';
import { checkInteger } from '../support/parameterChecks.js';
import { erfc } from '../math/specialFunctions.js';

/**
 * 'auto' groups: the fewest whose separable error |T − M| is at most this at every angle, for the
 * gratings a scale shows with at least 4 pixels per cycle (f ≤ px per mm / 4, as the accuracy suite
 * asserts), and whose step edge at 45° is within ISOTROPY_STEP_ERROR. The accuracy suite's 0.03
 * holds the blur's own error along the axes too (measured up to 0.026 at 5 px/mm).
 */
export const ISOTROPY_ERROR = 0.016;

/**
 * 'auto' groups: the most a step edge at 45° may differ from the radial profile's, a fraction of
 * the step, as seen through the pixels (each term widened by a pixel's variance, 1/12 px²): the
 * accuracy suite asserts 1 % for the whole blur.
 */
export const ISOTROPY_STEP_ERROR = 0.006;

/**
 * The most groups: the blur carries four groups' RGB and the coverage between its passes in two
 * RGBA32UI texels (halves; shaders/3-blur/kernelGroups.glsl). Closed forms at 1–10 px/mm: skin
 * 0.013–0.021 with three, skinBurley 0.030–0.032 with three and 0.010–0.016 with four, milk 0.020
 * with four.
 */
export const MAX_KERNEL_GROUPS = 4;

/** The angles the transfer error is taken at: by symmetry 0..45° covers every angle. */
const ANGLES = Object.freeze([0, 1, 2, 3, 4].map((k) => (k * Math.PI) / 16));
/** Frequencies per error evaluation, evenly from 0 to the largest shown. */
const FREQUENCY_STEPS = 48;
/** Distances from a 45° step edge the step error is taken at, square-root spaced to 4 σ of the widest Gaussian. */
const STEP_POINTS = 96;
/** The boundary search's steps, in Gaussians (a boundary at 2.3 gives 30 % of Gaussian 2 to the group below). */
const BOUNDARY_STEPS = Object.freeze([0.5, 0.2, 0.1, 0.05]);

const TWO_PI_SQUARED = 2 * Math.PI ** 2;

/** Σ_i m_i w_i(c) exp(−2π² v_i f²): a group's marginal's Fourier transform (its energy W at f = 0). */
function groupTransfer(gaussians, member, c, f) {
  let sum = 0;
  for (let i = 0; i < gaussians.length; i++) if (member[i] > 0) sum += member[i] * gaussians[i].weights[c] * Math.exp(-TWO_PI_SQUARED * gaussians[i].varianceMm2 * f * f);
  return sum;
}

/**
 * The grouped separable blur's transfer T(f, θ) in channel c (see the header).
 * @param {ReadonlyArray<{ varianceMm2: number, weights: number[] }>} gaussians
 * @param {number[][]} members per group, the fraction of each Gaussian in it (the fractions of a
 *   Gaussian sum to 1 over the groups)
 * @param {number} c channel @param {number} f cycles/mm @param {number} angle radians
 */
export function groupedTransfer(gaussians, members, c, f, angle) {
  const fx = f * Math.cos(angle);
  const fy = f * Math.sin(angle);
  let sum = 0;
  for (const member of members) {
    const W = groupTransfer(gaussians, member, c, 0);
    if (W > 0) sum += (groupTransfer(gaussians, member, c, fx) * groupTransfer(gaussians, member, c, fy)) / W;
  }
  return sum;
}

/**
 * exp(−2π² v_i f²) of every Gaussian at the frequencies separableError takes, up to maxFrequency:
 * along the grating (radial[i][k]) and its two axis components at each angle (x[i][k·A + a], y[…]).
 * Computed once per scale.
 */
function transferTable(gaussians, maxFrequency) {
  const at = (v, f) => Math.exp(-TWO_PI_SQUARED * v * f * f);
  const frequency = (k) => ((k + 1) / FREQUENCY_STEPS) * maxFrequency;
  const table = { radial: [], x: [], y: [] };
  for (const { varianceMm2: v } of gaussians) {
    table.radial.push(Float64Array.from({ length: FREQUENCY_STEPS }, (_, k) => at(v, frequency(k))));
    table.x.push(Float64Array.from({ length: FREQUENCY_STEPS * ANGLES.length }, (_, j) => at(v, frequency(Math.floor(j / ANGLES.length)) * Math.cos(ANGLES[j % ANGLES.length]))));
    table.y.push(Float64Array.from({ length: FREQUENCY_STEPS * ANGLES.length }, (_, j) => at(v, frequency(Math.floor(j / ANGLES.length)) * Math.sin(ANGLES[j % ANGLES.length]))));
  }
  return table;
}

/**
 * The worst |T − M| of channel c's groups over ANGLES and f in (0, maxFrequency].
 * @param {ReturnType<typeof transferTable>} table transferTable of the gaussians at maxFrequency
 */
export function separableError(gaussians, members, c, table) {
  const n = gaussians.length;
  const points = FREQUENCY_STEPS * ANGLES.length;
  const grouped = new Float64Array(points);
  for (const member of members) {
    const weights = member.map((m, i) => m * gaussians[i].weights[c]);
    const W = weights.reduce((s, w) => s + w, 0);
    if (!(W > 0)) continue;
    for (let j = 0; j < points; j++) {
      let ax = 0;
      let ay = 0;
      for (let i = 0; i < n; i++) {
        if (weights[i] > 0) {
          ax += weights[i] * table.x[i][j];
          ay += weights[i] * table.y[i][j];
        }
      }
      grouped[j] += (ax * ay) / W;
    }
  }
  let worst = 0;
  for (let j = 0; j < points; j++) {
    let radial = 0;
    for (let i = 0; i < n; i++) radial += gaussians[i].weights[c] * table.radial[i][Math.floor(j / ANGLES.length)];
    worst = Math.max(worst, Math.abs(grouped[j] - radial));
  }
  return worst;
}

/** The normal distribution's upper tail, Q(x) = erfc(x / √2) / 2. */
const upperTail = (x) => 0.5 * erfc(x / Math.SQRT2);

/**
 * The tails a 45° step edge's response is made of, at STEP_POINTS distances u from the edge: the
 * product of two Gaussians N(v_i)·N(v_j) projects onto the diagonal as N((v_i + v_j) / 2), so the
 * pair's response is Q(u / √((v_i + v_j)/2 + p)) (p the pixel's variance, 1/12 px², in mm²), and
 * the radial profile's Gaussian i answers with the pair (i, i). Computed once per scale.
 * @returns {Float64Array[][]} tails[i][j][k]
 */
function diagonalTails(gaussians, pixelVarianceMm2) {
  const n = gaussians.length;
  const reach = 4 * Math.sqrt(gaussians[n - 1].varianceMm2 + pixelVarianceMm2);
  const tails = Array.from({ length: n }, () => new Array(n));
  for (let i = 0; i < n; i++) {
    for (let j = i; j < n; j++) {
      const sigma = Math.sqrt((gaussians[i].varianceMm2 + gaussians[j].varianceMm2) / 2 + pixelVarianceMm2);
      tails[i][j] = tails[j][i] = Float64Array.from({ length: STEP_POINTS }, (_, k) => upperTail(((k + 1) / STEP_POINTS) ** 2 * reach / sigma));
    }
  }
  return tails;
}

/**
 * The worst difference between channel c's response to a step edge at 45° and the radial
 * profile's, as seen through pixels: the groups answer Σ_g Σ_{i,j} m_i m_j w_i w_j / W_g · tail(i, j),
 * the profile Σ_i w_i tail(i, i) (see diagonalTails).
 * @param {Float64Array[][]} tails diagonalTails of the gaussians at the scale
 */
export function diagonalStepError(gaussians, members, c, tails) {
  const n = gaussians.length;
  const difference = new Float64Array(STEP_POINTS);
  const add = (coefficient, tail) => {
    for (let k = 0; k < STEP_POINTS; k++) difference[k] += coefficient * tail[k];
  };
  for (let i = 0; i < n; i++) add(-gaussians[i].weights[c], tails[i][i]);
  for (const member of members) {
    const W = groupTransfer(gaussians, member, c, 0);
    if (!(W > 0)) continue;
    for (let i = 0; i < n; i++) {
      const wi = member[i] * gaussians[i].weights[c];
      if (!(wi > 0)) continue;
      for (let j = 0; j < n; j++) {
        const wj = member[j] * gaussians[j].weights[c];
        if (wj > 0) add((wi * wj) / W, tails[i][j]);
      }
    }
  }
  return difference.reduce((worst, d) => Math.max(worst, Math.abs(d)), 0);
}

/** Fractions of Gaussians 0..n−1 in each group from the boundaries 0 < b_1 < … < n (in Gaussians). */
function membersOf(n, boundaries) {
  const edges = [0, ...boundaries, n];
  return edges.slice(1).map((top, g) => Array.from({ length: n }, (_, i) => Math.max(0, Math.min(i + 1, top) - Math.max(i, edges[g]))));
}

/** Every set of whole-Gaussian boundaries splitting 0..n−1 into `count` non-empty runs. */
function wholeBoundaries(n, count) {
  const out = [];
  const extend = (start, left, chosen) => {
    if (left === 1) {
      out.push(chosen);
      return;
    }
    for (let end = start + 1; end <= n - left + 1; end++) extend(end, left - 1, [...chosen, end]);
  };
  extend(0, count, []);
  return out;
}

/**
 * Channel c's best boundaries for `count` groups: the best whole-Gaussian split, then each boundary
 * moved by BOUNDARY_STEPS while the score (the larger of the two errors over their budgets) falls.
 */
function bestBoundaries(gaussians, count, c, { transfers, tails }) {
  const n = gaussians.length;
  const errorsOf = (boundaries) => {
    const members = membersOf(n, boundaries);
    const transfer = separableError(gaussians, members, c, transfers);
    const step = diagonalStepError(gaussians, members, c, tails);
    return { boundaries, transfer, step, score: Math.max(transfer / ISOTROPY_ERROR, step / ISOTROPY_STEP_ERROR) };
  };
  let best = null;
  for (const boundaries of wholeBoundaries(n, count)) {
    const e = errorsOf(boundaries);
    if (!best || e.score < best.score) best = e;
  }
  for (const step of BOUNDARY_STEPS) {
    for (let improved = true; improved;) {
      improved = false;
      for (let b = 0; b < count - 1; b++) {
        for (const move of [-step, step]) {
          const next = [...best.boundaries];
          next[b] += move;
          const low = b === 0 ? 0 : next[b - 1];
          const high = b === count - 2 ? n : next[b + 1];
          if (next[b] - low < 0.25 || high - next[b] < 0.25) continue; // no group thinner than a quarter Gaussian
          const e = errorsOf(next);
          if (e.score < best.score - 1e-12) {
            best = e;
            improved = true;
          }
        }
      }
    }
  }
  return best;
}

/**
 * The grouping of a profile into `count` groups with the least error at a scale.
 * @param {object} profile
 * @param {number} count 1..MAX_KERNEL_GROUPS (fewer when the profile has fewer Gaussians)
 * @param {number} pxPerMm the on-screen scale: the transfer is taken up to pxPerMm / 4 cycles/mm,
 *   the step edge through pixels of that size
 * @returns {Readonly<{ count: number, gaussians: ReadonlyArray<object>, members: number[][][], error: number[], stepError: number[], fitStepError: number[] }>}
 *   members[c][g][i]: the fraction of Gaussian i in group g, channel c; error per channel (|T − M|
 *   up to pxPerMm / 4, closed form of the Gaussian sum) and stepError (at 45°); fitStepError: the
 *   Gaussian sum's own (gaussianFit.js, 0 for Gaussian profiles)
 */
export function kernelGroups(profile, count, pxPerMm) {
  checkInteger('kernelGroups', count, 1, MAX_KERNEL_GROUPS, 'groups');
  const { gaussians, stepError: fitStepError } = gaussianSumOf(profile);
  const k = Math.min(count, gaussians.length);
  const scale = { transfers: transferTable(gaussians, pxPerMm / 4), tails: diagonalTails(gaussians, 1 / (12 * pxPerMm * pxPerMm)) };
  const best = [0, 1, 2].map((c) => bestBoundaries(gaussians, k, c, scale));
  return Object.freeze({
    count: k,
    gaussians,
    members: best.map((b) => membersOf(gaussians.length, b.boundaries)),
    error: best.map((b) => b.transfer),
    stepError: best.map((b) => b.step),
    fitStepError,
  });
}

/** Whether a grouping is within both budgets in every channel. */
const withinBudget = (grouping) => grouping.error.every((e) => e <= ISOTROPY_ERROR) && grouping.stepError.every((e) => e <= ISOTROPY_STEP_ERROR);

/**
 * Checks the `kernelGroups` option: 'auto' or a count.
 * @param {*} value @param {string} [name] @returns {'auto'|number}
 */
export function checkKernelGroups(value, name = 'kernelGroups') {
  if (value === 'auto') return value;
  if (typeof value !== 'number') throw new TypeError(`${name} must be 'auto' or an integer in 1..${MAX_KERNEL_GROUPS}, got ${typeof value === 'string' ? `'${value}'` : String(value)}`);
  return checkInteger(name, value, 1, MAX_KERNEL_GROUPS, "groups (or 'auto')");
}

/** Footprint table rows per cached scale step (8 rows an octave). */
const ROWS_PER_STEP = 4;

/** The footprint row that names `pxPerMm`'s cached step (its upper end, rounded up). */
const stepRowOf = (pxPerMm) => Math.ceil(footprintRowOf(Math.max(pxPerMm, Number.MIN_VALUE)) / ROWS_PER_STEP) * ROWS_PER_STEP;

/**
 * The scale where the cached step holding `pxPerMm` ends: kernelGroupsAt gives one grouping below
 * it (down to the step's start) and the next step's from it on.
 * @param {number} pxPerMm @returns {number}
 */
export function groupingStepEnd(pxPerMm) {
  const row = stepRowOf(pxPerMm);
  return row >= FOOTPRINT_ROWS - 1 ? Infinity : footprintRowScale(row + 0.5); // footprintRowOf rounds at half rows
}

/** profile → `${footprint row}/${setting}` → the grouping there. */
const groupingsAt = new WeakMap();

/**
 * The grouping for a frame whose largest on-screen scale is `pxPerMm`: for 'auto' the fewest groups
 * within ISOTROPY_ERROR (per channel, f ≤ pxPerMm / 4, the gratings shown with at least 4 pixels
 * per cycle) and ISOTROPY_STEP_ERROR, at most MAX_KERNEL_GROUPS; for a count, that many, chosen
 * for the same scale.
 * Cached per half octave of scale (the error taken at the step's upper end; choosing takes up to a
 * few hundred ms for a fitted profile of 10 Gaussians, so a zoom recomputes rarely).
 * @param {object} profile @param {number} pxPerMm @param {'auto'|number} [setting='auto']
 */
export function kernelGroupsAt(profile, pxPerMm, setting = 'auto') {
  checkKernelGroups(setting);
  // Half-octave steps of the footprint table's rows, rounded up: a zoom recomputes rarely.
  const row = stepRowOf(pxPerMm);
  let byRow = groupingsAt.get(profile);
  if (!byRow) groupingsAt.set(profile, (byRow = new Map()));
  const key = `${row}/${setting}`;
  if (!byRow.has(key)) {
    const scale = footprintRowScale(row);
    let grouping;
    for (let count = setting === 'auto' ? 1 : setting; count <= (setting === 'auto' ? MAX_KERNEL_GROUPS : setting); count++) {
      grouping = kernelGroups(profile, count, scale);
      if (withinBudget(grouping) || grouping.count < count) break;
    }
    byRow.set(key, grouping);
  }
  return byRow.get(key);
}

/**
 * The counts of groups a frame may take with `setting` over `profiles` (the frame takes the most
 * of its profiles'; no profile more than its Gaussians): the programs a warm-up compiles.
 * @param {readonly object[]} profiles @param {'auto'|number} setting
 * @returns {number[]}
 */
export function possibleGroupCounts(profiles, setting) {
  checkKernelGroups(setting);
  const most = Math.max(1, ...profiles.map((profile) => gaussianSumOf(profile).gaussians.length));
  const top = Math.min(setting === 'auto' ? MAX_KERNEL_GROUPS : setting, most);
  return setting === 'auto' ? Array.from({ length: top }, (_, i) => i + 1) : [top];
}

/** 'auto' groups at `pxPerMm` (kernelGroupsAt with 'auto'). @param {object} profile @param {number} pxPerMm */
export const autoKernelGroups = (profile, pxPerMm) => kernelGroupsAt(profile, pxPerMm, 'auto');

/** Each group's share of the profile's energy per channel (summing to 1): [g][c]. @param {ReturnType<typeof kernelGroups>} grouping */
export function groupEnergies({ gaussians, members }) {
  const energies = members[0].map(() => [0, 0, 0]);
  for (let c = 0; c < 3; c++) {
    members[c].forEach((member, g) => member.forEach((fraction, i) => { energies[g][c] += fraction * gaussians[i].weights[c]; }));
    const total = energies.reduce((sum, e) => sum + e[c], 0);
    for (const e of energies) e[c] = total > 0 ? e[c] / total : 1 / energies.length;
  }
  return energies;
}

/**
 * The share of each group in the marginal energy of every footprint of a footprint table, as the
 * blur splits it (shaders/3-blur/kernelGroups.glsl): at each row's scale s, the footprints snapped
 * to whole pixels as the shader snaps them (footprint k covers pixels e_{k−1} + 1 .. e_k, so
 * [(e_{k−1} + ½) / s, (e_k + ½) / s] mm; the centre |x| < ½ / s; the last to infinity), and group g's
 * energy there Σ_i m_gi w_i (erfc(a / √(2 v_i)) − erfc(b / √(2 v_i))) / 2 from its Gaussians (a fitted
 * profile's fit: the total stays the exact marginal's, only its split comes from the fit).
 * @param {ReturnType<typeof kernelGroups>} grouping
 * @param {{ data: Float32Array, columns: number }} table footprintTable's numbers
 * @returns {Float32Array} per row r and column k (0: the centre, j + 1: footprint j), MAX_KERNEL_GROUPS
 *   RGB fractions at ((r · (columns + 1) + k) · MAX_KERNEL_GROUPS + g) · 3 + c; groups past the
 *   grouping's count hold 0. Where no group has energy (past float range) the widest takes it all.
 */
export function footprintGroupFractions(grouping, table) {
  const { share = 1, unfaded = grouping } = grouping;
  let byTable = ownFractions.get(unfaded);
  if (!byTable) ownFractions.set(unfaded, (byTable = new WeakMap()));
  if (!byTable.has(table)) byTable.set(table, ownGroupFractions(unfaded, table));
  const own = byTable.get(table);
  if (share >= 1) return own;
  // A faded grouping (fadedGrouping): each footprint's split leans to the groups' energy shares.
  const shares = groupEnergies(unfaded);
  const out = new Float32Array(own.length);
  for (let texel = 0; texel < own.length; texel += MAX_KERNEL_GROUPS * 3) {
    if (own[texel] + own[texel + 3] + own[texel + 6] + own[texel + 9] === 0) continue; // past a row's last footprint
    shares.forEach((rgb, g) => rgb.forEach((e, c) => { out[texel + g * 3 + c] = share * own[texel + g * 3 + c] + (1 - share) * e; }));
  }
  return out;
}

/** grouping → footprint table → its own fractions (a faded grouping's share only mixes them). */
const ownFractions = new WeakMap();

/** footprintGroupFractions of an unfaded grouping, computed. */
function ownGroupFractions(grouping, { data, columns }) {
  const { gaussians, members } = grouping;
  const count = members[0].length;
  const scales = gaussians.map((g) => 1 / Math.sqrt(2 * g.varianceMm2));
  const out = new Float32Array(FOOTPRINT_ROWS * (columns + 1) * MAX_KERNEL_GROUPS * 3);
  const energies = new Float64Array(count);
  const write = (row, column, lowMm, highMm) => {
    const tails = scales.map((k) => [erfc(lowMm * k), highMm === Infinity ? 0 : erfc(highMm * k)]);
    for (let c = 0; c < 3; c++) {
      let total = 0;
      for (let g = 0; g < count; g++) {
        let e = 0;
        members[c][g].forEach((fraction, i) => { if (fraction > 0) e += fraction * gaussians[i].weights[c] * (tails[i][0] - tails[i][1]); });
        energies[g] = Math.max(e, 0);
        total += energies[g];
      }
      const base = (row * (columns + 1) + column) * MAX_KERNEL_GROUPS;
      for (let g = 0; g < count; g++) out[(base + g) * 3 + c] = total > 0 ? energies[g] / total : (g === count - 1 ? 1 : 0);
    }
  };
  for (let row = 0; row < FOOTPRINT_ROWS; row++) {
    const s = footprintRowScale(row);
    write(row, 0, 0, 0.5 / s);
    let lastEdge = 0;
    for (let k = 0; k < columns; k++) {
      const edgeMm = data[2 * (row * columns + k)];
      const last = k === columns - 1 || edgeMm === Infinity;
      const edge = last ? Infinity : Math.max(Math.floor(edgeMm * s + 0.5), lastEdge + 1);
      write(row, k + 1, (lastEdge + 0.5) / s, last ? Infinity : (edge + 0.5) / s);
      if (last) break;
      lastEdge = edge;
    }
  }
  return out;
}

/** grouping → share → its fadedGrouping. */
const fadedGroupings = new WeakMap();

/**
 * `grouping` faded towards one kernel: each footprint's split between the groups is `share` of
 * its own and 1 − share of the groups' energy shares (groupEnergies). At share 0 every footprint
 * splits alike, so each group's blur is that share of the one-kernel blur and the groups sum to it
 * exactly: a plan changing between one kernel and groups (kernelGroups 'auto') ramps the share
 * instead of switching (src/3-blur/blurPlan.js). Cached per share (the plan steps it).
 * @param {ReturnType<typeof kernelGroups>} grouping @param {number} share in [0, 1]
 */
export function fadedGrouping(grouping, share) {
  if (share >= 1) return grouping;
  let byShare = fadedGroupings.get(grouping);
  if (!byShare) fadedGroupings.set(grouping, (byShare = new Map()));
  if (!byShare.has(share)) byShare.set(share, Object.freeze({ ...grouping, share, unfaded: grouping }));
  return byShare.get(share);
}
