// Stage 3: one direction of the separable, depth- and mask-aware subsurface blur.
// Defines (src/3-blur/SubsurfaceBlurPass.js sets them): AXIS (0 = horizontal, 1 = vertical: an
// index into vectors), SAMPLES (the most taps, odd: every count is the uniform tapCount below it, so no count recompiles), FOLLOW_SURFACE (FOLLOW_SURFACE_OFF, _DROP, _LERP),
// FORESHORTEN (0 or 1: grazing-angle correction, below), SSS_COVERAGE (0 or 1: the inputs were
// resolved from MSAA, shaders/common/surfaceSample.glsl), SSS_MAX_SLOPE, SSS_MIN_KERNEL_PIXELS,
// SSS_ENERGY_LEFT (the numbers of src/3-blur/samplingModel.js), PROFILE_COUNT (the profiles in the
// frame; above 1 each pixel blurs with its own, shaders/common/surfaceSample.glsl), SSS_GROUPS (1:
// one kernel; 2..4: the isotropic blur's groups, 'footprint' only, shaders/3-blur/kernelGroups.glsl:
// the horizontal pass then writes the groups, the vertical one sums them), SSS_LIGHT_CARRIES_DEPTH (1: the
// light read carries the depth in its alpha, one fetch per tap instead of two:
// shaders/common/surfaceSample.glsl; the horizontal pass of one kernel writes its light that way
// for the vertical one) and KERNEL_MODE:
//   KERNEL_MODE_TAPS: fixed weights and offsets (computeKernel's reference or marginal kernel);
//   KERNEL_MODE_FOOTPRINT: per pixel, footprints of whole pixels from the FootprintTable, weighted
//     by the profile marginal's exact energy from the ProfileLookup.
//
// The sampling model this implements is stated once, numbered, in docs/ARCHITECTURE.md ("Stage 3:
// the sampling model"); the float64 oracle in test/oracle/convolution.js implements the same.

uniform sampler2D tDiffuse;  // the multi-target's diffuse light (or the horizontal pass's output, SSS_GROUPS 1); alpha: the mask
uniform sampler2D tSurface;  // the multi-target's surface: r linear view depth (world units), g world units per profile mm
uniform vec4 kernel[ SAMPLES ]; // (weight R, G, B, offset in kernel mm), centre tap first
uniform int tapCount;           // the kernel's taps (<= SAMPLES; the footprints' budget; 'auto' sets it per frame)
uniform float kernelRadiusMm;   // the kernel's reach: below SSS_MIN_KERNEL_PIXELS of it a pixel does no work
uniform vec3 strength;          // KERNEL_MODE_FOOTPRINT: mix with no scattering (the reference's strength)
uniform vec2 projectionScale;   // camera.projectionMatrix.elements[0], [5]
uniform vec2 resolution;        // pixels (width, height)
uniform float depthFalloff;     // 1 / depth threshold (world units): dz beyond it is another surface
uniform bool perspective;       // false for an orthographic camera: the step does not shrink with depth

#include "common/finite.glsl"
#include "common/carriedDepth.glsl"
#include "common/screenScale.glsl"
#include "common/surfaceSample.glsl"
#include "common/surfaceSlope.glsl"
#include "common/surfaceTap.glsl"

#if SSS_GROUPS > 1
	#if KERNEL_MODE != KERNEL_MODE_FOOTPRINT
		#error "SSS_GROUPS > 1 needs KERNEL_MODE_FOOTPRINT"
	#endif
	#include "3-blur/kernelGroups.glsl"
	#if PROFILE_COUNT > 1
		#define SSS_GROUP_SLOT sssSlot
	#else
		#define SSS_GROUP_SLOT 0
	#endif
#endif
#if SSS_GROUPS == 1 || AXIS == 1
	layout( location = 0 ) out highp vec4 sssFragColor; // GLSL 3 (the horizontal groups write two integer attachments)
	#define gl_FragColor sssFragColor
#endif

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

