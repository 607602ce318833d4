// Christensen & Burley 2015's normalised diffusion: exponentials with closed-form radii; the
// marginal through K0 (what Unity HDRP, Unreal and Babylon.js sample).
import { checkRgb, checkOneOf } from '../support/parameterChecks.js';
import { besselK } from '../math/specialFunctions.js';
import { radialProfile, checkFraction } from './radialProfile.js';

const rgbOf = (value) => (typeof value === 'number' ? [value, value, value] : value);

/**
 * The radius holding `fraction` of the energy, in scatter distances (16.56 at 99.7 %, REFERENCE §2):
 * Christensen & Burley 2015's closed-form inverse, u = 1 − CDF.
 */
function burleyScaledRadius(fraction) {
  const u = 1 - fraction;
  const G = 1 + 4 * u * (2 * u + Math.sqrt(1 + 4 * u * u));
  const g3 = Math.cbrt(G);
  return 3 * Math.log((1 + 1 / g3 + g3) / (4 * u));
}

/**
 * Burley normalised diffusion (Christensen & Burley 2015), per channel with scatter distance l = 1/s:
 *   R(r) = (e^{−r/l} + e^{−r/3l}) / (8π l r)             (the albedo factor A is dropped: unit energy)
 *   a(x) = (K0(|x|/l) + K0(|x|/3l)) / (4π l)             since ∫ e^{−s√(x²+y²)}/√(x²+y²) dy = 2 K0(s|x|)
 *   T(d) = (e^{−d/l} + 3 e^{−d/3l}) / 4,  CDF = 1 − T,  radius from the closed-form inverse.
 * The marginal is infinite at x = 0 (logarithmic singularity, integrable).
 *
 * Give either the scatter distances directly, or an albedo and a mean free path with one of the fits
 * s = 1.85 − A + 7|A − 0.8|³ ('searchlight', light entering perpendicular) or
 * s = 1.9 − A + 3.5 (A − 0.8)² ('diffuse'), and l = meanFreePath / s.
 * @param {{scatterDistanceMm?: number[], albedo?: number[], meanFreePathMm?: number|number[],
 *   fit?: 'searchlight'|'diffuse', name?: string}} options
 * @returns {Readonly<object>} the profile
 */
export function burleyProfile(options = {}) {
  let l;
  if (options.scatterDistanceMm !== undefined) {
    l = checkRgb('scatterDistanceMm', options.scatterDistanceMm, { min: 0, minExclusive: true, unit: 'mm' });
  } else {
    const albedo = checkRgb('albedo', options.albedo, { min: 0, max: 1 });
    const mfp = checkRgb('meanFreePathMm', rgbOf(options.meanFreePathMm), { min: 0, minExclusive: true, unit: 'mm' });
    const fit = checkOneOf('fit', options.fit ?? 'searchlight', ['searchlight', 'diffuse']);
    const scale = albedo.map((A) =>
      fit === 'searchlight' ? 1.85 - A + 7 * Math.abs(A - 0.8) ** 3 : 1.9 - A + 3.5 * (A - 0.8) ** 2,
    );
    l = mfp.map((d, c) => d / scale[c]);
  }
  const perChannel = (fn) => [fn(l[0]), fn(l[1]), fn(l[2])];
  const transmittance = (dMm) => {
    const d = Math.abs(dMm);
    return perChannel((lc) => 0.25 * (Math.exp(-d / lc) + 3 * Math.exp(-d / (3 * lc))));
  };
  const cdf = (rMm) => perChannel((lc) => -0.25 * (Math.expm1(-rMm / lc) + 3 * Math.expm1(-rMm / (3 * lc))));
  const radiusMm = (fraction = 0.997) => {
    checkFraction(fraction);
    const k = burleyScaledRadius(fraction);
    return perChannel((lc) => k * lc);
  };
  return radialProfile({
    name: options.name ?? 'burley',
    scatterDistanceMm: l,
    lengthScaleMm: Math.max(...l) * burleyScaledRadius(0.5),
    R: (rMm) => perChannel((lc) => (Math.exp(-rMm / lc) + Math.exp(-rMm / (3 * lc))) / (8 * Math.PI * lc * rMm)),
    marginal: (xMm) => {
      const ax = Math.abs(xMm);
      if (ax === 0) return [Infinity, Infinity, Infinity];
      return perChannel((lc) => (besselK(0, ax / lc) + besselK(0, ax / (3 * lc))) / (4 * Math.PI * lc));
    },
    transmittance,
    cdf,
    radiusMm,
  });
}
