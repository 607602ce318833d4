// A light texture that carries the surface's depth in its alpha (the diffuse attachment without
// MSAA, src/2-scene-split/subsurfaceTarget.js; the horizontal blur's output): on the mask the
// alpha is the linear view depth (world units, the coverage divided out), off it +0.0. A depth of
// exactly 0 (an orthographic camera sees behind its plane) is written as -0.0, so the mask is "the
// alpha's bits are not +0.0's" whatever the depth's sign. The same test reads an alpha that is
// the coverage (0 off the mask, up to 1 on it) the same way, so the compose needs no define.

// Whether a texel is on the mask, by its alpha (a carried depth, or a coverage).
bool sssCarriesSurface( const in float alpha ) {
	return floatBitsToUint( alpha ) != 0u;
}

// The alpha that carries `depth` on the mask: -0.0 for a depth of 0, so it is not read as off it.
float sssCarriedDepth( const in float depth ) {
	return floatBitsToUint( depth ) == 0u ? uintBitsToFloat( 0x80000000u ) : depth;
}