// The two texels around a tap at `offsetPx` along the axis (centres at integer + 0.5, clamped) and
// the second one's share; false when the tap is off screen.
bool sssTapTexels( const in float offsetPx, const in ivec2 pixel, out ivec2 texel0, out ivec2 texel1, out float fraction ) {
	float position = float( pixel[ AXIS ] ) + 0.5 + offsetPx;
	texel0 = texel1 = pixel;
	fraction = 0.0;
	if ( position < 0.0 || position >= resolution[ AXIS ] ) return false;
	float u = position - 0.5;
	float below = floor( u );
	fraction = u - below;
	int last = int( resolution[ AXIS ] ) - 1;
	texel0[ AXIS ] = clamp( int( below ), 0, last );
	texel1[ AXIS ] = clamp( int( below ) + 1, 0, last );
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

#if SSS_GROUPS > 1 && AXIS == 1
	// The tap rule's weight of a group texel: with the depth it carries (SSS_GROUPS_CARRY_DEPTH, one
	// profile) no surface fetch, else the rule as for any texel.
	float sssGroupTexelRule( const in ivec2 texel, const in float coverage, const in float depth, const in float expectedDepth, out float farness ) {
		#if SSS_GROUPS_CARRY_DEPTH == 1 && PROFILE_COUNT == 1
			return sssDepthRule( depth, expectedDepth, farness );
		#else
			return sssTexelRule( texel, coverage, expectedDepth, farness );
		#endif
	}

	// Adds a texel's groups at `share` of the tap (its linear weight) to the tap's light by the tap
	// rule ('lerp': each group moved towards the centre's by the farness); returns the weight kept.
	float sssAddGroupTexel( const in ivec2 texel, const in float share, const in float expectedDepth,
		const in vec3 centre0, const in vec3 centre1, const in vec3 centre2, const in vec3 centre3,
		inout vec3 light0, inout vec3 light1, inout vec3 light2, inout vec3 light3 ) {
		vec3 a, b, c, d;
		float depth;
		float coverage = sssGroupsAt( texel, a, b, c, d, depth );
		if ( ! ( coverage > 0.0 ) ) return 0.0;
		float farness;
		float weight = share * sssGroupTexelRule( texel, coverage, depth, expectedDepth, farness );
		#if FOLLOW_SURFACE == FOLLOW_SURFACE_LERP
			a = mix( a, centre0, farness );
			b = mix( b, centre1, farness );
			#if SSS_GROUPS > 2
				c = mix( c, centre2, farness );
				d = mix( d, centre3, farness );
			#endif
		#endif
		sssAccumulate( light0, light1, light2, light3, vec3( weight ), vec3( weight ), vec3( weight ), vec3( weight ), a, b, c, d );
		return weight;
	}

	#if SSS_GROUPS > 2
		// As sssAddGroupTexel for groups 3 and 4 only (the footprints past groups 1 and 2's reach:
		// one fetch, the group target's second attachment).
		float sssAddFarTexel( const in ivec2 texel, const in float share, const in float expectedDepth, const in vec3 centre2, const in vec3 centre3, inout vec3 light2, inout vec3 light3 ) {
			vec3 c, d;
			float depth;
			float coverage = sssFarGroupsAt( texel, c, d, depth );
			if ( ! ( coverage > 0.0 ) ) return 0.0;
			float farness;
			float weight = share * sssGroupTexelRule( texel, coverage, depth, expectedDepth, farness );
			#if FOLLOW_SURFACE == FOLLOW_SURFACE_LERP
				c = mix( c, centre2, farness );
				d = mix( d, centre3, farness );
			#endif
			light2 += c * weight;
			light3 += d * weight;
			return weight;
		}

		float sssLinearFarTap( const in float offsetPx, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre2, const in vec3 centre3, out vec3 light2, out vec3 light3 ) {
			ivec2 texel0, texel1;
			float fraction;
			light2 = light3 = vec3( 0.0 );
			if ( ! sssTapTexels( offsetPx, pixel, texel0, texel1, fraction ) ) return 0.0;
			float kept = sssAddFarTexel( texel0, 1.0 - fraction, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre2, centre3, light2, light3 );
			if ( fraction > 0.0 ) kept += sssAddFarTexel( texel1, fraction, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre2, centre3, light2, light3 );
			return kept;
		}
	#endif

	// The vertical pass's tap over the groups: as sssLinearTap, each group apart.
	float sssLinearGroupTap( const in float offsetPx, const in ivec2 pixel, const in float centreDepth, const in float slope,
		const in vec3 centre0, const in vec3 centre1, const in vec3 centre2, const in vec3 centre3,
		out vec3 light0, out vec3 light1, out vec3 light2, out vec3 light3 ) {
		ivec2 texel0, texel1;
		float fraction;
		light0 = light1 = light2 = light3 = vec3( 0.0 );
		if ( ! sssTapTexels( offsetPx, pixel, texel0, texel1, fraction ) ) return 0.0;
		float kept = sssAddGroupTexel( texel0, 1.0 - fraction, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre0, centre1, centre2, centre3, light0, light1, light2, light3 );
		// A tap on a texel centre weighs its second texel 0 (as sssLinearTap).
		if ( fraction > 0.0 ) kept += sssAddGroupTexel( texel1, fraction, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre0, centre1, centre2, centre3, light0, light1, light2, light3 );
		return kept;
	}
#endif

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

#if SSS_GROUPS == 1
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
#else
// Each channel's sum over its weights, or `fallback` where nothing was kept.
vec3 sssNormalised( const in vec3 sum, const in vec3 weightSum, const in vec3 fallback ) {
	return vec3(
		weightSum.r > 0.0 ? sum.r / weightSum.r : fallback.r,
		weightSum.g > 0.0 ? sum.g / weightSum.g : fallback.g,
		weightSum.b > 0.0 ? sum.b / weightSum.b : fallback.b
	);
}

#if AXIS == 0
	// A pixel that does no work (its kernel under half a pixel): its light split by the groups'
	// shares of the profile's energy.
	void sssWriteUnblurred( const in vec3 centre, const in float coverage, const in float depth ) {
		int first = SSS_GROUP_SLOT * SSS_MAX_GROUPS;
		#if SSS_GROUPS > 2
			vec3 energy2 = groupEnergies[ first + 2 ];
			#if SSS_GROUPS > 3
				vec3 energy3 = groupEnergies[ first + 3 ];
			#else
				vec3 energy3 = vec3( 0.0 );
			#endif
		#else
			vec3 energy2 = vec3( 0.0 ), energy3 = vec3( 0.0 );
		#endif
		sssWriteGroups( centre * groupEnergies[ first ], centre * groupEnergies[ first + 1 ], centre * energy2, centre * energy3, coverage, depth );
	}
#endif

// The groups' blur. The horizontal pass writes each group's light over all the groups' kept weight,
// so the groups sum to the one-kernel blur exactly, and the vertical pass, normalising each group by
// its own weight, gives the one-kernel answer along both axes; off them only the cross terms inside a
// group are left. With `strength` < 1 each group is mixed with its share of the unblurred light.
void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	#if AXIS == 0
		SssCentre pixelCentre = sssCentreAt( pixel );
		float coverage = pixelCentre.coverage;
		vec2 surface = pixelCentre.surface;
		vec3 centre = pixelCentre.colour;
		// Not a subsurface pixel: nothing (the diffuse attachment is 0 there), the mask kept.
		if ( ! ( coverage > 0.0 ) ) {
			sssWriteGroups( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), 0.0, 0.0 );
			return;
		}
	#else
		vec3 centre0, centre1, centre2, centre3;
		float carriedDepth; // the surface is read below: the centre needs its width too
		float coverage = sssGroupsAt( pixel, centre0, centre1, centre2, centre3, carriedDepth );
		vec2 surface = sssUncovered( texelFetch( tSurface, pixel, 0 ).rg, coverage );
		vec3 unblurred = centre0 + centre1 + centre2 + centre3;
		if ( ! ( coverage > 0.0 ) ) {
			gl_FragColor = vec4( 0.0 );
			return;
		}
	#endif
	#if PROFILE_COUNT > 1
		sssSlot = sssNearestSlot( pixel, coverage );
	#endif

	float slope;
	float stepPx = sssAxisStep( pixel, surface, slope );
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= SSS_MIN_KERNEL_PIXELS ) ) {
		#if AXIS == 0
			sssWriteUnblurred( centre, coverage, surface.r );
		#else
			gl_FragColor = sssCovered( unblurred, coverage );
		#endif
		return;
	}

	int row = sssFootprintRow( stepPx );
	vec3 energyBelow = sssReadProfile( tProfile, SSS_MARGINAL_ROW, 0.5 / stepPx, SSS_MARGINAL_RANGE_MM );
	vec3 weightSum0, weightSum1, weightSum2, weightSum3;
	sssSplit( 2.0 * energyBelow, 0, SSS_FOOTPRINT_ROW( row ), weightSum0, weightSum1, weightSum2, weightSum3 );
	#if AXIS == 0
		// Each group's weight as planned, dropped taps and all: the horizontal pass writes each group
		// normalised over its own kept weight, times its planned share (below).
		vec3 planned0 = weightSum0, planned1 = weightSum1, planned2 = weightSum2, planned3 = weightSum3;
		vec3 sum0 = centre * weightSum0, sum1 = centre * weightSum1, sum2 = centre * weightSum2, sum3 = centre * weightSum3;
	#else
		vec3 sum0 = centre0 * weightSum0, sum1 = centre1 * weightSum1, sum2 = centre2 * weightSum2, sum3 = centre3 * weightSum3;
	#endif
	int lastEdge = 0;
	// With three or four groups the footprints past groups 1 and 2's reach (`near`, from the table)
	// are blurred for groups 3 and 4 alone, in a second loop: one fetch per texel, not two.
	#if SSS_GROUPS > 2
		int near = sssNearFootprints( SSS_FOOTPRINT_ROW( row ) );
	#else
		int near = BLOCKS + 1;
	#endif
	int j = 0;
	bool done = false;
	for ( ; j <= BLOCKS; j ++ ) {
		if ( j >= near ) break;
		vec3 weight;
		float offsetPx;
		bool last;
		if ( ! sssFootprint( j, row, stepPx, energyBelow, lastEdge, weight, offsetPx, last ) ) {
			done = true;
			break;
		}
		vec3 part0, part1, part2, part3;
		sssSplit( weight, j + 1, SSS_FOOTPRINT_ROW( row ), part0, part1, part2, part3 );
		// Both sides' taps, then each group's part of their sum (the parts are the same on both sides).
		#if AXIS == 0
			vec3 light, other;
			float kept = sssLinearTap( offsetPx, pixel, surface.r, slope, centre, light );
			kept += sssLinearTap( - offsetPx, pixel, surface.r, slope, centre, other );
			light += other;
			sssAccumulate( sum0, sum1, sum2, sum3, part0, part1, part2, part3, light, light, light, light );
		#else
			vec3 light0, light1, light2, light3, other0, other1, other2, other3;
			float kept = sssLinearGroupTap( offsetPx, pixel, surface.r, slope, centre0, centre1, centre2, centre3, light0, light1, light2, light3 );
			kept += sssLinearGroupTap( - offsetPx, pixel, surface.r, slope, centre0, centre1, centre2, centre3, other0, other1, other2, other3 );
			sssAccumulate( sum0, sum1, sum2, sum3, part0, part1, part2, part3, light0 + other0, light1 + other1, light2 + other2, light3 + other3 );
		#endif
		sssAccumulate( weightSum0, weightSum1, weightSum2, weightSum3, part0, part1, part2, part3, vec3( kept ), vec3( kept ), vec3( kept ), vec3( kept ) );
		#if AXIS == 0
			sssAccumulate( planned0, planned1, planned2, planned3, part0, part1, part2, part3, vec3( 2.0 ), vec3( 2.0 ), vec3( 2.0 ), vec3( 2.0 ) );
		#endif
		if ( last ) {
			done = true;
			break;
		}
	}
	#if SSS_GROUPS > 2
		for ( ; j <= BLOCKS; j ++ ) {
			if ( done ) break;
			vec3 weight;
			float offsetPx;
			bool last;
			if ( ! sssFootprint( j, row, stepPx, energyBelow, lastEdge, weight, offsetPx, last ) ) break;
			#if SSS_GROUPS == 3
				vec3 part2 = weight;
				vec3 part3 = vec3( 0.0 );
			#else
				vec3 part2 = weight * sssUnorm10( texelFetch( tGroupFractions, ivec2( j + 1, SSS_FOOTPRINT_ROW( row ) ), 0 ).b );
				vec3 part3 = max( weight - part2, vec3( 0.0 ) ); // groups 1 and 2's share here is below the table's NEAR_SHARE
			#endif
			#if AXIS == 0
				vec3 light, other;
				float kept = sssLinearTap( offsetPx, pixel, surface.r, slope, centre, light );
				kept += sssLinearTap( - offsetPx, pixel, surface.r, slope, centre, other );
				light += other;
				sum2 += part2 * light;
				sum3 += part3 * light;
			#else
				vec3 light2, light3, other2, other3;
				float kept = sssLinearFarTap( offsetPx, pixel, surface.r, slope, centre2, centre3, light2, light3 );
				kept += sssLinearFarTap( - offsetPx, pixel, surface.r, slope, centre2, centre3, other2, other3 );
				sum2 += part2 * ( light2 + other2 );
				sum3 += part3 * ( light3 + other3 );
			#endif
			weightSum2 += part2 * kept;
			weightSum3 += part3 * kept;
			#if AXIS == 0
				planned2 += 2.0 * part2;
				planned3 += 2.0 * part3;
			#endif
			if ( last ) break;
		}
	#endif

	#if AXIS == 0
		vec3 planned = planned0 + planned1 + planned2 + planned3;
		if ( ! all( greaterThan( planned, vec3( 0.0 ) ) ) ) { // the centre's own weight is 0 only past float range
			sssWriteUnblurred( centre, coverage, surface.r );
			return;
		}
		// Group g: its light normalised over its own kept weight (the one-kernel blur's rule, per
		// group), times its planned share, mixed with that share of the unblurred light by
		// `strength`. With nothing dropped the groups sum to the one-kernel blur exactly, so both axes
		// are its answer; with drops (depth edges, the screen's border) each group keeps its share,
		// so the vertical pass's per-group averages cannot add up past the light (a share taken from
		// the kept weights would: the wide group loses more at an edge than the narrow one).
		vec3 inverse = 1.0 / planned;
		vec3 light0 = planned0 * inverse * mix( centre, sssNormalised( sum0, weightSum0, centre ), strength );
		vec3 light1 = planned1 * inverse * mix( centre, sssNormalised( sum1, weightSum1, centre ), strength );
		vec3 light2 = vec3( 0.0 ), light3 = vec3( 0.0 );
		#if SSS_GROUPS > 2
			light2 = planned2 * inverse * mix( centre, sssNormalised( sum2, weightSum2, centre ), strength );
			light3 = planned3 * inverse * mix( centre, sssNormalised( sum3, weightSum3, centre ), strength );
		#endif
		if ( sssFinite( light0 + light1 + light2 + light3 ) ) sssWriteGroups( light0, light1, light2, light3, coverage, surface.r );
		else sssWriteUnblurred( centre, coverage, surface.r );
	#else
		vec3 blurred = sssNormalised( sum0, weightSum0, centre0 ) + sssNormalised( sum1, weightSum1, centre1 );
		#if SSS_GROUPS > 2
			blurred += sssNormalised( sum2, weightSum2, centre2 ) + sssNormalised( sum3, weightSum3, centre3 );
		#endif
		vec3 result = mix( unblurred, blurred, strength );
		gl_FragColor = sssCovered( sssFinite( result ) ? result : unblurred, coverage );
	#endif
}
#endif
