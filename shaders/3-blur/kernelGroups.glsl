// The isotropic blur's groups (src/3-blur/kernelGroups.js, issue 20). A horizontal then vertical
// blur with one kernel is exact along the screen axes only (off them its transfer is
// A(f cos θ)·A(f sin θ), not the radial profile's); a 2D Gaussian is exactly separable, so the
// profile's Gaussians are blurred in SSS_GROUPS (2..4) groups, each separably, and the vertical pass
// sums them: only the cross terms inside a group are left. Each footprint's marginal energy (the
// exact one, from the ProfileLookup) is split between the groups by the fractions of
// KernelGroupTable (computed at the footprint table row's scale from the groups' Gaussians); the
// taps and their fetches are the one-kernel blur's.
//
// Between the passes (BlurStage's group target, two RGBA32UI attachments; halves are the precision
// of the HalfFloatType target they replace), every value premultiplied by the coverage as the
// multi-target's diffuse is:
//   tGroups0: rgb = packHalf2x16(group 1, group 2) of that channel, a = the coverage's bits;
//   tGroups1: rgb = packHalf2x16(group 3, group 4) of that channel, a = the coverage's bits again
//             (SSS_GROUPS > 2 only; the footprints past groups 1 and 2's reach read it alone).
// With SSS_GROUPS_CARRY_DEPTH (without MSAA, where the coverage is 1 on the mask and 0 off it) both
// alphas carry the centre's linear depth instead, as the one-kernel hand-off does
// (shaders/common/carriedDepth.glsl: 0 off the mask): the vertical pass's taps then read no
// surface texel with one profile.
// The groups are four named vec3s (unused ones compiled out), never an array, and SSS_GROUPS is a
// define with one program per count (SubsurfaceBlurPass): on SwiftShader an array of groups measured
// 9x the one-kernel blur's time, and a uniform count's branches another 1.3x.

#if SSS_COVERAGE == 0
	#define SSS_GROUPS_CARRY_DEPTH 1
#else
	#define SSS_GROUPS_CARRY_DEPTH 0
#endif

uniform vec3 groupEnergies[ SSS_MAX_GROUPS * PROFILE_COUNT ]; // slot p's group g: its share of the energy, per channel, at [p * SSS_MAX_GROUPS + g]
uniform highp usampler2D tGroupFractions;                 // KernelGroupTable.texture: column 0 the centre, column j + 1 footprint j

// Three fractions (r, g, b) from 10-bit unorms in bits 0, 10, 20 (KernelGroupTable).
vec3 sssUnorm10( const in uint packed ) {
	return vec3( ( uvec3( packed ) >> uvec3( 0u, 10u, 20u ) ) & 1023u ) / 1023.0;
}

// A footprint's energy `weight` split between the groups: groups 1..SSS_GROUPS − 1's RGB fractions
// in the table texel's r, g, b, the last group the rest, so the parts sum to `weight`. `column` 0 is
// the centre, j + 1 footprint j, of row `row`. Parts of groups past SSS_GROUPS are 0.
void sssSplit( const in vec3 weight, const in int column, const in int row, out vec3 part0, out vec3 part1, out vec3 part2, out vec3 part3 ) {
	uvec3 packed = texelFetch( tGroupFractions, ivec2( column, row ), 0 ).rgb;
	part0 = weight * sssUnorm10( packed.r );
	part2 = part3 = vec3( 0.0 );
	#if SSS_GROUPS == 2
		part1 = max( weight - part0, vec3( 0.0 ) );
	#else
		part1 = weight * sssUnorm10( packed.g );
		#if SSS_GROUPS == 3
			part2 = max( weight - part0 - part1, vec3( 0.0 ) );
		#else
			part2 = weight * sssUnorm10( packed.b );
			part3 = max( weight - part0 - part1 - part2, vec3( 0.0 ) );
		#endif
	#endif
}

// The footprints of row `row` within groups 1 and 2's reach (KernelGroupTable's NEAR_SHARE): the
// centre texel's a. Past them a footprint is blurred for groups 3 and 4 only.
int sssNearFootprints( const in int row ) {
	return int( texelFetch( tGroupFractions, ivec2( 0, row ), 0 ).a );
}

// sum_g += part_g * light_g for the groups the frame has (groups 3 and 4 above two): the one way
// the blur accumulates them (named vec3s, see the header).
void sssAccumulate( inout vec3 sum0, inout vec3 sum1, inout vec3 sum2, inout vec3 sum3,
	const in vec3 part0, const in vec3 part1, const in vec3 part2, const in vec3 part3,
	const in vec3 light0, const in vec3 light1, const in vec3 light2, const in vec3 light3 ) {
	sum0 += part0 * light0;
	sum1 += part1 * light1;
	#if SSS_GROUPS > 2
		sum2 += part2 * light2;
		sum3 += part3 * light3;
	#endif
}

