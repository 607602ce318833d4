	// The clear coat dims everything under it, the diffuse light included.
	#ifdef USE_CLEARCOAT
		sssDiffuse *= 1.0 - material.clearcoat * Fcc;
	#endif
