// The float64 maths under the profiles: special functions against mpmath, quadrature rules.
import { describe, it, expect } from 'vitest';
import { erf, erfc, besselK } from '../../../src/math/specialFunctions.js';
import { gaussLegendre, integrateAdaptive } from '../../../src/math/quadrature.js';

const relErr = (a, b) => Math.abs(a - b) / Math.abs(b);

describe('special functions', () => {
  // reference values from mpmath at 30 digits
  const ERF = [
    [0.1, 0.112462916018284898404712251014, 0.887537083981715101595287748986],
    [0.5, 0.520499877813046537682746653892, 0.479500122186953462317253346108],
    [1, 0.842700792949714869341220635083, 0.157299207050285130658779364917],
    [2, 0.995322265018952734162069256367, 0.00467773498104726583793074363275],
    [3.5, 0.999999256901627658587254476316, 7.43098372341412745523683756096e-7],
    [6, 0.999999999999999978480263287501, 2.15197367124989131165933503992e-17],
  ];
  it('erf and erfc are float64 accurate', () => {
    for (const [x, e, ec] of ERF) {
      expect(Math.abs(erf(x) - e)).toBeLessThan(1e-15);
      expect(Math.abs(erf(-x) + e)).toBeLessThan(1e-15);
      expect(relErr(erfc(x), ec)).toBeLessThan(1e-13);
      expect(Math.abs(erfc(-x) - (2 - ec))).toBeLessThan(1e-15);
    }
    expect(erf(Infinity)).toBe(1);
    expect(erf(-Infinity)).toBe(-1);
    expect(erfc(Infinity)).toBe(0);
  });
  it('besselK0 and K1 are float64 accurate', () => {
    const K = [
      [1e-6, 13.931442073626419458688962846, 999999.999992784324215075882301],
      [0.01, 4.72124473016109494432463037498, 99.9738941182962455609319931003],
      [0.3, 1.37246006054429741057321301059, 3.0559920334573251071823113024],
      [1, 0.421024438240708333335627379213, 0.601907230197234574737540001536],
      [5, 0.00369109833404259427473526100746, 0.00404461344545216420836502183754],
      [30, 2.13247749646305637116689606297e-14, 2.16773200189154942486703783362e-14],
    ];
    for (const [z, k0, k1] of K) {
      expect(relErr(besselK(0, z), k0)).toBeLessThan(1e-13);
      expect(relErr(besselK(1, z), k1)).toBeLessThan(1e-13);
    }
  });
  it('Gauss-Legendre rules integrate polynomials of degree 2n−1 exactly', () => {
    const { nodes, weights } = gaussLegendre(10);
    const integral = (deg) => nodes.reduce((s, x, i) => s + weights[i] * x ** deg, 0);
    for (let deg = 0; deg < 20; deg++) expect(Math.abs(integral(deg) - (deg % 2 ? 0 : 2 / (deg + 1)))).toBeLessThan(1e-14);
  });
  it('adaptive quadrature handles a square-root endpoint singularity', () => {
    const [v] = integrateAdaptive((x) => [Math.sqrt(x)], 0, 1, { dim: 1 });
    expect(Math.abs(v - 2 / 3)).toBeLessThan(1e-12);
  });
});
