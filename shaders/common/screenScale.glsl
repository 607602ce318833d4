// How large a profile millimetre is on screen: src/support/screenScale.js's formula (its header
// derives it), per screen axis. Needs the uniforms `perspective` (false for an orthographic
// camera), `projectionScale` (projectionMatrix.elements[0], [5]) and `resolution` (pixels).
// `surface` is the multi-target's surface texel: r linear view depth, g world units per profile mm.

float sssViewDepth( const in vec2 surface ) {
	return perspective ? surface.r : 1.0;
}

// Pixels one profile millimetre spans along x and y.
vec2 sssPixelsPerMm( const in vec2 surface ) {
	return surface.g * projectionScale / ( 2.0 * sssViewDepth( surface ) ) * resolution;
}

// World units one pixel spans across the view at this depth, along x and y.
vec2 sssPixelWorld( const in vec2 surface ) {
	return 2.0 * sssViewDepth( surface ) / ( projectionScale * resolution );
}
