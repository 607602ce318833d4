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
 * Jimenez 2009 four-Gaussian fit of marble (REFERENCE §2). The table's leading (0, 0, 0) weight row,
 * a zero-variance term with no energy, is dropped; green and blue sum to 0.9999 and are renormalised.
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
 * `skinBurley`'s scatter distances: each channel's 99.7 % radius equals d'Eon skin's,
 * l_c = skin.radiusMm(0.997)_c / 16.5644 (Burley's 99.7 % radius is 16.5644 l), to 5 digits (the
 * unit tests recompute them). The shapes still differ: Burley's sharp centre and exponential tail.
 */
export const SKIN_BURLEY_SCATTER_DISTANCE_MM = Object.freeze([0.41954, 0.097094, 0.059361]);

/**
 * Whole milk, from the measured coefficients of Jensen et al. 2001 ("A practical model for subsurface
 * light transport"), per mm. Recalled, not re-read (REFERENCE.md names the table, not its numbers):
 * check them against the paper before relying on milk quantitatively.
 */
export const WHOLE_MILK_COEFFICIENTS = Object.freeze({
  sigmaSPrimeMm: Object.freeze([2.55, 3.21, 3.77]),
  sigmaAMm: Object.freeze([0.0011, 0.0024, 0.014]),
  eta: 1.3,
});

/** The built-in profiles, from the data above. */
export const profiles = Object.freeze({
  skin: gaussianSumProfile('skin', DEON_SKIN_GAUSSIANS),
  skinBurley: burleyProfile({ name: 'skinBurley', scatterDistanceMm: [...SKIN_BURLEY_SCATTER_DISTANCE_MM] }),
  marble: gaussianSumProfile('marble', MARBLE_GAUSSIANS),
  milk: dipoleProfile({ name: 'milk', ...WHOLE_MILK_COEFFICIENTS }),
});

/**
 * Jimenez et al. 2010's skin transmittance (REFERENCE §5), T(s) = Σ w_i exp(−s²/v_i): not the exact
 * integral (profiles.skin.transmittance, exp(−s²/2v), equal at √2·s); the reference's scale assumes it.
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

/** How far a custom profile's energy may be from 1 per channel (marginalIntegral(-∞, ∞), transmittance(0)). */
export const PROFILE_ENERGY_TOLERANCE = 1e-3;
const CHANNELS = Object.freeze(['red', 'green', 'blue']);
/** Where a custom profile is sampled, in multiples of its length scale (r > 0: Burley's R and marginal are infinite at 0). */
const SAMPLE_SCALES = Object.freeze([0.1, 0.5, 1, 2, 5]);
/** Profiles already checked: the built-ins (known good) and each custom object once. */
const checkedProfiles = new WeakSet(Object.values(profiles));

/** Checks one call's [r, g, b]: 3 finite numbers ≥ 0. */
function checkChannels(who, call, values) {
  if (!values || typeof values !== 'object' || !(values.length >= 3)) {
    throw new TypeError(`${who}: ${call} must return [r, g, b], got ${describeValue(values)}`);
  }
  for (let c = 0; c < 3; c++) {
    const v = values[c];
    if (typeof v !== 'number' || !Number.isFinite(v)) {
      throw new TypeError(`${who}: ${call} must be a finite number in every channel, got ${describeValue(v)} in the ${CHANNELS[c]} channel`);
    }
    if (v < 0) throw new RangeError(`${who}: ${call} must be non-negative in every channel, got ${v} in the ${CHANNELS[c]} channel`);
  }
  return values;
}

/** Checks that a call gives 1 per channel within PROFILE_ENERGY_TOLERANCE. */
function checkUnitEnergy(who, call, values) {
  checkChannels(who, call, values);
  for (let c = 0; c < 3; c++) {
    if (Math.abs(values[c] - 1) > PROFILE_ENERGY_TOLERANCE) {
      throw new RangeError(`${who}: ${call} must be 1 in every channel (unit energy, within ${PROFILE_ENERGY_TOLERANCE}), ` +
        `got ${values[c]} in the ${CHANNELS[c]} channel`);
    }
  }
}

/**
 * Checks a custom profile once: finite, non-negative values at a few radii, unit energy per channel.
 * @param {object} profile
 * @returns {object} the profile
 */
function checkCustomProfile(profile) {
  if (checkedProfiles.has(profile)) return profile;
  const who = `profile ${JSON.stringify(String(profile.name ?? 'unnamed'))}`;
  const scale = Number.isFinite(profile.lengthScaleMm) && profile.lengthScaleMm > 0 ? profile.lengthScaleMm : 1;
  const mm = (x) => `${Number(x.toPrecision(4))} mm`;
  for (const k of SAMPLE_SCALES) {
    const x = k * scale;
    checkChannels(who, `R(${mm(x)})`, profile.R(x));
    checkChannels(who, `marginal(${mm(x)})`, profile.marginal(x));
    checkChannels(who, `marginalIntegral(0, ${mm(x)})`, profile.marginalIntegral(0, x));
    checkChannels(who, `transmittance(${mm(x)})`, profile.transmittance(x));
  }
  checkUnitEnergy(who, 'marginalIntegral(-∞, ∞)', profile.marginalIntegral(-Infinity, Infinity));
  checkUnitEnergy(who, 'transmittance(0)', profile.transmittance(0));
  const radii = checkChannels(who, 'radiusMm(0.997)', profile.radiusMm(0.997));
  radii.forEach((r, c) => {
    if (!(r > 0)) throw new RangeError(`${who}: radiusMm(0.997) must be positive in every channel, got ${r} in the ${CHANNELS[c]} channel`);
  });
  checkedProfiles.add(profile);
  return profile;
}

/**
 * Resolves a profile name or checks a profile object.
 * @param {'skin'|'skinBurley'|'marble'|'milk'|object} nameOrProfile
 * @returns {Readonly<object>} the profile
 * @throws {TypeError} for anything else, naming the accepted names; for a profile whose functions
 *   return NaN, Infinity or no [r, g, b], naming the function and the channel
 * @throws {RangeError} for a profile with negative values or without unit energy per channel
 */
export function getProfile(nameOrProfile) {
  if (typeof nameOrProfile === 'string' && PROFILE_NAMES.includes(nameOrProfile)) return profiles[nameOrProfile];
  if (
    nameOrProfile !== null &&
    typeof nameOrProfile === 'object' &&
    PROFILE_METHODS.every((m) => typeof nameOrProfile[m] === 'function')
  ) {
    return checkCustomProfile(nameOrProfile);
  }
  throw new TypeError(
    `profile must be one of ${PROFILE_NAMES.map((n) => `'${n}'`).join(', ')} or a profile object ` +
      `(with ${PROFILE_METHODS.join(', ')}), got ${describeValue(nameOrProfile)}`,
  );
}
