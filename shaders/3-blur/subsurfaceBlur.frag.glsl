// Stage 3: one direction of the separable, depth- and mask-aware subsurface blur with one kernel
// (exact along the screen axes). The horizontal pass writes its light with the centre's depth in
// the alpha for the vertical one; the vertical pass writes it premultiplied by its coverage.
// Defines: shaders/3-blur/blurTaps.glsl's (AXIS, SAMPLES, KERNEL_MODE, the footprint table's,
// FOLLOW_SURFACE, FORESHORTEN, SSS_COVERAGE, SSS_LIGHT_CARRIES_DEPTH, PROFILE_COUNT and the
// sampling model's numbers).

#include "3-blur/blurTaps.glsl"

layout( location = 0 ) out highp vec4 sssFragColor; // GLSL 3, as the groups' program
#define gl_FragColor sssFragColor

// A subsurface pixel's result: from the horizontal pass as it is with the centre's depth in the
// alpha (carriedDepth.glsl: the vertical taps fetch one texel, not two), from the vertical one
// premultiplied by its coverage (sssCovered), as the compose reads it.
vec4 sssBlurOutput( const in vec3 colour, const in float coverage, const in float depth ) {
	#if AXIS == 0
		return vec4( colour, sssCarriedDepth( depth ) );
	#else
		return sssCovered( colour, coverage );
	#endif
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

	float slope; // depth change per pixel along the axis, world units
	float stepPx = sssAxisStep( pixel, surface, slope );
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= SSS_MIN_KERNEL_PIXELS ) ) {
		gl_FragColor = sssBlurOutput( centre, pixelCentre.coverage, surface.r );
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
		int row = sssFootprintRow( stepPx );
		// The centre pixel is its own footprint: |x| < 0.5 px.
		vec3 energyBelow = sssReadProfile( tProfile, SSS_MARGINAL_ROW, 0.5 / stepPx, SSS_MARGINAL_RANGE_MM );
		weightSum = 2.0 * energyBelow;
		sum = centre * weightSum;
		int lastEdge = 0;
		for ( int j = 0; j <= BLOCKS; j ++ ) {
			vec3 weight;
			float offsetPx;
			bool last;
			if ( ! sssFootprint( j, row, stepPx, energyBelow, lastEdge, weight, offsetPx, last ) ) break;
			addTap( offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			addTap( - offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			if ( last ) break;
		}
	#endif

	vec3 result = sum / weightSum;
	#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
		result = mix( centre, result, strength ); // fixed-tap kernels have the strength built in
	#endif
	gl_FragColor = sssBlurOutput( sssFinite( result ) ? result : centre, pixelCentre.coverage, surface.r );
}
