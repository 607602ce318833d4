// Stage 3: one direction of the separable, depth- and mask-aware subsurface blur.
// Defines (src/3-blur/SubsurfaceBlurPass.js sets them): AXIS (0 = horizontal, 1 = vertical: an
// index into vectors), SAMPLES (the taps compiled for, odd; KERNEL_MODE_TAPS runs tapCount of them), FOLLOW_SURFACE (FOLLOW_SURFACE_OFF, _DROP, _LERP),
// FORESHORTEN (0 or 1: grazing-angle correction, below), SSS_COVERAGE (0 or 1: the inputs were
// resolved from MSAA, shaders/common/surfaceSample.glsl), SSS_MAX_SLOPE, SSS_MIN_KERNEL_PIXELS,
// SSS_ENERGY_LEFT (the numbers of src/3-blur/samplingModel.js), PROFILE_COUNT (the profiles in the
// frame; above 1 each pixel blurs with its own, shaders/common/surfaceSample.glsl) and KERNEL_MODE:
//   KERNEL_MODE_TAPS: fixed weights and offsets (computeKernel's reference or marginal kernel);
//   KERNEL_MODE_FOOTPRINT: per pixel, footprints of whole pixels from the FootprintTable, weighted
//     by the profile marginal's exact energy from the ProfileLookup.
//
// The sampling model this implements is stated once, numbered, in docs/ARCHITECTURE.md ("Stage 3:
// the sampling model"); the float64 oracle in test/oracle/convolution.js implements the same.

uniform sampler2D tDiffuse;  // the multi-target's diffuse light (or the horizontal pass's output); alpha: the mask
uniform sampler2D tSurface;  // the multi-target's surface: r linear view depth (world units), g world units per profile mm
uniform vec4 kernel[ SAMPLES ]; // (weight R, G, B, offset in kernel mm), centre tap first
uniform int tapCount;           // KERNEL_MODE_TAPS: the kernel's taps (<= SAMPLES; 'auto' sets it per frame)
uniform float kernelRadiusMm;   // the kernel's reach: below SSS_MIN_KERNEL_PIXELS of it a pixel does no work
uniform vec3 strength;          // KERNEL_MODE_FOOTPRINT: mix with no scattering (the reference's strength)
uniform vec2 projectionScale;   // camera.projectionMatrix.elements[0], [5]
uniform vec2 resolution;        // pixels (width, height)
uniform float depthFalloff;     // 1 / depth threshold (world units): dz beyond it is another surface
uniform bool perspective;       // false for an orthographic camera: the step does not shrink with depth

#include "common/finite.glsl"
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
	#define BLOCKS ( ( SAMPLES - 1 ) / 2 - 1 ) // footprints per side before the tail
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

