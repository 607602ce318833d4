// Stage 3's taps along one axis in TSL, shared by the one-kernel blur and the isotropic blur's
// groups: a port of shaders/3-blur/blurTaps.glsl, function by function (sssTapTexels, sssLinearTap
// and addTap → tapAdder; sssAxisStep → axisStep; sssFootprintRow → footprintRow; sssFootprint →
// footprintStep). Each builder is called inside the pass's Fn (src/webgpu/3-blur/subsurfaceBlurTsl.js).
import { If, clamp, float, floor, int, inverseSqrt, ivec2, log2, max, min, select, textureLoad, vec3 } from 'three/tsl';
import { FOOTPRINT_ROWS, FOOTPRINT_SCALES } from '../../profiles/footprints.js';
import { along, finite1, withAlong } from '../common/surfaceTsl.js';

/**
 * addTap: adds one tap at `offsetPx` along the axis, each sum with its part (`parts`) of the kernel
 * weight; the tap's two texels (centres at integer + 0.5, clamped) are compared with the depth the
 * centre's plane predicts there: centreDepth + slope * (texel offset). A texel outside the
 * subsurface pixels' box (`boxAlong`: its first and last + 1 along the axis) is off the mask: it
 * weighs 0 unread, as it would read (the node's blur targets are not cleared outside the box).
 * @param {{ axis: 0|1, lights: object[], lightOf: (k: number) => number, tapWeight: Function, resolutionAlong: object, boxAlong: object[] }} o
 *   lightOf: the light sum k blurs; tapWeight: surfaceTsl.js's surfaceTap
 */
export function tapAdder({ axis, lights, lightOf, tapWeight, resolutionAlong, boxAlong: [boxStart, boxEnd] }) {
  const inBox = (at) => at.greaterThanEqual(int(boxStart)).and(at.lessThan(int(boxEnd)));
  return (offsetPx, parts, pixel, centreDepth, slope, centres, sums, weightSums) => {
    const position = float(along(pixel, axis)).add(0.5).add(offsetPx).toVar();
    If(position.greaterThanEqual(0).and(position.lessThan(resolutionAlong)), () => {
      const u0 = position.sub(0.5);
      const below = floor(u0);
      const fraction = u0.sub(below).toVar();
      const last = int(resolutionAlong).sub(1);
      const at0 = clamp(int(below), 0, last).toVar();
      const at1 = clamp(int(below).add(1), 0, last).toVar();
      const weight0 = float(0).toVar();
      const colours0 = lights.map(() => vec3(0).toVar());
      const weight1 = float(0).toVar();
      const colours1 = lights.map(() => vec3(0).toVar());
      /** Texel `at`'s weight (times `share`) and colours into `weight` and `colours`, where it is in the box. */
      const read = (at, share, weight, colours) => {
        const tap = tapWeight(withAlong(pixel, axis, at), centreDepth.add(slope.mul(float(at.sub(along(pixel, axis))))), centres);
        weight.assign(share.mul(tap.weight));
        colours.forEach((colour, k) => colour.assign(tap.colours[k]));
      };
      If(inBox(at0), () => read(at0, fraction.oneMinus(), weight0, colours0));
      // A tap on a texel centre weighs its second texel 0: not fetched (the same sums).
      If(fraction.greaterThan(0).and(inBox(at1)), () => read(at1, fraction, weight1, colours1));
      const kept = weight0.add(weight1);
      If(kept.greaterThan(0), () => {
        sums.forEach((sum, k) => sum.addAssign(parts[k].mul(colours0[lightOf(k)].mul(weight0).add(colours1[lightOf(k)].mul(weight1)))));
        weightSums.forEach((weightSum, k) => weightSum.addAssign(parts[k].mul(kept)));
      });
    });
  };
}

/**
 * sssAxisStep: the pixel's scale along the axis, px per profile mm (times cos(tilt) with
 * `foreshorten`), and the depth change per pixel along it (world units; 0 without).
 * @param {{ axis: 0|1, scale: object, slopeAt: Function, foreshorten: boolean }} o
 *   scale: surfaceTsl.js's screenScale; slopeAt: its surfaceSlope
 */
export function axisStep({ axis, scale, slopeAt, foreshorten }) {
  return (pixel, surface) => {
    const stepPx = along(scale.pixelsPerMm(surface), axis).toVar();
    const slope = float(0).toVar();
    if (foreshorten) {
      const pixelWorld = along(scale.pixelWorld(surface), axis).toVar();
      slope.assign(slopeAt(pixel, surface, pixelWorld));
      const tilt = slope.div(pixelWorld);
      stepPx.mulAssign(inverseSqrt(tilt.mul(tilt).add(1))); // cos(theta)
    }
    return { stepPx, slope };
  };
}

/** sssFootprintRow: the table row nearest a pixel's scale (src/profiles/footprints.js's footprintRowOf). */
export const footprintRow = (stepPx) => clamp(int(floor(log2(stepPx.div(FOOTPRINT_SCALES.min)).mul(FOOTPRINT_SCALES.perOctave).add(0.5))), 0, FOOTPRINT_ROWS - 1).toVar();

/**
 * sssFootprint: footprint j of table row `row` at the pixel's scale: its energy per side
 * (`weight`), where it is sampled (`offsetPx`, snapped to whole pixels), its outer edge and the
 * energy below it (to carry to the next), and whether it is the last (it runs to the kernel's end).
 * @param {{ footprints: object, profileAt: Function, marginalRangeMm: object, blocks: number }} o
 *   footprints: texture node of the FootprintTable; profileAt: surfaceTsl.js's readProfile;
 *   blocks: footprints per side before the tail
 */
export function footprintStep({ footprints, profileAt, marginalRangeMm, blocks }) {
  return (j, row, stepPx, energyBelow, lastEdge) => {
    const footprint = textureLoad(footprints, ivec2(j, row)).xy.toVar(); // outer edge, sample offset (mm)
    // The last footprint runs to the kernel's end and takes all the energy left.
    const last = j.equal(blocks).or(finite1(footprint.x).not()).toVar();
    const snapped = max(int(floor(select(last, float(0), footprint.x).mul(stepPx).add(0.5))), lastEdge.add(1));
    const edge = select(last, lastEdge.add(1), snapped).toVar();
    const energy = select(last, vec3(0.5), profileAt(1, float(edge).add(0.5).div(stepPx), marginalRangeMm)).toVar();
    const weight = energy.sub(energyBelow).toVar();
    // Sampled where the table says, kept inside the footprint as snapped at this pixel's scale.
    const inside = max(footprint.y.mul(stepPx), float(lastEdge.add(1)));
    const offsetPx = select(last, inside, min(inside, float(edge))).toVar();
    return { last, edge, energy, weight, offsetPx };
  };
}
