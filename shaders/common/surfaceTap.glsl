// The rule every tap of the blur and the dense reference follows (the sampling model,
// shaders/3-blur/subsurfaceBlur.frag.glsl): a texel off the mask (the diffuse light's alpha: 0 off
// subsurface pixels, whatever their width) or with a non-finite colour weighs 0; in 'drop' mode
// (FOLLOW_SURFACE_DROP) it weighs 1 - farness, farness = clamp(|depth - expectedDepth| /
// threshold, 0, 1), so no light crosses a depth edge (Unreal, HDRP); in 'lerp' mode its colour
// moves towards the centre's by the farness (Jimenez 2012). `expectedDepth` is the depth the
// centre's plane predicts at the texel. Needs `tDiffuse`, `tSurface`, `depthFalloff` (1 / threshold)
// and shaders/common/finite.glsl and surfaceSample.glsl.
//
// With SSS_COVERAGE (the multi-target was resolved from MSAA) a texel's alpha is the fraction of
// its samples on subsurface surfaces and its colour, depth and width are premultiplied by it: the
// texel weighs its coverage, with its colour and depth divided back out.
//
// With several profiles (PROFILE_COUNT > 1) a texel of another profile weighs 0 too, like one off
// the mask (surfaceSample.glsl's sssOnProfile).

// The depth rule alone, for a texel at `depth` (linear view depth, coverage divided out): its
// weight ('drop': 1 - farness; 1 otherwise) and the farness 'lerp' moves its colour by.
float sssDepthRule( const in float depth, const in float expectedDepth, out float farness ) {
	farness = 0.0;
	#if FOLLOW_SURFACE != FOLLOW_SURFACE_OFF
		float far = clamp( abs( depth - expectedDepth ) * depthFalloff, 0.0, 1.0 );
		#if FOLLOW_SURFACE == FOLLOW_SURFACE_DROP
			return 1.0 - far;
		#else
			farness = far;
		#endif
	#endif
	return 1.0;
}

// The rule's weight of a texel of coverage `coverage` (its light's alpha) by the mask, the profile
// and the depth, whatever the light is stored as (the diffuse texture, or the isotropic blur's
// groups, shaders/3-blur/kernelGroups.glsl); `farness` is what 'lerp' moves its colour by (0 in
// the other modes).
float sssTexelRule( const in ivec2 texel, const in float coverage, const in float expectedDepth, out float farness ) {
	farness = 0.0;
	float weight = 1.0;
	#if SSS_COVERAGE == 1
		weight = coverage;
	#endif
	#if PROFILE_COUNT > 1
		// Another profile's texel is off this profile's mask in every followSurface mode: where a
		// marble hand touches skin their depths agree, so the depth rule cannot part them.
		vec4 surfaceTexel = texelFetch( tSurface, texel, 0 ); // one fetch for the slot and the depth
		weight *= sssOnProfile( surfaceTexel.ba, coverage );
		if ( weight == 0.0 ) return 0.0;
	#endif
	#if FOLLOW_SURFACE != FOLLOW_SURFACE_OFF
		#if PROFILE_COUNT == 1
			vec2 surfaceTexel = texelFetch( tSurface, texel, 0 ).rg;
		#endif
		weight *= sssDepthRule( sssUncovered( surfaceTexel.rg, coverage ).r, expectedDepth, farness );
	#endif
	return weight;
}

// The rule's weight of the light texel `texel` (tDiffuse) for a centre expecting `expectedDepth`,
// its colour (coverage divided out, moved by 'lerp') in `colour`. With SSS_LIGHT_CARRIES_DEPTH the light
// carries its depth (one fetch; with MSAA a second for the coverage; several profiles still read
// the surface for the slot).
float sssTapWeight( const in ivec2 texel, const in float expectedDepth, const in vec3 centre, out vec3 colour ) {
	vec4 light = texelFetch( tDiffuse, texel, 0 );
	colour = light.rgb;
	#if SSS_LIGHT_CARRIES_DEPTH == 1
		// The light carries the depth (surfaceSample.glsl): one fetch, and with MSAA the coverage's.
		bool onMask = sssCarriesSurface( light.a );
	#else
		bool onMask = light.a > 0.0;
	#endif
	if ( ! onMask || ! sssFinite( colour ) ) {
		colour = vec3( 0.0 );
		return 0.0;
	}
	float farness;
	#if SSS_LIGHT_CARRIES_DEPTH == 1
		float coverage = sssCoverageAt( texel );
		#if PROFILE_COUNT == 1
			float weight = sssDepthRule( light.a, expectedDepth, farness );
			#if SSS_COVERAGE == 1
				weight *= coverage;
			#endif
		#else
			float weight = sssTexelRule( texel, coverage, expectedDepth, farness );
		#endif
	#else
		#if SSS_COVERAGE == 1
			colour /= light.a;
		#endif
		float weight = sssTexelRule( texel, light.a, expectedDepth, farness );
	#endif
	#if FOLLOW_SURFACE == FOLLOW_SURFACE_LERP
		colour = mix( colour, centre, farness );
	#endif
	return weight;
}
