// Reading the multi-target's surface (r: linear view depth, g: world units per profile mm) and
// diffuse light at a texel. Without SSS_COVERAGE they are read as stored. With SSS_COVERAGE (the
// multi-target was rendered with MSAA and resolved by averaging) a texel holds the average of its
// samples, and samples off subsurface surfaces hold 0: its diffuse alpha is the coverage c, and
// colour, depth and width are c times the covered samples' values. Dividing by c gives them back
// exactly where one surface meets the background or an ordinary material (silhouettes); where two
// subsurface surfaces share a pixel, their coverage-weighted mean. Needs `tSurface`, `tDiffuse`
// and shaders/common/finite.glsl, and PROFILE_COUNT (1: one profile, the b channel unread).
//
// SSS_LIGHT_CARRIES_DEPTH 1: the light read (`tDiffuse`) carries the depth in its alpha
// (shaders/common/carriedDepth.glsl): the multi-target's diffuse without MSAA, or the horizontal
// blur's output. A tap then fetches one texel, not two (light, surface). Its rgb
// has the coverage divided out; with SSS_COVERAGE the coverage comes from `tCoverage`'s alpha (the
// multi-target's diffuse): one number cannot hold both. Needs shaders/common/carriedDepth.glsl.

#if SSS_LIGHT_CARRIES_DEPTH == 1 && SSS_COVERAGE == 1
	uniform sampler2D tCoverage; // the multi-target's diffuse: its alpha is the coverage
#endif

// The coverage of a texel on the mask (SSS_COVERAGE only: without MSAA it is 1): the light's alpha,
// or tCoverage's where the light carries the depth.
float sssCoverageAt( const in ivec2 texel ) {
	#if SSS_LIGHT_CARRIES_DEPTH == 1 && SSS_COVERAGE == 1
		return texelFetch( tCoverage, texel, 0 ).a;
	#elif SSS_LIGHT_CARRIES_DEPTH == 1
		return 1.0;
	#else
		return texelFetch( tDiffuse, texel, 0 ).a;
	#endif
}

// Divides a premultiplied value by its coverage (a no-op without SSS_COVERAGE).
vec2 sssUncovered( const in vec2 value, const in float coverage ) {
	#if SSS_COVERAGE == 1
		return coverage > 0.0 ? value / coverage : vec2( 0.0 );
	#else
		return value;
	#endif
}

vec2 sssSurfaceAt( const in ivec2 texel ) {
	vec2 surface = texelFetch( tSurface, texel, 0 ).rg;
	#if SSS_COVERAGE == 1
		surface = sssUncovered( surface, sssCoverageAt( texel ) );
	#endif
	return surface;
}

// The pixel a surface pass shades.
struct SssCentre {
	vec3 colour;    // its diffuse light (0 if not finite), coverage divided out
	float coverage; // 0 off subsurface pixels (or NaN), 1 on them, the MSAA coverage between (the diffuse alpha, or tCoverage's with SSS_LIGHT_CARRIES_DEPTH)
	vec2 surface;   // linear view depth and world units per profile mm, coverage divided out
};

SssCentre sssCentreAt( const in ivec2 pixel ) {
	vec4 light = texelFetch( tDiffuse, pixel, 0 );
	SssCentre centre;
	centre.colour = sssFinite( light.rgb ) ? light.rgb : vec3( 0.0 );
	#if SSS_LIGHT_CARRIES_DEPTH == 1
		centre.coverage = sssCarriesSurface( light.a ) ? sssCoverageAt( pixel ) : 0.0;
	#else
		centre.coverage = light.a > 0.0 ? light.a : 0.0;
		#if SSS_COVERAGE == 1
			if ( centre.coverage > 0.0 ) centre.colour /= centre.coverage;
		#endif
	#endif
	centre.surface = sssUncovered( texelFetch( tSurface, pixel, 0 ).rg, centre.coverage );
	return centre;
}

// A surface pass's output: its colour premultiplied by the centre's coverage (1 without MSAA), as
// its input was, so the next pass and the compose read it the same way.
vec4 sssCovered( const in vec3 colour, const in float coverage ) {
	return vec4( colour * coverage, coverage );
}

#if PROFILE_COUNT > 1
	// Several profiles (src/profiles/profileSlots.js): the surface's b channel holds the material's
	// slot, premultiplied by the coverage like depth and width, so a pixel two profiles share (MSAA)
	// holds their coverage-weighted mean slot. The pass's main() sets `sssSlot`, the centre's: its
	// mean slot rounded to the nearest (a shared pixel is blurred with its majority's profile).
	int sssSlot;

	// A texel is on a slot when its mean slot is within SSS_SLOT_TOLERANCE of it (SurfacePass: half
	// the smallest step a resolve of MAX_MULTISAMPLING samples makes between two slots).

	float sssSlotAt( const in ivec2 texel, const in float coverage ) {
		float slot = texelFetch( tSurface, texel, 0 ).b;
		#if SSS_COVERAGE == 1
			slot = coverage > 0.0 ? slot / coverage : 0.0;
		#endif
		return slot;
	}

	int sssNearestSlot( const in ivec2 pixel, const in float coverage ) {
		return clamp( int( floor( sssSlotAt( pixel, coverage ) + 0.5 ) ), 0, PROFILE_COUNT - 1 );
	}

	// Whether a texel is on the centre's profile: 1 on it; 0 on another, and 0 for a texel two
	// profiles share (its light is theirs mixed: it would carry one's light into the other). The
	// surface's a holds the slot's square, so a shared texel's spread a − b² is above
	// SSS_SLOT_SPREAD_TOLERANCE even where its mean slot is a third one's (0 and 2 average to 1).
	// `slotMoments`: the texel's surface .ba (mean slot, mean slot², premultiplied by `coverage`).
	float sssOnProfile( const in vec2 slotMoments, const in float coverage ) {
		vec2 slot = slotMoments;
		#if SSS_COVERAGE == 1
			slot = coverage > 0.0 ? slot / coverage : vec2( 0.0 );
		#endif
		bool single = slot.y - slot.x * slot.x < SSS_SLOT_SPREAD_TOLERANCE;
		return single && abs( slot.x - float( sssSlot ) ) < SSS_SLOT_TOLERANCE ? 1.0 : 0.0;
	}
#endif