#if AXIS == 0
	// Both attachments are written at every count: WebGL refuses a draw with a target attachment
	// the shader has no output for.
	layout( location = 0 ) out highp uvec4 sssGroupsOut0;
	layout( location = 1 ) out highp uvec4 sssGroupsOut1;

	// Writes the groups, premultiplied by `coverage`, and the coverage or (SSS_GROUPS_CARRY_DEPTH) the
	// centre's `depth` on the mask (see the header).
	void sssWriteGroups( const in vec3 light0, const in vec3 light1, const in vec3 light2, const in vec3 light3, const in float coverage, const in float depth ) {
		vec3 a = light0 * coverage;
		vec3 b = light1 * coverage;
		#if SSS_GROUPS_CARRY_DEPTH == 1
			uint alpha = floatBitsToUint( coverage > 0.0 ? sssCarriedDepth( depth ) : 0.0 );
		#else
			uint alpha = floatBitsToUint( coverage );
		#endif
		sssGroupsOut0 = uvec4( packHalf2x16( vec2( a.r, b.r ) ), packHalf2x16( vec2( a.g, b.g ) ), packHalf2x16( vec2( a.b, b.b ) ), alpha );
		#if SSS_GROUPS > 2
			vec3 c = light2 * coverage;
			vec3 d = light3 * coverage;
			sssGroupsOut1 = uvec4( packHalf2x16( vec2( c.r, d.r ) ), packHalf2x16( vec2( c.g, d.g ) ), packHalf2x16( vec2( c.b, d.b ) ), alpha );
		#else
			sssGroupsOut1 = uvec4( 0u );
		#endif
	}
#else
	uniform highp usampler2D tGroups0; // the horizontal pass's groups (see the header)
	#if SSS_GROUPS > 2
		uniform highp usampler2D tGroups1;
	#endif

	// The two groups of one attachment's texel: rgb = packHalf2x16(first, second) per channel.
	void sssUnpackGroups( const in uvec3 packed, out vec3 first, out vec3 second ) {
		vec2 r = unpackHalf2x16( packed.r );
		vec2 g = unpackHalf2x16( packed.g );
		vec2 b = unpackHalf2x16( packed.b );
		first = vec3( r.x, g.x, b.x );
		second = vec3( r.y, g.y, b.y );
	}

	// The coverage and the carried depth (SSS_GROUPS_CARRY_DEPTH; else 0) a texel's alpha holds.
	float sssGroupCoverage( const in uint alpha, out float depth ) {
		float value = uintBitsToFloat( alpha );
		#if SSS_GROUPS_CARRY_DEPTH == 1
			depth = value;
			return sssCarriesSurface( value ) ? 1.0 : 0.0;
		#else
			depth = 0.0;
			return value;
		#endif
	}

	// A texel's groups with the coverage divided out, and its carried depth (SSS_GROUPS_CARRY_DEPTH);
	// returns the coverage (0 off the mask, or when a group is not finite).
	float sssGroupsAt( const in ivec2 texel, out vec3 light0, out vec3 light1, out vec3 light2, out vec3 light3, out float depth ) {
		uvec4 packed = texelFetch( tGroups0, texel, 0 );
		float coverage = sssGroupCoverage( packed.a, depth );
		sssUnpackGroups( packed.rgb, light0, light1 );
		vec3 sum = light0 + light1;
		light2 = light3 = vec3( 0.0 );
		#if SSS_GROUPS > 2
			sssUnpackGroups( texelFetch( tGroups1, texel, 0 ).rgb, light2, light3 );
			sum += light2 + light3;
		#endif
		if ( ! ( coverage > 0.0 ) || ! sssFinite( sum ) ) {
			light0 = light1 = light2 = light3 = vec3( 0.0 );
			return 0.0;
		}
		#if SSS_COVERAGE == 1
			float inverse = 1.0 / coverage;
			light0 *= inverse;
			light1 *= inverse;
			light2 *= inverse;
			light3 *= inverse;
		#endif
		return coverage;
	}

	#if SSS_GROUPS > 2
		// Groups 3 and 4 of a texel alone (the second attachment, which holds the coverage or the depth too).
		float sssFarGroupsAt( const in ivec2 texel, out vec3 light2, out vec3 light3, out float depth ) {
			uvec4 packed = texelFetch( tGroups1, texel, 0 );
			float coverage = sssGroupCoverage( packed.a, depth );
			sssUnpackGroups( packed.rgb, light2, light3 );
			if ( ! ( coverage > 0.0 ) || ! sssFinite( light2 + light3 ) ) {
				light2 = light3 = vec3( 0.0 );
				return 0.0;
			}
			#if SSS_COVERAGE == 1
				light2 /= coverage;
				light3 /= coverage;
			#endif
			return coverage;
		}
	#endif
#endif
