	// After clipping and alpha tests, so the depth matches the full draw that follows exactly.
	if ( sssDepthOnly ) {
		gl_FragColor = vec4( 0.0 );
		return;
	}
