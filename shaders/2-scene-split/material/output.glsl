	// Fog blends location 0 towards the fog colour; the diffuse light fades by the same factor so
	// that diffuse + location 0 equals three's own fogged result.
	#ifdef USE_FOG
		sssDiffuse *= 1.0 - fogFactor;
	#endif
	if ( sssDebugOutput == SSS_OUTPUT_TRANSMITTANCE ) sssDiffuse = sssTransmitted;
	if ( sssDebugOutput == SSS_OUTPUT_THICKNESS ) sssDiffuse = vec3( sssThicknessMm );
	// A non-finite value would spread through the blur: keep it out.
	if ( ! sssFinite( sssDiffuse ) ) sssDiffuse = vec3( 0.0 );
	sssDiffuseOutput = vec4( max( sssDiffuse, vec3( 0.0 ) ), sssDiffuseCarriesDepth ? sssCarriedDepth( vViewPosition.z ) : 1.0 );
	// b and a (several profiles only: the attachment is RG otherwise): the slot and its square, so
	// that after an MSAA resolve a pixel two profiles share shows its slots' spread.
	float sssSlotNumber = float( sssProfileSlot );
	sssSurfaceOutput = vec4( vViewPosition.z, sssWidthWorld * sssWidthScale, sssSlotNumber, sssSlotNumber * sssSlotNumber );
