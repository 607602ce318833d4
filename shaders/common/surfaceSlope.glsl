// The surface's depth slope at a pixel along one screen axis (world units of depth per pixel), as
// the blur and the dense reference estimate it for their grazing-angle correction (FORESHORTEN),
// with the numbers of src/3-blur/samplingModel.js:
// - both neighbours on the surface (in the image, with a width) and their slopes within
//   SSS_PLANE_SLOPE_AGREEMENT of each other: one plane, however steep (up to SSS_MAX_PLANE_SLOPE
//   world units of depth per world unit across): the central difference;
// - otherwise each neighbour counts if it is on the surface and no steeper than SSS_MAX_SLOPE
//   (a steeper one is another surface: a depth edge): the central difference of both, the one
//   that counts, or 0 when neither does.
// Needs `resolution` and `viewOrigin` (vec2, pixels: the view's size and first pixel; neighbours
// outside the view are not on the surface) and shaders/common/surfaceSample.glsl.

float sssSurfaceSlope( const in ivec2 pixel, const in int axis, const in vec2 surface, const in float pixelWorld ) {
	ivec2 before = pixel;
	ivec2 after = pixel;
	before[ axis ] = max( pixel[ axis ] - 1, int( viewOrigin[ axis ] ) );
	after[ axis ] = min( pixel[ axis ] + 1, int( viewOrigin[ axis ] + resolution[ axis ] ) - 1 );
	vec2 surfaceBefore = sssSurfaceAt( before );
	vec2 surfaceAfter = sssSurfaceAt( after );
	float slopeBefore = surface.r - surfaceBefore.r;
	float slopeAfter = surfaceAfter.r - surface.r;
	bool onBefore = surfaceBefore.g > 0.0 && before != pixel;
	bool onAfter = surfaceAfter.g > 0.0 && after != pixel;
	float steeper = max( abs( slopeBefore ), abs( slopeAfter ) );
	if ( onBefore && onAfter && abs( slopeAfter - slopeBefore ) <= SSS_PLANE_SLOPE_AGREEMENT * steeper && steeper <= SSS_MAX_PLANE_SLOPE * pixelWorld ) {
		return 0.5 * ( slopeBefore + slopeAfter ); // one plane
	}
	bool useBefore = onBefore && abs( slopeBefore ) <= SSS_MAX_SLOPE * pixelWorld;
	bool useAfter = onAfter && abs( slopeAfter ) <= SSS_MAX_SLOPE * pixelWorld;
	return useBefore && useAfter ? 0.5 * ( slopeBefore + slopeAfter ) : useBefore ? slopeBefore : useAfter ? slopeAfter : 0.0;
}
