// Stage 3: the separable blur's taps along one axis, shared by its two programs
// (shaders/3-blur/subsurfaceBlur.frag.glsl, one kernel; shaders/3-blur/kernelGroupsBlur.frag.glsl,
// the isotropic blur's groups): the tap rule over the two texels around a tap, the pixel's step
// along the axis and the footprints. Included first; the sampling model it implements is stated
// once, numbered, in docs/ARCHITECTURE.md ("Stage 3: the sampling model"); the float64 oracle in
// test/oracle/convolution.js implements the same.
// Defines (src/3-blur/SubsurfaceBlurPass.js and SurfacePass.js set them):
//   AXIS: 0 horizontal, 1 vertical (an index into vectors);
//   SAMPLES: the most taps, odd (each count is the uniform tapCount below it: no count recompiles);
//   KERNEL_MODE: KERNEL_MODE_TAPS, fixed weights and offsets (computeKernel's reference or
//     marginal kernel); KERNEL_MODE_FOOTPRINT, per pixel footprints of whole pixels from the
//     FootprintTable, weighted by the profile marginal's exact energy from the ProfileLookup;
//   SSS_FOOTPRINT_SCALE_MIN, SSS_FOOTPRINT_PER_OCTAVE, SSS_FOOTPRINT_ROWS: the footprint table's rows;
//   FOLLOW_SURFACE (FOLLOW_SURFACE_OFF, _DROP, _LERP), FORESHORTEN (0 or 1: the grazing-angle
//     correction), SSS_COVERAGE (0 or 1: the inputs were resolved from MSAA), SSS_LIGHT_CARRIES_DEPTH
//     (0 or 1: the light read carries the depth in its alpha, one fetch per tap),
//     PROFILE_COUNT (above 1 each pixel blurs with its own profile), SSS_MAX_SLOPE,
//     SSS_MIN_KERNEL_PIXELS, SSS_ENERGY_LEFT and the slot tolerances: the common chunks'.

uniform sampler2D tDiffuse;  // the multi-target's diffuse light (or the horizontal pass's output); alpha: the mask
uniform sampler2D tSurface;  // the multi-target's surface: r linear view depth (world units), g world units per profile mm
uniform vec4 kernel[ SAMPLES ]; // (weight R, G, B, offset in kernel mm), centre tap first
uniform int tapCount;           // the kernel's taps (<= SAMPLES; the footprints' budget; 'auto' sets it per frame)
uniform float kernelRadiusMm;   // the kernel's reach: below SSS_MIN_KERNEL_PIXELS of it a pixel does no work
uniform vec3 strength;          // KERNEL_MODE_FOOTPRINT: mix with no scattering (the reference's strength)
uniform vec2 projectionScale;   // camera.projectionMatrix.elements[0], [5]
uniform vec2 resolution;        // the view's pixels (width, height): the frame, or an ArrayCamera view's viewport
uniform vec2 viewOrigin;        // the view's first pixel (0, 0 for the frame): taps stay in the view
uniform float depthFalloff;     // 1 / depth threshold (world units): dz beyond it is another surface
uniform bool perspective;       // false for an orthographic camera: the step does not shrink with depth

#include "common/finite.glsl"
#include "common/carriedDepth.glsl"
#include "common/screenScale.glsl"
#include "common/surfaceSample.glsl"
#include "common/surfaceSlope.glsl"
#include "common/surfaceTap.glsl"

#if KERNEL_MODE == KERNEL_MODE_TAPS && PROFILE_COUNT > 1
	// Several profiles: row p holds slot p's kernel, laid out as `kernel` (SubsurfaceBlurPass.setKernel).
	uniform sampler2D tKernels;
	#define SSS_KERNEL_TAP( i ) texelFetch( tKernels, ivec2( i, sssSlot ), 0 )
#else
	#define SSS_KERNEL_TAP( i ) kernel[ i ]
#endif

#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
	#define BLOCKS ( ( tapCount - 1 ) / 2 - 1 ) // footprints per side before the tail
	uniform sampler2D tProfile;                 // ProfileLookup.texture, row 1: G(x) = ∫_0^x marginal
	#if PROFILE_COUNT == 1
		uniform float marginalRangeMm;              // ProfileLookup.marginalRangeMm
		#define SSS_MARGINAL_ROW 1
		#define SSS_MARGINAL_RANGE_MM marginalRangeMm
		#define SSS_FOOTPRINT_ROW( row ) row
	#else
		// Several profiles: tProfile and tFootprints are ProfileStack's, slot p's rows at 2p + 1 and
		// from p * SSS_FOOTPRINT_ROWS; the pixel reads its own slot's (sssSlot).
		uniform float marginalRangesMm[ PROFILE_COUNT ]; // ProfileStack.marginalRangesMm
		#define SSS_MARGINAL_ROW ( 2 * sssSlot + 1 )
		#define SSS_MARGINAL_RANGE_MM marginalRangesMm[ sssSlot ]
		#define SSS_FOOTPRINT_ROW( row ) ( sssSlot * SSS_FOOTPRINT_ROWS + row )
	#endif
	// FootprintTable.texture: row r is scale SSS_FOOTPRINT_SCALE_MIN * 2^(r / SSS_FOOTPRINT_PER_OCTAVE)
	// px/mm; texel j holds footprint j's outer edge (infinite for the last one) and where it is
	// sampled (where it keeps the kernel's variance: footprintSamplePosition), in profile mm.
	uniform sampler2D tFootprints;
	#include "common/profileLookup.glsl"
#endif

