	// Light arriving through the object from behind (Jimenez et al. 2010), added to the direct
	// diffuse light before the blur. Three's own attenuation functions keep it consistent with the
	// light's front-side contribution; the shadow does not apply (the light went through).
	vec3 sssTransmitted = vec3( 0.0 ); // kept for the debug views
	float sssThicknessMm = 0.0;
	#ifdef SSS_TRANSMITTANCE
	{
		vec3 sssPosition = - vViewPosition;
		#if SSS_LIGHT_TYPE == SSS_LIGHT_TYPE_DIRECTIONAL
			vec3 sssToLight = sssLightDirectionView;
			float sssAttenuation = 1.0;
		#else // SSS_LIGHT_TYPE_SPOT
			vec3 sssLightVector = sssLightPositionView - sssPosition;
			float sssLightDistance = length( sssLightVector );
			vec3 sssToLight = sssLightVector / sssLightDistance;
			float sssAttenuation = getSpotAttenuation( sssSpotConeCos, sssSpotPenumbraCos, dot( sssToLight, sssLightDirectionView ) )
				* getDistanceAttenuation( sssLightDistance, sssLightCutoffDistance, sssLightDecay );
		#endif
		// Wrap lighting on the back side: saturate(0.3 + dot(-N, L)) (REFERENCE §5).
		float sssWrap = saturate( 0.3 + dot( - nonPerturbedNormal, sssToLight ) );
		float sssThickness = sssThicknessWorld( sssPosition, nonPerturbedNormal );
		sssThicknessMm = sssThickness * sssThicknessToProfileMm;
		sssTransmitted = sssLightColor * ( sssAttenuation * sssWrap )
			* sssTransmittanceProfile( sssThickness ) * BRDF_Lambert( material.diffuseColor );
		// A degenerate light set-up must not turn the whole material NaN (outside the pipeline too).
		if ( ! sssFinite( sssTransmitted ) ) sssTransmitted = vec3( 0.0 );
		reflectedLight.directDiffuse += sssTransmitted;
	}
	#endif
