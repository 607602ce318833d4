// Stage 3 for WebGPURenderer: one direction of the separable, depth- and mask-aware subsurface
// blur, 'footprint' kernel mode, as a TSL fragment node. A port of
// shaders/3-blur/subsurfaceBlur.frag.glsl (its KERNEL_MODE_FOOTPRINT branch; its header states
// the sampling model, which this follows step by step: addTap ↔ addTap, main ↔ subsurfaceBlur).
// The footprint table and the profile lookup are the WebGL path's own textures (FootprintTable,
// ProfileLookup), filled by the same JS.
import {
  Break, Fn, If, Loop, all, clamp, float, floor, greaterThan, int, inverseSqrt, ivec2, log2, max, min, mix, screenCoordinate,
  select, textureLoad, vec3, vec4,
} from 'three/tsl';
import { FOOTPRINT_ROWS, FOOTPRINT_SCALES } from '../../profiles/footprints.js';
import { ENERGY_LEFT, MIN_KERNEL_PIXELS } from '../../3-blur/samplingModel.js';
import {
  along, finite3, finite1, readProfile, screenScale, surfaceSample, surfaceSlope, surfaceTap, withAlong,
} from './surfaceTsl.js';

/**
 * The blur's fragment node.
 * @param {object} o
 * @param {0|1} o.axis 0 horizontal, 1 vertical
 * @param {number} o.samples the kernel's taps (odd): (samples - 1) / 2 - 1 footprints per side before the tail
 * @param {'off'|'drop'|'lerp'} o.followSurface
 * @param {boolean} o.foreshorten the grazing-angle correction
 * @param {boolean} o.coverage the inputs were resolved from MSAA
 * @param {object} o.diffuse texture node: the light to blur (a: the mask)
 * @param {object} o.surface texture node: r linear view depth, g widthMm
 * @param {object} o.profile texture node of ProfileLookup.texture
 * @param {number} o.profileSize its texels per row
 * @param {object} o.footprints texture node of FootprintTable.texture
 * @param {object} o.uniforms { kernelRadiusMm, strength, projectionScale, resolution, depthFalloff, perspective, mmToWorld, marginalRangeMm }
 */
