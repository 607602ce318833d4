// The surface's depth slope at a pixel along one screen axis (world units of depth per pixel), as
// the blur and the dense reference estimate it for their grazing-angle correction (FORESHORTEN):
// central difference of the two neighbours; one-sided when a neighbour is off the image, has no
// width (g = 0) or is steeper than SSS_MAX_SLOPE world units of depth per world unit across
// (another surface: a depth edge; the number is MAX_SLOPE in src/3-blur/samplingModel.js); 0 when
// both are. Needs `resolution` (vec2, pixels) and shaders/common/surfaceSample.glsl.

float sssSurfaceSlope( const in ivec2 pixel, const in int axis, const in vec2 surface, const in float pixelWorld ) {
	ivec2 before = pixel;
	ivec2 after = pixel;
	before[ axis ] = max( pixel[ axis ] - 1, 0 );
	after[ axis ] = min( pixel[ axis ] + 1, int( resolution[ axis ] ) - 1 );
	vec2 surfaceBefore = sssSurfaceAt( before );
	vec2 surfaceAfter = sssSurfaceAt( after );
	float slopeBefore = surface.r - surfaceBefore.r;
	float slopeAfter = surfaceAfter.r - surface.r;
	bool useBefore = surfaceBefore.g > 0.0 && before != pixel && abs( slopeBefore ) <= SSS_MAX_SLOPE * pixelWorld;
	bool useAfter = surfaceAfter.g > 0.0 && after != pixel && abs( slopeAfter ) <= SSS_MAX_SLOPE * pixelWorld;
	return useBefore && useAfter ? 0.5 * ( slopeBefore + slopeAfter ) : useBefore ? slopeBefore : useAfter ? slopeAfter : 0.0;
}
