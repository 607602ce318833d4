// Stage 3: one direction of the isotropic blur's groups (shaders/3-blur/kernelGroups.glsl: the
// profile's Gaussians blurred in SSS_GROUPS groups, each separably, and summed by the vertical pass).
// The horizontal pass writes the groups into two integer attachments; the vertical one reads them.
// Defines: SSS_GROUPS (2..4), SSS_MAX_GROUPS, and shaders/3-blur/blurTaps.glsl's (AXIS, SAMPLES,
// KERNEL_MODE, which must be KERNEL_MODE_FOOTPRINT, the footprint table's, FOLLOW_SURFACE,
// FORESHORTEN, SSS_COVERAGE, PROFILE_COUNT and the sampling model's numbers; SSS_LIGHT_CARRIES_DEPTH 0:
// the light read is the multi-target's diffuse, horizontally, and the groups, vertically).

#if KERNEL_MODE != KERNEL_MODE_FOOTPRINT
	#error "the groups need KERNEL_MODE_FOOTPRINT"
#endif
#include "3-blur/blurTaps.glsl"
#include "3-blur/kernelGroups.glsl"
#if PROFILE_COUNT > 1
	#define SSS_GROUP_SLOT sssSlot
#else
	#define SSS_GROUP_SLOT 0
#endif
#if AXIS == 1
	layout( location = 0 ) out highp vec4 sssFragColor; // GLSL 3 (the horizontal pass writes two integer attachments)
	#define gl_FragColor sssFragColor
#endif

#if AXIS == 1
	// The tap rule's weight of a group texel: with the depth it carries (SSS_GROUPS_CARRY_DEPTH, one
	// profile) no surface fetch, else the rule as for any texel.
	float sssGroupTexelRule( const in ivec2 texel, const in float coverage, const in float depth, const in float expectedDepth, out float farness ) {
		#if SSS_GROUPS_CARRY_DEPTH == 1 && PROFILE_COUNT == 1
			return sssDepthRule( depth, expectedDepth, farness );
		#else
			return sssTexelRule( texel, coverage, expectedDepth, farness );
		#endif
	}

	// A group texel's weight at `share` of the tap (its linear weight) by the tap rule: 0 off the
	// mask (`coverage` 0); `farness`, what 'lerp' moves its groups by.
	float sssGroupTexelWeight( const in ivec2 texel, const in float share, const in float coverage, const in float depth, const in float expectedDepth, out float farness ) {
		farness = 0.0;
		if ( ! ( coverage > 0.0 ) ) return 0.0;
		return share * sssGroupTexelRule( texel, coverage, depth, expectedDepth, farness );
	}

	// 'lerp': two groups of a texel moved towards the centre's by the farness (no-op otherwise).
	void sssLerpGroups( inout vec3 first, inout vec3 second, const in vec3 centreFirst, const in vec3 centreSecond, const in float farness ) {
		#if FOLLOW_SURFACE == FOLLOW_SURFACE_LERP
			first = mix( first, centreFirst, farness );
			second = mix( second, centreSecond, farness );
		#endif
	}

	// Adds a texel's groups at `share` of the tap to the tap's light by the tap rule; returns the
	// weight kept. (GLSL evaluates arguments left to right: `depth` is read after sssGroupsAt wrote it.)
	float sssAddGroupTexel( const in ivec2 texel, const in float share, const in float expectedDepth,
		const in vec3 centre0, const in vec3 centre1, const in vec3 centre2, const in vec3 centre3,
		inout vec3 light0, inout vec3 light1, inout vec3 light2, inout vec3 light3 ) {
		vec3 a, b, c, d;
		float depth, farness;
		float weight = sssGroupTexelWeight( texel, share, sssGroupsAt( texel, a, b, c, d, depth ), depth, expectedDepth, farness );
		if ( weight == 0.0 ) return 0.0;
		sssLerpGroups( a, b, centre0, centre1, farness );
		#if SSS_GROUPS > 2
			sssLerpGroups( c, d, centre2, centre3, farness );
		#endif
		sssAccumulate( light0, light1, light2, light3, vec3( weight ), vec3( weight ), vec3( weight ), vec3( weight ), a, b, c, d );
		return weight;
	}

	#if SSS_GROUPS > 2
		// As sssAddGroupTexel for groups 3 and 4 only (the footprints past groups 1 and 2's reach:
		// one fetch, the group target's second attachment).
		float sssAddFarTexel( const in ivec2 texel, const in float share, const in float expectedDepth, const in vec3 centre2, const in vec3 centre3, inout vec3 light2, inout vec3 light3 ) {
			vec3 c, d;
			float depth, farness;
			float weight = sssGroupTexelWeight( texel, share, sssFarGroupsAt( texel, c, d, depth ), depth, expectedDepth, farness );
			if ( weight == 0.0 ) return 0.0;
			sssLerpGroups( c, d, centre2, centre3, farness );
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
