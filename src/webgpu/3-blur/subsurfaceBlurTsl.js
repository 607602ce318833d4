// Stage 3 for WebGPURenderer: one direction of the separable, depth- and mask-aware subsurface
// blur, 'footprint' kernel mode, as a TSL fragment node: the main() of
// shaders/3-blur/subsurfaceBlur.frag.glsl (KERNEL_MODE_FOOTPRINT) and, with `groups`, of
// kernelGroupsBlur.frag.glsl, in one builder (the groups are arrays of sums at build time, so a
// node builds either program); the taps they share are blurTapsTsl.js, as blurTaps.glsl, whose
// header states the sampling model this follows step by step.
// The footprint table and the profile lookup are the WebGL path's own textures (FootprintTable,
// ProfileLookup), filled by the same JS.
// With `groups` it is one pass of the isotropic blur (kernelGroups.js and
// shaders/3-blur/kernelGroups.glsl): each footprint's energy is split between the groups
// by GroupFractionTexture; the horizontal pass writes each group to its own attachment of one
// multi-target (halves, where the GLSL packs four groups in two integer texels), and the vertical
// pass reads every group's texel at each tap and sums the groups, each normalised by its own weight.
import {
  Break, Fn, If, Loop, all, float, greaterThan, int, ivec2, mat4, mix, mrt, screenCoordinate, select, textureLoad, vec3, vec4,
} from 'three/tsl';
import { FOOTPRINT_ROWS } from '../../profiles/footprints.js';
import { ENERGY_LEFT, MIN_KERNEL_PIXELS } from '../../3-blur/samplingModel.js';
import {
  along, carriedDepth, finite3, readProfile, screenScale, surfaceSample, surfaceSlope, surfaceTap,
} from '../common/surfaceTsl.js';
import { axisStep, footprintRow, footprintStep, tapAdder } from './blurTapsTsl.js';

/**
 * Each channel of `sum` over its weight, `fallback` where nothing was kept (kernelGroupsBlur.frag.glsl's
 * sssNormalised; scalar selects: GLSL has no ternary over a bvec3).
 */
const normalised = (sum, weightSum, fallback) => vec3(
  select(weightSum.x.greaterThan(0), sum.x.div(weightSum.x), fallback.x),
  select(weightSum.y.greaterThan(0), sum.y.div(weightSum.y), fallback.y),
  select(weightSum.z.greaterThan(0), sum.z.div(weightSum.z), fallback.z),
);

/**
 * The blur's fragment node.
 * @param {object} o
 * @param {0|1} o.axis 0 horizontal, 1 vertical
 * @param {number} o.samples the kernel's taps (odd): (samples - 1) / 2 - 1 footprints per side before the tail
 * @param {'off'|'drop'|'lerp'} o.followSurface
 * @param {boolean} o.foreshorten the grazing-angle correction
 * @param {boolean} o.coverage the inputs were resolved from MSAA
 * @param {object} o.diffuse texture node: the light to blur (a: the mask, or the depth with `carriesDepth`)
 * @param {boolean} [o.carriesDepth] `diffuse` carries the surface's depth in its alpha (the
 *   horizontal pass's output with `carryDepth`): the taps read no surface (carriedDepth.glsl)
 * @param {boolean} [o.carryDepth] the output carries the centre's depth in its alpha, not the
 *   coverage (one kernel without MSAA: the coverage is 1 on the mask)
 * @param {object} o.surface texture node: r linear view depth, g widthMm
 * @param {object} o.profile texture node of ProfileLookup.texture
 * @param {number} o.profileSize its texels per row
 * @param {object} o.footprints texture node of FootprintTable.texture
 * @param {object} o.uniforms { kernelRadiusMm, strength, projectionScale, resolution, depthFalloff, perspective, mmToWorld, marginalRangeMm,
 *   subsurfaceBox (x0, y0, x1, y1: the subsurface pixels' box, from the top left; the passes run in it) }
 * @param {object} [o.groups] the isotropic blur (absent: one kernel): { count, fractions: texture
 *   node of GroupFractionTexture; horizontal: names (the multi-target's attachment of each group,
 *   its light times the group's planned share) and energies (uniform vec3s: each group's share of
 *   the profile's energy, for pixels that do no work); vertical: lights (each group's attachment;
 *   `diffuse` is the first) }
 * @returns {object} the fragment node; the horizontal pass in groups an mrt() of the groups' outputs
 */
