// The isotropic blur's groups (src/3-blur/kernelGroups.js, issue 20). A horizontal then vertical
// blur with one kernel is exact along the screen axes only (off them its transfer is
// A(f cos θ)·A(f sin θ), not the radial profile's); a 2D Gaussian is exactly separable, so the
// profile's Gaussians are blurred in up to SSS_GROUPS groups, each separably, and the vertical pass
// sums them: only the cross terms inside a group are left. Each footprint's marginal energy (the
// exact one, from the ProfileLookup) is split between the groups by the fractions of
// KernelGroupTable (computed at the footprint table row's scale from the groups' Gaussians); the
// taps and their fetches are the one-kernel blur's.
//
// Between the passes (BlurStage's group target, two RGBA32UI attachments; halves are the precision
// of the HalfFloatType target they replace), every value premultiplied by the coverage as the
// multi-target's diffuse is:
//   tGroups0: rgb = packHalf2x16(group 1, group 2) of that channel, a = the coverage's bits;
//   tGroups1: rgb = packHalf2x16(group 3, group 4) of that channel (read only when groupCount > 2).
// `groupCount` (1..SSS_GROUPS, per frame) says how many hold light.

uniform int groupCount;                                   // the frame's groups, 1..SSS_GROUPS
uniform vec3 groupEnergies[ SSS_GROUPS * PROFILE_COUNT ]; // slot p's group g: its share of the energy, per channel, at [p * SSS_GROUPS + g]
uniform highp usampler2D tGroupFractions;                 // KernelGroupTable.texture: column 0 the centre, column j + 1 footprint j

// The groups' light of one texel (or their weights, or sums).
struct SssGroupLight {
	vec3 group[ SSS_GROUPS ];
};

SssGroupLight sssNoGroups() {
	SssGroupLight none;
	for ( int g = 0; g < SSS_GROUPS; g ++ ) none.group[ g ] = vec3( 0.0 );
	return none;
}

// A footprint's energy `weight` split between the frame's groups: groups 1..3's RGB fractions are
// 10-bit unorms in the table texel's r, g, b (KernelGroupTable), the last group takes the rest, so
// the parts sum to `weight` exactly. `column` 0 is the centre, j + 1 footprint j, of row `row`.
SssGroupLight sssSplit( const in vec3 weight, const in int column, const in int row ) {
	uvec3 packed = texelFetch( tGroupFractions, ivec2( column, row ), 0 ).rgb;
	SssGroupLight parts = sssNoGroups();
	vec3 left = weight;
	for ( int g = 0; g < SSS_GROUPS - 1; g ++ ) {
		if ( g + 1 >= groupCount ) break;
		vec3 fraction = vec3( ( uvec3( packed[ g ] ) >> uvec3( 0, 10, 20 ) ) & 1023u ) / 1023.0;
		parts.group[ g ] = min( weight * fraction, left );
		left -= parts.group[ g ];
	}
	parts.group[ groupCount - 1 ] = left;
	return parts;
}

#if AXIS == 0
	layout( location = 0 ) out highp uvec4 sssGroupsOut0;
	layout( location = 1 ) out highp uvec4 sssGroupsOut1;

	// Writes the groups, premultiplied by `coverage` (see the header).
	void sssWriteGroups( const in SssGroupLight light, const in float coverage ) {
		vec3 a = light.group[ 0 ] * coverage;
		vec3 b = light.group[ 1 ] * coverage;
		vec3 c = light.group[ 2 ] * coverage;
		vec3 d = light.group[ 3 ] * coverage;
		sssGroupsOut0 = uvec4( packHalf2x16( vec2( a.r, b.r ) ), packHalf2x16( vec2( a.g, b.g ) ), packHalf2x16( vec2( a.b, b.b ) ), floatBitsToUint( coverage ) );
		sssGroupsOut1 = uvec4( packHalf2x16( vec2( c.r, d.r ) ), packHalf2x16( vec2( c.g, d.g ) ), packHalf2x16( vec2( c.b, d.b ) ), 0u );
	}
#else
	uniform highp usampler2D tGroups0; // the horizontal pass's groups (see the header)
	uniform highp usampler2D tGroups1;

	// A texel's groups with the coverage divided out; returns the coverage (0 off the mask, or when
	// a group is not finite).
	float sssGroupsAt( const in ivec2 texel, out SssGroupLight light ) {
		uvec4 packed = texelFetch( tGroups0, texel, 0 );
		float coverage = uintBitsToFloat( packed.a );
		light = sssNoGroups();
		vec2 r = unpackHalf2x16( packed.r );
		vec2 g = unpackHalf2x16( packed.g );
		vec2 b = unpackHalf2x16( packed.b );
		light.group[ 0 ] = vec3( r.x, g.x, b.x );
		light.group[ 1 ] = vec3( r.y, g.y, b.y );
		vec3 sum = light.group[ 0 ] + light.group[ 1 ];
		if ( groupCount > 2 ) {
			uvec3 more = texelFetch( tGroups1, texel, 0 ).rgb;
			r = unpackHalf2x16( more.r );
			g = unpackHalf2x16( more.g );
			b = unpackHalf2x16( more.b );
			light.group[ 2 ] = vec3( r.x, g.x, b.x );
			light.group[ 3 ] = vec3( r.y, g.y, b.y );
			sum += light.group[ 2 ] + light.group[ 3 ];
		}
		if ( ! ( coverage > 0.0 ) || ! sssFinite( sum ) ) {
			light = sssNoGroups();
			return 0.0;
		}
		#if SSS_COVERAGE == 1
			for ( int k = 0; k < SSS_GROUPS; k ++ ) light.group[ k ] /= coverage;
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
			for ( int k = 0; k < SSS_GROUPS; k ++ ) light.group[ k ] = mix( light.group[ k ], centre.group[ k ], farness );
		#endif
		return weight;
	}
#endif