// Adds one tap at `offsetPx` along the axis with kernel weight `weight` to the sums. Texels are
// compared with the depth the centre's plane predicts there: centreDepth + slope * (texel offset).
void addTap( const in float offsetPx, const in vec3 weight, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre, inout vec3 sum, inout vec3 weightSum ) {
	float position = float( pixel[ AXIS ] ) + 0.5 + offsetPx;
	if ( position < 0.0 || position >= resolution[ AXIS ] ) return;
	// The two texels around the tap along the axis (centres at integer + 0.5, clamped).
	float u = position - 0.5;
	float below = floor( u );
	float fraction = u - below;
	int last = int( resolution[ AXIS ] ) - 1;
	ivec2 texel0 = pixel;
	ivec2 texel1 = pixel;
	texel0[ AXIS ] = clamp( int( below ), 0, last );
	texel1[ AXIS ] = clamp( int( below ) + 1, 0, last );
	vec3 colour0, colour1 = vec3( 0.0 );
	float weight0 = ( 1.0 - fraction ) * sssTapWeight( texel0, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre, colour0 );
	float weight1 = 0.0;
	// A tap on a texel centre (every footprint one pixel wide: most of them at small scales) weighs
	// its second texel 0: not fetching it gives the same sums (SSS_SKIP_EMPTY_TEXELS 0: fetched).
	if ( SSS_SKIP_EMPTY_TEXELS == 0 || fraction > 0.0 ) weight1 = fraction * sssTapWeight( texel1, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre, colour1 );
	float kept = weight0 + weight1;
	if ( kept <= 0.0 ) return;
	sum += weight * ( colour0 * weight0 + colour1 * weight1 );
	weightSum += weight * kept;
}

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	SssCentre pixelCentre = sssCentreAt( pixel );
	vec3 centre = pixelCentre.colour;
	// Not a subsurface pixel: pass through so the next pass sees the same mask.
	if ( ! ( pixelCentre.coverage > 0.0 ) ) {
		gl_FragColor = vec4( centre, 0.0 );
		return;
	}
	vec2 surface = pixelCentre.surface;
	#if PROFILE_COUNT > 1
		sssSlot = sssNearestSlot( pixel, pixelCentre.coverage );
	#endif

	float stepPx = sssPixelsPerMm( surface )[ AXIS ];
	float slope = 0.0; // depth change per pixel along the axis, world units
	#if FORESHORTEN == 1
		float pixelWorld = sssPixelWorld( surface )[ AXIS ]; // world units one pixel spans across the view
		slope = sssSurfaceSlope( pixel, AXIS, surface, pixelWorld );
		float tilt = slope / pixelWorld;
		stepPx *= inversesqrt( 1.0 + tilt * tilt ); // cos(theta)
	#endif
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= SSS_MIN_KERNEL_PIXELS ) ) {
		gl_FragColor = sssCovered( centre, pixelCentre.coverage );
		return;
	}

	vec3 sum;
	vec3 weightSum;

	#if KERNEL_MODE == KERNEL_MODE_TAPS
		weightSum = SSS_KERNEL_TAP( 0 ).rgb;
		sum = centre * weightSum;
		for ( int i = 1; i < SAMPLES; i ++ ) {
			if ( i >= tapCount ) break;
			addTap( SSS_KERNEL_TAP( i ).a * stepPx, SSS_KERNEL_TAP( i ).rgb, pixel, surface.r, slope, centre, sum, weightSum );
		}
	#else
		// The table row nearest this pixel's scale (src/profiles/footprints.js's footprintRowOf).
		int row = clamp( int( floor( log2( stepPx / SSS_FOOTPRINT_SCALE_MIN ) * SSS_FOOTPRINT_PER_OCTAVE + 0.5 ) ), 0, SSS_FOOTPRINT_ROWS - 1 );
		// The centre pixel is its own footprint: |x| < 0.5 px.
		vec3 energyBelow = sssReadProfile( tProfile, SSS_MARGINAL_ROW, 0.5 / stepPx, SSS_MARGINAL_RANGE_MM );
		weightSum = 2.0 * energyBelow;
		sum = centre * weightSum;
		int lastEdge = 0; // pixels; footprint j covers pixels lastEdge + 1 .. edge on each side
		for ( int j = 0; j <= BLOCKS; j ++ ) {
			if ( all( greaterThan( energyBelow, vec3( 0.5 - SSS_ENERGY_LEFT ) ) ) ) break; // nothing left
			vec2 footprint = texelFetch( tFootprints, ivec2( j, SSS_FOOTPRINT_ROW( row ) ), 0 ).rg; // outer edge, sample offset (mm)
			// The last footprint runs to the kernel's end and takes all the energy left.
			bool last = j == BLOCKS || isinf( footprint.x );
			int edge = last ? lastEdge + 1 : max( int( floor( footprint.x * stepPx + 0.5 ) ), lastEdge + 1 );
			vec3 energy = last ? vec3( 0.5 ) : sssReadProfile( tProfile, SSS_MARGINAL_ROW, ( float( edge ) + 0.5 ) / stepPx, SSS_MARGINAL_RANGE_MM );
			vec3 weight = energy - energyBelow;
			// Sampled where the table says, kept inside the footprint as snapped at this pixel's scale.
			float offsetPx = max( footprint.y * stepPx, float( lastEdge + 1 ) );
			if ( ! last ) offsetPx = min( offsetPx, float( edge ) );
			addTap( offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			addTap( - offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			if ( last ) break;
			energyBelow = energy;
			lastEdge = edge;
		}
	#endif

	vec3 result = sum / weightSum;
	#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
		result = mix( centre, result, strength ); // fixed-tap kernels have the strength built in
	#endif
	gl_FragColor = sssCovered( sssFinite( result ) ? result : centre, pixelCentre.coverage );
}
