// Jensen et al. 2001's classical dipole from measured scattering coefficients (milk, marble, ...).
import { checkNumber, checkRgb } from '../support/parameterChecks.js';
import { besselK } from '../math/specialFunctions.js';
import { solveDecreasing } from '../math/roots.js';
import { radialProfile, checkFraction } from './radialProfile.js';

/**
 * Classical dipole diffuse reflectance of Jensen, Marschner, Levoy & Hanrahan 2001 ("A practical model
 * for subsurface light transport", eq. 4-5), per channel, normalised to unit energy:
 *   σt' = σa + σs', α' = σs'/σt', σtr = √(3 σa σt'), z_r = 1/σt', z_v = z_r (1 + 4A/3),
 *   A = (1 + F_dr)/(1 − F_dr), F_dr = −1.440/η² + 0.710/η + 0.668 + 0.0636 η,
 *   d_r,v = √(r² + z_r,v²),
 *   R_d(r) = α'/(4π) Σ_{z ∈ {z_r, z_v}} z (σtr d + 1) e^{−σtr d} / d³.
 * The integrals are closed form (substituting ρ² = r² + z², ρ dρ = r dr, and (σρ+1)e^{−σρ}/ρ² = −d/dρ(e^{−σρ}/ρ)):
 *   energy outside radius r: (α'/2) Σ z e^{−σtr d(r)} / d(r);  total R_d = (α'/2)(e^{−σtr z_r} + e^{−σtr z_v});
 *   marginal: ∫ (σD+1)e^{−σD}/D³ dy = 2σ K1(σρ)/ρ with ρ = √(x² + z²).
 * The total is used to normalise (exact, no numerical normalisation needed).
 * @param {{sigmaSPrimeMm: number[], sigmaAMm: number[], eta: number, name?: string}} options
 *   reduced scattering and absorption coefficients in 1/mm, relative index of refraction
 * @returns {Readonly<object>} the profile
 */
export function dipoleProfile({ sigmaSPrimeMm, sigmaAMm, eta, name = 'dipole' } = {}) {
  const sigmaS = checkRgb('sigmaSPrimeMm', sigmaSPrimeMm, { min: 0, minExclusive: true, unit: '1/mm' });
  const sigmaA = checkRgb('sigmaAMm', sigmaAMm, { min: 0, minExclusive: true, unit: '1/mm' });
  checkNumber('eta', eta, { min: 1, max: 3 });
  const Fdr = -1.44 / (eta * eta) + 0.71 / eta + 0.668 + 0.0636 * eta;
  const A = (1 + Fdr) / (1 - Fdr);
  const ch = [0, 1, 2].map((c) => {
    const sigmaTPrime = sigmaA[c] + sigmaS[c];
    const alphaPrime = sigmaS[c] / sigmaTPrime;
    const sigmaTr = Math.sqrt(3 * sigmaA[c] * sigmaTPrime);
    const zr = 1 / sigmaTPrime;
    const zv = zr * (1 + (4 * A) / 3);
    const total = 0.5 * alphaPrime * (Math.exp(-sigmaTr * zr) + Math.exp(-sigmaTr * zv));
    return { alphaPrime, sigmaTr, zr, zv, total };
  });
  const R = (rMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(rMm * rMm + z * z);
        return (z * (sigmaTr * d + 1) * Math.exp(-sigmaTr * d)) / (d * d * d);
      };
      return ((alphaPrime / (4 * Math.PI)) * (term(zr) + term(zv))) / total;
    });
  const transmittance = (dMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(dMm * dMm + z * z);
        return (z * Math.exp(-sigmaTr * d)) / d;
      };
      return (0.5 * alphaPrime * (term(zr) + term(zv))) / total;
    });
  // 1 − T without cancellation: e^{−σz} − z e^{−σd}/d = −e^{−σz} expm1(−log1p(Δ/z) − σΔ), Δ = d − z = r²/(d + z)
  const cdf = (rMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const d = Math.sqrt(rMm * rMm + z * z);
        const delta = (rMm * rMm) / (d + z);
        return -Math.exp(-sigmaTr * z) * Math.expm1(-Math.log1p(delta / z) - sigmaTr * delta);
      };
      return rMm === Infinity ? 1 : (0.5 * alphaPrime * (term(zr) + term(zv))) / total;
    });
  const marginal = (xMm) =>
    ch.map(({ alphaPrime, sigmaTr, zr, zv, total }) => {
      const term = (z) => {
        const rho = Math.sqrt(xMm * xMm + z * z);
        return (z * besselK(1, sigmaTr * rho)) / rho;
      };
      return ((alphaPrime * sigmaTr) / (2 * Math.PI)) * (term(zr) + term(zv)) / total;
    });
  const lengthScaleMm = Math.max(...ch.map(({ sigmaTr, zv }) => Math.max(1 / sigmaTr, zv)));
  const radiusMm = (fraction = 0.997) => {
    checkFraction(fraction);
    return [0, 1, 2].map((c) => solveDecreasing((r) => transmittance(r)[c], 1 - fraction, 0, lengthScaleMm));
  };
  return radialProfile({ name, R, marginal, transmittance, cdf, radiusMm, lengthScaleMm });
}
