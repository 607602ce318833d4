	// The scene split's first call: the object is there only to cast shadows (three renders the shadow maps in that call,
	// with depth materials of its own), so its triangles are put beyond the far plane and clipped
	// whole: no fragment is rasterised, and the split call draws it once. First in main(): the
	// vertex's shading would be thrown away.
	if ( sssHidden ) {
		gl_Position = vec4( 0.0, 0.0, 2.0, 1.0 );
		return;
	}