export function subsurfaceBlurNode(o) {
  const { axis, samples, uniforms: u, groups } = o;
  const blocks = (samples - 1) / 2 - 1; // footprints per side before the tail
  const scale = screenScale(u);
  const sample = surfaceSample(o);
  const slopeAt = surfaceSlope(sample, u, axis);
  // The lights the taps read and the group each sum is of: one kernel one light and no group; the
  // horizontal group pass the diffuse light for every group; the vertical one each group's own.
  const lights = axis === 1 && groups ? groups.lights : [o.diffuse];
  const sumGroups = groups ? Array.from({ length: groups.count }, (_, g) => g) : [null];
  const lightOf = (k) => (lights.length === 1 ? 0 : k); // the light sum k blurs
  const tapWeight = surfaceTap(sample, u, { ...o, lights });
  const profileAt = readProfile(o.profile, o.profileSize);
  const resolutionAlong = along(u.resolution, axis);
  // Each sum's part of `weight`, the energy of table column `column` (0: the centre, j + 1: footprint j).
  const partsOf = (weight, column, row) => sumGroups.map((g) => (g === null ? weight
    : weight.mul(textureLoad(groups.fractions, ivec2(column, row.add(g * FOOTPRINT_ROWS))).rgb)));

  const boxAlong = axis === 0 ? [u.subsurfaceBox.x, u.subsurfaceBox.z] : [u.subsurfaceBox.y, u.subsurfaceBox.w];
  const addTap = tapAdder({ axis, lights, lightOf, tapWeight, resolutionAlong, boxAlong });
  const stepAt = axisStep({ axis, scale, slopeAt, foreshorten: o.foreshorten });
  const footprintAt = footprintStep({ footprints: o.footprints, profileAt, marginalRangeMm: u.marginalRangeMm, blocks });

  const splits = axis === 0 && groups; // the horizontal pass in groups: one output per group
  const call = Fn(() => {
    const pixel = ivec2(screenCoordinate.xy).toVar();
    const centre = sample.centreAt(pixel);
    const colour = centre.colour;
    // Each light's centre colour (the groups' texels share the coverage), and what a pixel that
    // does no work writes: its light as it is, or (the horizontal group pass) each group's share of it.
    const texels = lights.slice(1).map((light) => textureLoad(light, pixel).rgb.toVar());
    const centres = [colour, ...texels.map((rgb) => sample.colourOf(rgb, centre.coverage))];
    // The vertical group pass: a centre whose groups are not all finite (a half past its range) is
    // off the mask, as kernelGroups.glsl's sssGroupsAt has it.
    const coverage = texels.length === 0 ? centre.coverage
      : select(finite3(texels.reduce((sum, rgb) => sum.add(rgb), centre.rgb)), centre.coverage, float(0)).toVar();
    const unblurred = centres.slice(1).reduce((sum, c) => sum.add(c), colour).toVar();
    const unsplit = splits ? groups.energies.slice(0, groups.count).map((energy) => colour.mul(energy).toVar()) : [unblurred];
    // Not a subsurface pixel: pass through so the next pass sees the same mask.
    const results = unsplit.map((light) => vec4(light, 0).toVar());
    If(coverage.greaterThan(0), () => {
      const surface = centre.surface();
      // The output, premultiplied by the coverage, or carrying the depth (SSS_DEPTH_ZERO for 0: still on the mask).
      const out = o.carryDepth ? (light) => vec4(light, carriedDepth(surface.x)) : (light) => sample.covered(light, coverage);
      const { stepPx, slope } = stepAt(pixel, surface); // slope: depth change per pixel along the axis, world units
      results.forEach((result, k) => result.assign(out(unsplit[k])));
      // Below half a pixel the kernel cannot move light to another pixel: no work.
      If(stepPx.mul(u.kernelRadiusMm).greaterThanEqual(MIN_KERNEL_PIXELS), () => {
        const row = footprintRow(stepPx);
        // The centre pixel is its own footprint: |x| < 0.5 px.
        const energyBelow = profileAt(1, float(0.5).div(stepPx), u.marginalRangeMm).toVar();
        const centreParts = partsOf(energyBelow.mul(2), 0, row);
        const weightSums = centreParts.map((part) => vec3(part).toVar());
        const sums = centreParts.map((part, k) => centres[lightOf(k)].mul(part).toVar());
        // The horizontal group pass: each group's weight and the whole kernel's as planned, dropped
        // taps and all (the groups' planned shares, below).
        const plannedGroups = splits ? centreParts.map((part) => vec3(part).toVar()) : [];
        const planned = energyBelow.mul(2).toVar();
        const lastEdge = int(0).toVar(); // pixels; footprint j covers lastEdge + 1 .. edge on each side
        Loop({ start: int(0), end: int(blocks), type: 'int', condition: '<=' }, ({ i: j }) => {
          If(all(greaterThan(energyBelow, vec3(0.5 - ENERGY_LEFT))), () => { Break(); }); // nothing left
          const { last, edge, energy, weight, offsetPx } = footprintAt(j, row, stepPx, energyBelow, lastEdge);
          const parts = partsOf(weight, j.add(1), row).map((part) => vec3(part).toVar());
          addTap(offsetPx, parts, pixel, surface.x, slope, centres, sums, weightSums);
          addTap(offsetPx.negate(), parts, pixel, surface.x, slope, centres, sums, weightSums);
          if (splits) {
            plannedGroups.forEach((plannedGroup, k) => plannedGroup.addAssign(parts[k].mul(2)));
            planned.addAssign(weight.mul(2));
          }
          If(last, () => { Break(); });
          energyBelow.assign(energy);
          lastEdge.assign(edge);
        });
        let blurred;
        if (!groups) blurred = [mix(colour, sums[0].div(weightSums[0]), u.strength)];
        // Group g: its light over its own kept weight (the one-kernel rule, per group), times its
        // planned share, so the groups sum to the one-kernel blur with nothing dropped and keep
        // their shares at depth edges (the GLSL's horizontal pass, kernelGroups.glsl).
        else if (splits) blurred = sums.map((sum, k) => plannedGroups[k].div(planned).mul(mix(colour, normalised(sum, weightSums[k], colour), u.strength)));
        // The groups' sum, each normalised by its own weight.
        else blurred = [mix(unblurred, sums.map((sum, k) => normalised(sum, weightSums[k], centres[k])).reduce((a, b) => a.add(b)), u.strength)];
        // Not finite: the light unblurred (every group's share of it at once, so the groups still sum to the light).
        const values = blurred.map((light) => vec3(light).toVar());
        const finite = finite3(values.slice(1).reduce((sum, v) => sum.add(v), values[0])).toVar();
        values.forEach((value, k) => results[k].assign(out(select(finite, value, unsplit[k]))));
      });
    });
    // The horizontal group pass's outputs as a matrix's columns (one value out of a TSL function).
    return splits ? mat4(...results, ...Array(4 - results.length).fill(vec4(0))).toVar() : results[0];
  })();
  if (!splits) return call;
  return mrt(Object.fromEntries(groups.names.map((name, g) => [name, call.element(g)])));
}
