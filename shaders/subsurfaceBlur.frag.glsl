// Stage 3: one direction of the separable, depth- and mask-aware subsurface blur.
// Defines: AXIS (0 = horizontal, 1 = vertical), SAMPLES (taps, odd), FOLLOW_SURFACE (0 off, 1 drop,
// 2 lerp), FORESHORTEN (0 or 1: grazing-angle correction, below) and KERNEL_MODE:
//   0 'taps': fixed weights and offsets (computeKernel's reference or marginal kernel);
//   1 'footprint': per pixel, the marginal kernel's footprints are snapped to the pixel grid (at
//     least one pixel each) and weighted by the exact energy of the profile's marginal over them,
//     read from the ProfileLookup. Where the taps cover the on-screen kernel pixel by pixel this is
//     the exact 1D convolution of the pixel image; beyond, footprints follow the profile's energy.
//     It stops as soon as the energy left is negligible, so small kernels cost fewer taps.
//
// Sampling model (the float64 oracle in test/oracle/convolution.js implements the same):
// - the step per kernel millimetre, in pixels, is widthWorld * P / (2 * depth) * resolution, with
//   P the projection's scale on this axis (P[0] or P[5]: the aspect fix, REFERENCE §4) and depth 1
//   for an orthographic camera;
// - a tap inside the screen lies between two texels along the axis; each texel counts with its
//   linear-interpolation weight times its mask (the diffuse light's alpha: 0 off subsurface pixels,
//   whatever their width) times, in 'drop' mode,
//   1 - farness (its depth difference over the threshold), so no colour crosses a depth edge or
//   the mask through filtering; in 'lerp' mode each texel's colour is lerped to the centre's;
// - the tap's kernel weight is scaled by the sum of its texel weights and each channel is
//   renormalised by the weights used;
// - grazing angles (FORESHORTEN, default on): the surface's depth slope along the axis, in world
//   units per pixel, comes from the two neighbours (central difference; one-sided when a neighbour
//   is off the mask or steeper than SSS_MAX_SLOPE = 4; 0 when both are). A surface tilted by theta puts
//   1 / cos(theta) = sqrt(1 + s^2) of surface under each pixel (s: depth change per world unit
//   across), so the step shrinks by cos(theta), as the seed paper proposes with a normal buffer; and
//   'drop'/'lerp' measure each texel's depth against the plane through the centre (centre depth +
//   slope * texel offset), so a tilted surface is not mistaken for a depth edge.

uniform sampler2D tDiffuse;  // diffuse light, linear HDR; alpha 1 on subsurface pixels, 0 elsewhere (the mask)
uniform sampler2D tSurface;  // r: linear view depth (world units), g: world units per kernel mm x strength
uniform vec4 kernel[ SAMPLES ]; // (weight R, G, B, offset in kernel mm), centre tap first
uniform float kernelRadiusMm;   // the kernel's reach: below half a pixel a pixel does no work
uniform vec3 strength;          // 'footprint' mode: mix with no scattering (the reference's strength)
uniform float projectionScale;  // camera.projectionMatrix.elements[0] or [5]
uniform vec2 resolution;        // pixels (width, height)
uniform float depthFalloff;     // 1 / depth threshold (world units): dz beyond it is another surface
uniform bool perspective;       // false for an orthographic camera: the step does not shrink with depth

// shaders/surfaceSlope.glsl (the slope estimate, shared with the dense reference) is inlined here
// by SubsurfaceBlurPass. Its SSS_MAX_SLOPE = 4 (76 degrees): at coarse resolutions a real depth
// edge (nose over cheek, ~20 mm) can be only a few pixel-widths deep and must not pass for a plane.
SURFACE_SLOPE_GLSL

#if KERNEL_MODE == 1
	#define BLOCKS ( ( SAMPLES - 1 ) / 2 - 1 ) // footprints per side before the tail
	// Energy per side below which the rest of the kernel is left out (invisible even at radiance 1e4).
	#define ENERGY_LEFT 1e-5
	uniform sampler2D tProfile;                 // ProfileLookup.texture, row 1: G(x) = ∫_0^x marginal
	uniform float marginalRangeMm;              // ProfileLookup.marginalRangeMm
	uniform float footprintEdgesMm[ EDGE_ARRAY_SIZE ]; // outer edge of each footprint, mm (max(BLOCKS, 1) entries)
	uniform float tailOffsetMm;                 // where the tail beyond the last edge is sampled, mm
	// shaders/profileLookup.glsl is inlined here by SubsurfaceBlurPass.
	PROFILE_LOOKUP_GLSL
#endif

varying vec2 vUv;

// shaders/finite.glsl, inlined by the pass.
FINITE_GLSL

