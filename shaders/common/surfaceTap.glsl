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

float sssTapWeight( const in ivec2 texel, const in float expectedDepth, const in vec3 centre, out vec3 colour ) {
	vec4 light = texelFetch( tDiffuse, texel, 0 );
	colour = light.rgb;
	if ( ! ( light.a > 0.0 ) || ! sssFinite( colour ) ) {
		colour = vec3( 0.0 );
		return 0.0;
	}
	float weight = 1.0;
	#if SSS_COVERAGE == 1
		colour /= light.a;
		weight = light.a;
	#endif
	#if PROFILE_COUNT > 1
		// Another profile's texel is off this profile's mask in every followSurface mode: where a
		// marble hand touches skin their depths agree, so the depth rule cannot part them.
		weight *= sssOnProfile( texel, light.a );
		if ( weight == 0.0 ) return 0.0; // no depth to fetch for a texel that weighs nothing
	#endif
	#if FOLLOW_SURFACE != FOLLOW_SURFACE_OFF
		float farness = clamp( abs( sssUncovered( texelFetch( tSurface, texel, 0 ).rg, light.a ).r - expectedDepth ) * depthFalloff, 0.0, 1.0 );
		#if FOLLOW_SURFACE == FOLLOW_SURFACE_DROP
			weight *= 1.0 - farness;
		#else
			colour = mix( colour, centre, farness );
		#endif
	#endif
	return weight;
}