export function subsurfaceBlurNode(o) {
  const { axis, samples, uniforms: u } = o;
  const blocks = (samples - 1) / 2 - 1; // footprints per side before the tail
  const scale = screenScale(u);
  const sample = surfaceSample(o);
  const slopeAt = surfaceSlope(sample, u, axis);
  const tapWeight = surfaceTap(sample, u, o);
  const profileAt = readProfile(o.profile, o.profileSize);
  const resolutionAlong = along(u.resolution, axis);

  // Adds one tap at `offsetPx` along the axis with kernel weight `weight` to the sums; texels are
  // compared with the depth the centre's plane predicts there: centreDepth + slope * (texel offset).
  const addTap = (offsetPx, weight, pixel, centreDepth, slope, centre, sum, weightSum) => {
    const position = float(along(pixel, axis)).add(0.5).add(offsetPx).toVar();
    If(position.greaterThanEqual(0).and(position.lessThan(resolutionAlong)), () => {
      const u0 = position.sub(0.5);
      const below = floor(u0);
      const fraction = u0.sub(below).toVar();
      const last = int(resolutionAlong).sub(1);
      const at0 = clamp(int(below), 0, last).toVar();
      const at1 = clamp(int(below).add(1), 0, last).toVar();
      const offset0 = float(at0.sub(along(pixel, axis)));
      const offset1 = float(at1.sub(along(pixel, axis)));
      const tap0 = tapWeight(withAlong(pixel, axis, at0), centreDepth.add(slope.mul(offset0)), centre);
      const weight0 = fraction.oneMinus().mul(tap0.weight).toVar();
      // A tap on a texel centre weighs its second texel 0: not fetched (subsurfaceBlur.frag.glsl's
      // SSS_SKIP_EMPTY_TEXELS; the same sums).
      const weight1 = float(0).toVar();
      const colour1 = vec3(0).toVar();
      If(fraction.greaterThan(0), () => {
        const tap1 = tapWeight(withAlong(pixel, axis, at1), centreDepth.add(slope.mul(offset1)), centre);
        weight1.assign(fraction.mul(tap1.weight));
        colour1.assign(tap1.colour);
      });
      const kept = weight0.add(weight1);
      If(kept.greaterThan(0), () => {
        sum.addAssign(weight.mul(tap0.colour.mul(weight0).add(colour1.mul(weight1))));
        weightSum.addAssign(weight.mul(kept));
      });
    });
  };

  return Fn(() => {
    const pixel = ivec2(screenCoordinate.xy).toVar();
    const centre = sample.centreAt(pixel);
    const colour = centre.colour;
    // Not a subsurface pixel: pass through so the next pass sees the same mask.
    const result = vec4(colour, 0).toVar();
    If(centre.coverage.greaterThan(0), () => {
      const surface = centre.surface;
      const stepPx = along(scale.pixelsPerMm(surface), axis).toVar();
      const slope = float(0).toVar(); // depth change per pixel along the axis, world units
      if (o.foreshorten) {
        const pixelWorld = along(scale.pixelWorld(surface), axis).toVar();
        slope.assign(slopeAt(pixel, surface, pixelWorld));
        const tilt = slope.div(pixelWorld);
        stepPx.mulAssign(inverseSqrt(tilt.mul(tilt).add(1))); // cos(theta)
      }
      result.assign(sample.covered(colour, centre.coverage));
      // Below half a pixel the kernel cannot move light to another pixel: no work.
      If(stepPx.mul(u.kernelRadiusMm).greaterThanEqual(MIN_KERNEL_PIXELS), () => {
        // The table row nearest this pixel's scale (src/profiles/footprints.js's footprintRowOf).
        const row = clamp(int(floor(log2(stepPx.div(FOOTPRINT_SCALES.min)).mul(FOOTPRINT_SCALES.perOctave).add(0.5))), 0, FOOTPRINT_ROWS - 1).toVar();
        // The centre pixel is its own footprint: |x| < 0.5 px.
        const energyBelow = profileAt(1, float(0.5).div(stepPx), u.marginalRangeMm).toVar();
        const weightSum = energyBelow.mul(2).toVar();
        const sum = colour.mul(weightSum).toVar();
        const lastEdge = int(0).toVar(); // pixels; footprint j covers lastEdge + 1 .. edge on each side
        Loop({ start: int(0), end: int(blocks), type: 'int', condition: '<=' }, ({ i: j }) => {
          If(all(greaterThan(energyBelow, vec3(0.5 - ENERGY_LEFT))), () => { Break(); }); // nothing left
          const footprint = textureLoad(o.footprints, ivec2(j, row)).xy.toVar(); // outer edge, sample offset (mm)
          // The last footprint runs to the kernel's end and takes all the energy left.
          const last = j.equal(blocks).or(finite1(footprint.x).not()).toVar();
          const snapped = max(int(floor(select(last, float(0), footprint.x).mul(stepPx).add(0.5))), lastEdge.add(1));
          const edge = select(last, lastEdge.add(1), snapped).toVar();
          const energy = select(last, vec3(0.5), profileAt(1, float(edge).add(0.5).div(stepPx), u.marginalRangeMm)).toVar();
          const weight = energy.sub(energyBelow).toVar();
          // Sampled where the table says, kept inside the footprint as snapped at this pixel's scale.
          const inside = max(footprint.y.mul(stepPx), float(lastEdge.add(1)));
          const offsetPx = select(last, inside, min(inside, float(edge))).toVar();
          addTap(offsetPx, weight, pixel, surface.x, slope, colour, sum, weightSum);
          addTap(offsetPx.negate(), weight, pixel, surface.x, slope, colour, sum, weightSum);
          If(last, () => { Break(); });
          energyBelow.assign(energy);
          lastEdge.assign(edge);
        });
        const blurred = mix(colour, sum.div(weightSum), u.strength).toVar();
        result.assign(sample.covered(select(finite3(blurred), blurred, colour), centre.coverage));
      });
    });
    return result;
  })();
}
