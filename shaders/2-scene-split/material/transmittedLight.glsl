	// Light arriving through the object from behind (Jimenez et al. 2010), from each light
	// (sssTransmittedFrom, pars.glsl), added to the direct diffuse light before the blur.
	// Uniform switches, not defines: one program serves every pipeline drawing the material.
	vec3 sssTransmitted = vec3( 0.0 ); // kept for the debug views
	float sssThicknessMm = 0.0;
	if ( sssTransmits ) {
		vec3 sssPosition = - vViewPosition;
		vec3 sssFace = sssFaceNormal( sssPosition ); // here, in uniform control flow (derivatives)
		// One call per light the material's pipelines use (SSS_LIGHT_SLOTS, 1..SSS_MAX_LIGHTS: the
		// program grows with them, so one light compiles one; a sampler array takes constant indices).
		sssTransmitted = sssTransmittedFrom( 0, sssLightDepthMaps[ 0 ], sssPosition, nonPerturbedNormal, sssFace );
#if SSS_LIGHT_SLOTS > 1
		sssTransmitted += sssTransmittedFrom( 1, sssLightDepthMaps[ 1 ], sssPosition, nonPerturbedNormal, sssFace );
#endif
#if SSS_LIGHT_SLOTS > 2
		sssTransmitted += sssTransmittedFrom( 2, sssLightDepthMaps[ 2 ], sssPosition, nonPerturbedNormal, sssFace );
#endif
#if SSS_LIGHT_SLOTS > 3
		sssTransmitted += sssTransmittedFrom( 3, sssLightDepthMaps[ 3 ], sssPosition, nonPerturbedNormal, sssFace );
#endif
		sssTransmitted *= BRDF_Lambert( material.diffuseColor );
		// A degenerate light set-up must not turn the whole material NaN (outside the pipeline too).
		if ( ! sssFinite( sssTransmitted ) ) sssTransmitted = vec3( 0.0 );
		reflectedLight.directDiffuse += sssTransmitted;
		// The thickness view shows the first light's (not from a point light's six faces: none).
		if ( sssDebugOutput == SSS_OUTPUT_THICKNESS && ! sssLightCubes[ 0 ] ) {
			sssThicknessMm = sssThicknessWorldFrom( sssLightDepthMaps[ 0 ], sssViewToLightViews[ 0 ], sssLightProjections[ 0 ], sssPosition, nonPerturbedNormal ) * sssThicknessToProfileMm;
		}
	}