// Weight of one texel of a tap: its interpolation weight, 0 off the mask, and in 'drop' mode less
// the farther its surface is from the centre's. In 'lerp' mode its colour moves to the centre's.
float texelWeight( const in ivec2 texel, const in float interpolation, const in float expectedDepth, const in vec3 centre, out vec3 colour ) {
	vec4 light = texelFetch( tDiffuse, texel, 0 );
	colour = light.rgb;
	if ( ! ( light.a > 0.0 ) || ! sssFinite( colour ) ) {
		colour = vec3( 0.0 );
		return 0.0;
	}
	float weight = interpolation;
	#if FOLLOW_SURFACE != 0
		float depth = texelFetch( tSurface, texel, 0 ).r;
		float farness = clamp( abs( depth - expectedDepth ) * depthFalloff, 0.0, 1.0 );
		#if FOLLOW_SURFACE == 1
			weight *= 1.0 - farness; // drop and renormalise (Unreal, HDRP)
		#else
			colour = mix( colour, centre, farness ); // lerp back to the centre (Jimenez 2012)
		#endif
	#endif
	return weight;
}

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
	vec3 colour0, colour1;
	float weight0 = texelWeight( texel0, 1.0 - fraction, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre, colour0 );
	float weight1 = texelWeight( texel1, fraction, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre, colour1 );
	float kept = weight0 + weight1;
	if ( kept <= 0.0 ) return;
	sum += weight * ( colour0 * weight0 + colour1 * weight1 );
	weightSum += weight * kept;
}

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	vec2 surface = texelFetch( tSurface, pixel, 0 ).rg;
	vec4 centreLight = texelFetch( tDiffuse, pixel, 0 );
	vec3 centre = sssFinite( centreLight.rgb ) ? centreLight.rgb : vec3( 0.0 );

	// Not a subsurface pixel: pass through so the next pass sees the same mask.
	if ( ! ( centreLight.a > 0.0 ) ) {
		gl_FragColor = vec4( centre, 0.0 );
		return;
	}

	float stepPx = surface.g * projectionScale / ( 2.0 * ( perspective ? surface.r : 1.0 ) ) * resolution[ AXIS ];
	float slope = 0.0; // depth change per pixel along the axis, world units
	#if FORESHORTEN == 1
		// World units one pixel spans across the view at this depth.
		float pixelWorld = 2.0 * ( perspective ? surface.r : 1.0 ) / ( projectionScale * resolution[ AXIS ] );
		slope = sssSurfaceSlope( pixel, AXIS, surface, pixelWorld );
		float tilt = slope / pixelWorld;
		stepPx *= inversesqrt( 1.0 + tilt * tilt ); // cos(theta)
	#endif
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= 0.5 ) ) {
		gl_FragColor = vec4( centre, 1.0 );
		return;
	}

	vec3 sum;
	vec3 weightSum;

	#if KERNEL_MODE == 0
		weightSum = kernel[ 0 ].rgb;
		sum = centre * weightSum;
		for ( int i = 1; i < SAMPLES; i ++ ) {
			addTap( kernel[ i ].a * stepPx, kernel[ i ].rgb, pixel, surface.r, slope, centre, sum, weightSum );
		}
	#else
		// The centre pixel is its own footprint: |x| < 0.5 px.
		vec3 energyBelow = sssReadProfile( tProfile, 1, 0.5 / stepPx, marginalRangeMm );
		weightSum = 2.0 * energyBelow;
		sum = centre * weightSum;
		int lastEdge = 0; // pixels; footprint j covers pixels lastEdge + 1 .. edge on each side
		for ( int j = 0; j < BLOCKS; j ++ ) {
			if ( all( greaterThan( energyBelow, vec3( 0.5 - ENERGY_LEFT ) ) ) ) break; // nothing left
			int edge = max( int( floor( footprintEdgesMm[ j ] * stepPx + 0.5 ) ), lastEdge + 1 );
			vec3 energy = sssReadProfile( tProfile, 1, ( float( edge ) + 0.5 ) / stepPx, marginalRangeMm );
			vec3 weight = energy - energyBelow;
			float offsetPx = 0.5 * float( lastEdge + 1 + edge ); // the footprint's middle
			addTap( offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			addTap( - offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			energyBelow = energy;
			lastEdge = edge;
		}
		// The tail beyond the last edge, sampled where the kernel put its outermost tap.
		vec3 tail = vec3( 0.5 ) - energyBelow;
		if ( any( greaterThan( tail, vec3( ENERGY_LEFT ) ) ) ) {
			float offsetPx = max( tailOffsetMm * stepPx, float( lastEdge + 1 ) );
			addTap( offsetPx, tail, pixel, surface.r, slope, centre, sum, weightSum );
			addTap( - offsetPx, tail, pixel, surface.r, slope, centre, sum, weightSum );
		}
	#endif

	vec3 result = sum / weightSum;
	#if KERNEL_MODE == 1
		result = mix( centre, result, strength ); // 'taps' kernels have the strength built in
	#endif
	gl_FragColor = vec4( sssFinite( result ) ? result : centre, 1.0 );
}
