// The surface's depth slope at a pixel along one screen axis (world units of depth per pixel), as
// the blur and the dense reference estimate it for their grazing-angle correction (FORESHORTEN),
// with the numbers of src/3-blur/samplingModel.js (the sampling model's item 3):
// - both neighbours on the surface (in the image, with a width) and their slopes within
//   SSS_PLANE_SLOPE_AGREEMENT of the steeper, however steep up to SSS_MAX_PLANE_SLOPE world units
//   of depth per world unit across: one plane, the central difference;
// - otherwise each neighbour on the surface counts unless it is steeper than SSS_MAX_SLOPE (another
//   surface: a depth edge): the mean of the one-sided slopes that count, 0 when none does.
// Each of the three limits fades linearly from limit / SSS_SLOPE_FADE to the limit (sssFadeBelow)
// rather than switching, so the slope moves continuously with the depths: a neighbour's weight,
// and the plane's share of the result against the one-sided rule's.
// Needs `resolution` and `viewOrigin` (vec2, pixels: the view's size and first pixel; neighbours
// outside the view are not on the surface) and shaders/common/surfaceSample.glsl.

// 1 up to limit / SSS_SLOPE_FADE, 0 from the limit, linear between (a limit of 0: 1 at 0 only).
float sssFadeBelow( const in float value, const in float limit ) {
	float band = limit * ( 1.0 - 1.0 / SSS_SLOPE_FADE );
	return band > 0.0 ? clamp( ( limit - value ) / band, 0.0, 1.0 ) : ( value > 0.0 ? 0.0 : 1.0 );
}

float sssSurfaceSlope( const in ivec2 pixel, const in int axis, const in vec2 surface, const in float pixelWorld ) {
	ivec2 before = pixel;
	ivec2 after = pixel;
	before[ axis ] = max( pixel[ axis ] - 1, int( viewOrigin[ axis ] ) );
	after[ axis ] = min( pixel[ axis ] + 1, int( viewOrigin[ axis ] + resolution[ axis ] ) - 1 );
	vec2 surfaceBefore = sssSurfaceAt( before );
	vec2 surfaceAfter = sssSurfaceAt( after );
	float slopeBefore = surface.r - surfaceBefore.r;
	float slopeAfter = surfaceAfter.r - surface.r;
	float onBefore = surfaceBefore.g > 0.0 && before != pixel ? 1.0 : 0.0;
	float onAfter = surfaceAfter.g > 0.0 && after != pixel ? 1.0 : 0.0;
	float steeper = max( abs( slopeBefore ), abs( slopeAfter ) );
	float plane = onBefore * onAfter * sssFadeBelow( abs( slopeAfter - slopeBefore ), SSS_PLANE_SLOPE_AGREEMENT * steeper ) * sssFadeBelow( steeper, SSS_MAX_PLANE_SLOPE * pixelWorld );
	float weightBefore = onBefore * sssFadeBelow( abs( slopeBefore ), SSS_MAX_SLOPE * pixelWorld );
	float weightAfter = onAfter * sssFadeBelow( abs( slopeAfter ), SSS_MAX_SLOPE * pixelWorld );
	// Their mean where both count; below a sum of 1 (one fading out, the other gone) their weighted
	// sum, which fades to 0 with them.
	float oneSided = ( weightBefore * slopeBefore + weightAfter * slopeAfter ) / max( weightBefore + weightAfter, 1.0 );
	return mix( oneSided, 0.5 * ( slopeBefore + slopeAfter ), plane );
}
