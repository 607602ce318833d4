// The numbers of the blur's sampling model (docs/ARCHITECTURE.md, "Stage 3: the sampling model"),
// shared by the shaders (as defines: SurfacePass sets them) and by the float64 oracle in
// test/oracle/convolution.js, which imports the numbers but none of the code.

/**
 * Below half a pixel of on-screen radius a kernel cannot move light into another pixel: the pixel
 * (and, for the largest radius of a frame, the whole blur) does no work.
 */
export const MIN_KERNEL_PIXELS = 0.5;

/**
 * A neighbour whose depth changes by more than this many world units per world unit across (76°)
 * belongs to another surface: the slope estimate ignores it. At coarse resolutions a real depth
 * edge (nose over cheek, about 20 mm) can be only a few pixel-widths deep and must not pass for a
 * plane.
 */
export const MAX_SLOPE = 4;

/**
 * Where both neighbours lie on the surface and their slopes agree within this fraction of the
 * larger, the pixel is on one plane however steep (up to MAX_PLANE_SLOPE): a plane tilted past
 * 76° (MAX_SLOPE) was otherwise taken for a depth edge (no foreshortening, and 'drop' cut the
 * kernel across it). A real edge has one side on each surface: their slopes differ by the step.
 * Perspective bends a plane's per-pixel depth steps by a few percent a pixel, well within 25 %.
 */
export const PLANE_SLOPE_AGREEMENT = 0.25;

/** The steepest plane followed, world units of depth per world unit across (89°). */
export const MAX_PLANE_SLOPE = 57;

/**
 * The slope estimate's three limits (PLANE_SLOPE_AGREEMENT, MAX_PLANE_SLOPE, MAX_SLOPE) each fade
 * linearly over a band below the limit, from the limit divided by this to the limit, instead of
 * switching there: at creases (eyelids, nostrils, lips) a neighbour's depth crosses a limit from
 * one frame to the next under the slightest motion, and a switch there changed the pixel's
 * foreshortening, and so its whole kernel, in one step: single pixels popped (the dolly of
 * test/browser/creases.test.js). Nothing beyond a limit counts, as before: a band above it let
 * the ears' depth edges count as slopes (docs/ARCHITECTURE.md, "Steady at creases").
 */
export const SLOPE_FADE = 4;

/**
 * 'footprint' kernels stop once each side has less energy left than this: invisible even at
 * radiance 1e4 in a half-float target (whose step there is about 8).
 */
export const ENERGY_LEFT = 1e-5;
