	// Light arriving through the object from behind (Jimenez et al. 2010), added to the direct
	// diffuse light before the blur. Three's own attenuation functions keep it consistent with the
	// light's front-side contribution; the shadow does not apply (the light went through).
	// A uniform switch, not a define: one program serves every pipeline drawing the material.
	vec3 sssTransmitted = vec3( 0.0 ); // kept for the debug views
	float sssThicknessMm = 0.0;
	if ( sssTransmits ) {
		vec3 sssPosition = - vViewPosition;
		vec3 sssToLight = sssLightDirectionView;
		float sssAttenuation = 1.0;
		if ( sssLightType == SSS_LIGHT_TYPE_SPOT ) {
			vec3 sssLightVector = sssLightPositionView - sssPosition;
			float sssLightDistance = length( sssLightVector );
			sssToLight = sssLightVector / sssLightDistance;
			sssAttenuation = getSpotAttenuation( sssSpotConeCos, sssSpotPenumbraCos, dot( sssToLight, sssLightDirectionView ) )
				* getDistanceAttenuation( sssLightDistance, sssLightCutoffDistance, sssLightDecay );
		}
		// Wrap lighting on the back side, where the light leaves: saturate(0.3 + dot(-N, L)) (REFERENCE
		// §5; the light's share that entered, the entry cosine, comes with the thickness from the
		// map: transmittance.glsl), for light that
		// comes from behind the point as the camera sees it (view space: +z points to the camera).
		// The constants are src/2-scene-split/transmittanceModel.js's TRANSMITTED_LIGHT, as defines.
		// Light from the camera's side reaches what the camera sees through its lit, visible
		// neighbourhood, which the blur already spreads: counted again it made a bright band
		// along a front light's terminator.
		float sssWrap = saturate( SSS_WRAP_OFFSET + dot( - nonPerturbedNormal, sssToLight ) ) * smoothstep( 0.0, SSS_FROM_BEHIND_RANGE, - sssToLight.z );
		// Most of a front-lit surface gets none (sssWrap is 0 wherever the light is on the camera's
		// side of the point): the map and the profile are read only where some light comes through.
		float sssWeight = sssAttenuation * sssWrap;
		if ( sssWeight > 0.0 ) {
			sssTransmitted = sssLightColor * sssWeight
				* sssTransmittance( sssPosition, nonPerturbedNormal ) * BRDF_Lambert( material.diffuseColor );
			// A degenerate light set-up must not turn the whole material NaN (outside the pipeline too).
			if ( ! sssFinite( sssTransmitted ) ) sssTransmitted = vec3( 0.0 );
			reflectedLight.directDiffuse += sssTransmitted;
		}
		if ( sssDebugOutput == SSS_OUTPUT_THICKNESS ) sssThicknessMm = sssThicknessWorld( sssPosition, nonPerturbedNormal ) * sssThicknessToProfileMm;
	}