varying vec2 vUv;

// The two texels around a tap at `offsetPx` along the axis (centres at integer + 0.5, clamped to
// the view) and the second one's share; false when the tap is off the view (the screen).
bool sssTapTexels( const in float offsetPx, const in ivec2 pixel, out ivec2 texel0, out ivec2 texel1, out float fraction ) {
	float position = float( pixel[ AXIS ] ) - viewOrigin[ AXIS ] + 0.5 + offsetPx;
	texel0 = texel1 = pixel;
	fraction = 0.0;
	if ( position < 0.0 || position >= resolution[ AXIS ] ) return false;
	float u = position - 0.5;
	float below = floor( u );
	fraction = u - below;
	int first = int( viewOrigin[ AXIS ] );
	int last = int( resolution[ AXIS ] ) - 1;
	texel0[ AXIS ] = first + clamp( int( below ), 0, last );
	texel1[ AXIS ] = first + clamp( int( below ) + 1, 0, last );
	return true;
}

// The light of a tap at `offsetPx`: its two texels' light, each times its share and the tap rule's
// weight, in `light`; returns the sum of those weights (0: nothing kept). Texels are compared with
// the depth the centre's plane predicts there: centreDepth + slope * (texel offset).
float sssLinearTap( const in float offsetPx, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre, out vec3 light ) {
	ivec2 texel0, texel1;
	float fraction;
	light = vec3( 0.0 );
	if ( ! sssTapTexels( offsetPx, pixel, texel0, texel1, fraction ) ) return 0.0;
	vec3 colour0, colour1 = vec3( 0.0 );
	float weight0 = ( 1.0 - fraction ) * sssTapWeight( texel0, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre, colour0 );
	float weight1 = 0.0;
	// A tap on a texel centre (every footprint one pixel wide: most of them at small scales) weighs
	// its second texel 0: not fetching it gives the same sums.
	if ( fraction > 0.0 ) weight1 = fraction * sssTapWeight( texel1, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre, colour1 );
	light = colour0 * weight0 + colour1 * weight1;
	return weight0 + weight1;
}

// Adds one tap at `offsetPx` along the axis with kernel weight `weight` to the sums.
void addTap( const in float offsetPx, const in vec3 weight, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre, inout vec3 sum, inout vec3 weightSum ) {
	vec3 light;
	float kept = sssLinearTap( offsetPx, pixel, centreDepth, slope, centre, light );
	if ( kept <= 0.0 ) return;
	sum += weight * light;
	weightSum += weight * kept;
}

// The pixel's scale along the axis, px per profile mm (times cos(tilt) with FORESHORTEN), and the
// depth change per pixel along it (world units; 0 without FORESHORTEN).
float sssAxisStep( const in ivec2 pixel, const in vec2 surface, out float slope ) {
	float stepPx = sssPixelsPerMm( surface )[ AXIS ];
	slope = 0.0;
	#if FORESHORTEN == 1
		float pixelWorld = sssPixelWorld( surface )[ AXIS ]; // world units one pixel spans across the view
		slope = sssSurfaceSlope( pixel, AXIS, surface, pixelWorld );
		float tilt = slope / pixelWorld;
		stepPx *= inversesqrt( 1.0 + tilt * tilt ); // cos(theta)
	#endif
	return stepPx;
}

#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
	// The table row nearest a pixel's scale (src/profiles/footprints.js's footprintRowOf).
	int sssFootprintRow( const in float stepPx ) {
		return clamp( int( floor( log2( stepPx / SSS_FOOTPRINT_SCALE_MIN ) * SSS_FOOTPRINT_PER_OCTAVE + 0.5 ) ), 0, SSS_FOOTPRINT_ROWS - 1 );
	}

	// Footprint j of table row `row` at the pixel's scale: its energy per side (`weight`) and where
	// it is sampled (`offsetPx`), snapped to whole pixels; `energyBelow` and `lastEdge` (pixels;
	// footprint j covers pixels lastEdge + 1 .. edge on each side) carry from one to the next.
	// Returns false when nothing is left (the loop ends); `last`: it runs to the kernel's end.
	bool sssFootprint( const in int j, const in int row, const in float stepPx, inout vec3 energyBelow, inout int lastEdge, out vec3 weight, out float offsetPx, out bool last ) {
		weight = vec3( 0.0 );
		offsetPx = 0.0;
		last = true;
		if ( all( greaterThan( energyBelow, vec3( 0.5 - SSS_ENERGY_LEFT ) ) ) ) return false; // nothing left
		vec2 footprint = texelFetch( tFootprints, ivec2( j, SSS_FOOTPRINT_ROW( row ) ), 0 ).rg; // outer edge, sample offset (mm)
		// The last footprint runs to the kernel's end and takes all the energy left.
		last = j == BLOCKS || isinf( footprint.x );
		int edge = last ? lastEdge + 1 : max( int( floor( footprint.x * stepPx + 0.5 ) ), lastEdge + 1 );
		vec3 energy = last ? vec3( 0.5 ) : sssReadProfile( tProfile, SSS_MARGINAL_ROW, ( float( edge ) + 0.5 ) / stepPx, SSS_MARGINAL_RANGE_MM );
		weight = energy - energyBelow;
		// Sampled where the table says, kept inside the footprint as snapped at this pixel's scale.
		offsetPx = max( footprint.y * stepPx, float( lastEdge + 1 ) );
		if ( ! last ) offsetPx = min( offsetPx, float( edge ) );
		energyBelow = energy;
		lastEdge = edge;
		return true;
	}
#endif
