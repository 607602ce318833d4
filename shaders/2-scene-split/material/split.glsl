	// Diffuse light goes to its own target to be blurred; location 0 keeps the rest.
	vec3 sssDiffuse = totalDiffuse;
	if ( sssSplit ) totalDiffuse = vec3( 0.0 );
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
