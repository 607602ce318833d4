// The built-in profiles and the measured data they come from, each with its source; `getProfile`
// resolves a name or checks a custom profile object. Built on import: pure computation.
import { checkNumber, describeValue } from '../support/parameterChecks.js';
import { gaussianSumProfile } from './gaussianSum.js';
import { burleyProfile } from './burley.js';
import { dipoleProfile } from './dipole.js';

/**
 * d'Eon & Luebke 2007 (GPU Gems 3, ch. 14) six-Gaussian skin fit: variances in mm², RGB weights.
 * Each channel already sums to 1.
 * @type {ReadonlyArray<Readonly<{varianceMm2: number, weights: ReadonlyArray<number>}>>}
 */
export const DEON_SKIN_GAUSSIANS = Object.freeze(
  [
    { varianceMm2: 0.0064, weights: [0.233, 0.455, 0.649] },
    { varianceMm2: 0.0484, weights: [0.1, 0.336, 0.344] },
    { varianceMm2: 0.187, weights: [0.118, 0.198, 0.0] },
    { varianceMm2: 0.567, weights: [0.113, 0.007, 0.007] },
    { varianceMm2: 1.99, weights: [0.358, 0.004, 0.0] },
    { varianceMm2: 7.41, weights: [0.078, 0.0, 0.0] },
  ].map((g) => Object.freeze({ varianceMm2: g.varianceMm2, weights: Object.freeze(g.weights) })),
);

/**
 * Jimenez 2009 four-Gaussian fit of marble (REFERENCE §2). The published table has a leading (0, 0, 0)
 * weight row that belongs to a zero-variance (delta) term with no energy: it is dropped, and the four
 * variances pair with the four remaining rows. The published green and blue weights sum to 0.9999, so
 * gaussianSumProfile renormalises each channel to sum exactly 1.
 * @type {ReadonlyArray<Readonly<{varianceMm2: number, weights: ReadonlyArray<number>}>>}
 */
export const MARBLE_GAUSSIANS = Object.freeze(
  [
    { varianceMm2: 0.0362, weights: [0.0545, 0.1245, 0.2177] },
    { varianceMm2: 0.1145, weights: [0.2437, 0.2435, 0.189] },
    { varianceMm2: 0.4556, weights: [0.3105, 0.3158, 0.3742] },
    { varianceMm2: 3.4833, weights: [0.3913, 0.3161, 0.219] },
  ].map((g) => Object.freeze({ varianceMm2: g.varianceMm2, weights: Object.freeze(g.weights) })),
);

/**
 * Scatter distances of the `skinBurley` preset, chosen so that each channel's 99.7 % radius equals the
 * d'Eon skin profile's: l_c = skin.radiusMm(0.997)_c / 16.5644 (Burley's 99.7 % radius is 16.5644 l).
 * Computed with this module (skin 99.7 % radii 6.9494, 1.6083, 0.98327 mm), rounded to 5 digits; the
 * unit tests recompute them. Matching only this radius leaves the shapes different: Burley's sharp
 * centre and exponential tail versus the Gaussians' rounded ones.
 */
export const SKIN_BURLEY_SCATTER_DISTANCE_MM = Object.freeze([0.41954, 0.097094, 0.059361]);

/**
 * Whole milk, from the table of measured scattering coefficients in Jensen et al. 2001 ("A practical
 * model for subsurface light transport", SIGGRAPH; σs', σa per RGB for marble, skin, milk, ketchup, ...):
 * σs' = (2.55, 3.21, 3.77)/mm, σa = (0.0011, 0.0024, 0.014)/mm, η = 1.3.
 * Caveat: recalled, not re-read from the paper here (REFERENCE.md names the table, not its numbers);
 * check them against the paper before relying on milk quantitatively.
 */
export const WHOLE_MILK_COEFFICIENTS = Object.freeze({
  sigmaSPrimeMm: Object.freeze([2.55, 3.21, 3.77]),
  sigmaAMm: Object.freeze([0.0011, 0.0024, 0.014]),
  eta: 1.3,
});

/**
 * The built-in profiles (built on import: pure computation, no side effects):
 * - skin: d'Eon & Luebke six Gaussians
 * - skinBurley: Burley with SKIN_BURLEY_SCATTER_DISTANCE_MM (same 99.7 % radii as skin)
 * - marble: Jimenez 2009 four-Gaussian marble fit
 * - milk: Jensen 2001 dipole of whole milk
 */
export const profiles = Object.freeze({
  skin: gaussianSumProfile('skin', DEON_SKIN_GAUSSIANS),
  skinBurley: burleyProfile({ name: 'skinBurley', scatterDistanceMm: [...SKIN_BURLEY_SCATTER_DISTANCE_MM] }),
  marble: gaussianSumProfile('marble', MARBLE_GAUSSIANS),
  milk: dipoleProfile({ name: 'milk', ...WHOLE_MILK_COEFFICIENTS }),
});

/**
 * The reference transmittance of Jimenez et al. 2010 (REFERENCE §5) for skin:
 *   T(s) = Σ_i w_i exp(−s²/v_i) over the six d'Eon Gaussians.
 * This is NOT the exact integral of the profile (that is profiles.skin.transmittance, with exp(−s²/2v));
 * the two agree at s_exact = √2 · s. Kept because the reference's artist-tuned scale assumes it.
 * @param {number} sMm scaled thickness in mm
 * @returns {number[]} [r, g, b]
 */
export function transmittance(sMm) {
  checkNumber('sMm', sMm, { min: 0, unit: 'mm' });
  const out = [0, 0, 0];
  for (const { varianceMm2, weights } of DEON_SKIN_GAUSSIANS) {
    const k = Math.exp((-sMm * sMm) / varianceMm2);
    for (let c = 0; c < 3; c++) out[c] += weights[c] * k;
  }
  return out;
}

const PROFILE_NAMES = Object.freeze(['skin', 'skinBurley', 'marble', 'milk']);
const PROFILE_METHODS = ['R', 'marginal', 'marginalIntegral', 'transmittance', 'radiusMm'];

/**
 * Resolves a profile name or checks a profile object.
 * @param {'skin'|'skinBurley'|'marble'|'milk'|object} nameOrProfile
 * @returns {Readonly<object>} the profile
 * @throws {TypeError} for anything else, naming the accepted names
 */
export function getProfile(nameOrProfile) {
  if (typeof nameOrProfile === 'string' && PROFILE_NAMES.includes(nameOrProfile)) return profiles[nameOrProfile];
  if (
    nameOrProfile !== null &&
    typeof nameOrProfile === 'object' &&
    PROFILE_METHODS.every((m) => typeof nameOrProfile[m] === 'function')
  ) {
    return nameOrProfile;
  }
  throw new TypeError(
    `profile must be one of ${PROFILE_NAMES.map((n) => `'${n}'`).join(', ')} or a profile object ` +
      `(with ${PROFILE_METHODS.join(', ')}), got ${describeValue(nameOrProfile)}`,
  );
}
