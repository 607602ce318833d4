// The isotropic blur's groups (src/3-blur/kernelGroups.js, issue 20). A horizontal then vertical
// blur with one kernel is exact along the screen axes only (off them its transfer is
// A(f cos θ)·A(f sin θ), not the radial profile's); a 2D Gaussian is exactly separable, so the
// profile's Gaussians are blurred in up to SSS_GROUPS groups, each separably, and the vertical pass
// sums them: only the cross terms inside a group are left. Each footprint's marginal energy (the
// exact one, from the ProfileLookup) is split between the groups by the fractions of
// KernelGroupTable (computed at the footprint table row's scale from the groups' Gaussians).
//
// Between the passes (BlurStage's group target, two unsigned-integer attachments; halves are the
// precision of the HalfFloatType target they replace), every value premultiplied by the coverage
// as the multi-target's diffuse is:
//   tGroups0 (RGBA32UI): rgb = packHalf2x16(group 1, group 2) of that channel, a = the coverage's bits;
//   tGroups1 (RG32UI):   r = packHalf2x16(group 3's r, g), g = packHalf2x16(group 3's b, coverage).
// `groupCount` (1..SSS_GROUPS, per frame) says how many hold light; tGroups1 is read only for 3.

uniform int groupCount;                                   // the frame's groups, 1..SSS_GROUPS
uniform vec3 groupEnergies[ SSS_GROUPS * PROFILE_COUNT ]; // slot p's group g: its share of the energy, per channel, at [p * SSS_GROUPS + g]
uniform highp usampler2D tGroupFractions;                 // KernelGroupTable.texture: column 0 the centre, column j + 1 footprint j

// Group 1's and 2's fractions of a footprint's energy (group 3 has the rest); `column` 0 is the
// centre pixel, j + 1 footprint j, of the footprint table's row `row` (stacked by slot like it).
void sssGroupFractions( const in int column, const in int row, out vec3 first, out vec3 second ) {
	uvec4 packed = texelFetch( tGroupFractions, ivec2( column, row ), 0 );
	vec2 a = unpackHalf2x16( packed.r );
	vec2 b = unpackHalf2x16( packed.g );
	vec2 c = unpackHalf2x16( packed.b );
	first = vec3( a, b.x );
	second = vec3( b.y, c );
}

// The three groups' light of one texel.
struct SssGroupLight {
	vec3 first;
	vec3 second;
	vec3 third;
};

#if AXIS == 0
	layout( location = 0 ) out highp uvec4 sssGroupsOut0;
	layout( location = 1 ) out highp uvec4 sssGroupsOut1;

	// Writes the groups, premultiplied by `coverage` (see the header).
	void sssWriteGroups( const in SssGroupLight light, const in float coverage ) {
		vec3 a = light.first * coverage;
		vec3 b = light.second * coverage;
		vec3 c = light.third * coverage;
		sssGroupsOut0 = uvec4( packHalf2x16( vec2( a.r, b.r ) ), packHalf2x16( vec2( a.g, b.g ) ), packHalf2x16( vec2( a.b, b.b ) ), floatBitsToUint( coverage ) );
		sssGroupsOut1 = uvec4( packHalf2x16( c.rg ), packHalf2x16( vec2( c.b, coverage ) ), 0u, 0u );
	}
#else
	uniform highp usampler2D tGroups0; // the horizontal pass's groups (see the header)
	uniform highp usampler2D tGroups1;

	// A texel's groups with the coverage divided out; returns the coverage (0 off the mask, or when
	// a group is not finite).
	float sssGroupsAt( const in ivec2 texel, out SssGroupLight light ) {
		uvec4 packed = texelFetch( tGroups0, texel, 0 );
		float coverage = uintBitsToFloat( packed.a );
		vec2 r = unpackHalf2x16( packed.r );
		vec2 g = unpackHalf2x16( packed.g );
		vec2 b = unpackHalf2x16( packed.b );
		light.first = vec3( r.x, g.x, b.x );
		light.second = vec3( r.y, g.y, b.y );
		light.third = vec3( 0.0 );
		if ( groupCount > 2 ) {
			uvec2 third = texelFetch( tGroups1, texel, 0 ).rg;
			light.third = vec3( unpackHalf2x16( third.r ), unpackHalf2x16( third.g ).x );
		}
		if ( ! ( coverage > 0.0 ) || ! sssFinite( light.first + light.second + light.third ) ) {
			light = SssGroupLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
			return 0.0;
		}
		#if SSS_COVERAGE == 1
			light.first /= coverage;
			light.second /= coverage;
			light.third /= coverage;
		#endif
		return coverage;
	}

	// The tap rule (shaders/common/surfaceTap.glsl) for a texel of groups: its weight, and its
	// groups in `light` ('lerp': each moved towards the centre's by the farness).
	float sssGroupTapWeight( const in ivec2 texel, const in float expectedDepth, const in SssGroupLight centre, out SssGroupLight light ) {
		float coverage = sssGroupsAt( texel, light );
		if ( ! ( coverage > 0.0 ) ) return 0.0;
		float farness;
		float weight = sssTexelRule( texel, coverage, expectedDepth, farness );
		#if FOLLOW_SURFACE == FOLLOW_SURFACE_LERP
			light.first = mix( light.first, centre.first, farness );
			light.second = mix( light.second, centre.second, farness );
			light.third = mix( light.third, centre.third, farness );
		#endif
		return weight;
	}
#endif
