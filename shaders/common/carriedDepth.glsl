// A light texture that carries the surface's depth in its alpha (the diffuse attachment without
// MSAA, src/2-scene-split/subsurfaceTarget.js; the horizontal blur's output): on the mask the
// alpha is the linear view depth (world units, the coverage divided out), off it 0. A depth of
// exactly 0 (an orthographic camera sees objects on its own plane, and behind it: negative
// depths) is written as SSS_DEPTH_ZERO, a normal float far below any depth difference the tap
// rule resolves (it compares depths to a threshold of millimetres), so the mask is "alpha != 0"
// whatever the depth's sign. The same test reads an alpha that is the coverage (0 off the mask,
// up to 1 on it), so the compose needs no define.

#define SSS_DEPTH_ZERO 1e-30 // world units; normal (above 1.2e-38), so no flush to zero

// Whether a texel is on the mask, by its alpha (a carried depth, or a coverage).
bool sssCarriesSurface( const in float alpha ) {
	return alpha != 0.0;
}

// The alpha that carries `depth` on the mask: SSS_DEPTH_ZERO for a depth of 0, so it is not read as off it.
float sssCarriedDepth( const in float depth ) {
	return depth == 0.0 ? SSS_DEPTH_ZERO : depth;
}
