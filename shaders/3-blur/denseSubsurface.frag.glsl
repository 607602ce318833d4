// The dense 2D reference (validation and the speed-accuracy bench, not production): every pixel
// whose centre lies within the radius holding `coverage` of the profile's energy contributes its
// diffuse light, weighted by the profile's exact energy over that pixel's square (from the
// QuadrantEnergyLookup: exact however narrow the profile is against a pixel). Same units, mask and
// depth rules as the separable blur (shaders/3-blur/subsurfaceBlur.frag.glsl); without FORESHORTEN,
// test/oracle/convolution.js's denseConvolutionOracle computes the same in float64.
// Defines (src/3-blur/DenseSubsurfacePass.js): FOLLOW_SURFACE (FOLLOW_SURFACE_OFF, _DROP, _LERP),
// FORESHORTEN (0 or 1), SSS_MAX_SLOPE, SSS_COVERAGE (0 or 1: MSAA-resolved inputs,
// shaders/common/surfaceSample.glsl).
//
// Per pixel c: pixels per mm along x and y, s = shaders/common/screenScale.glsl's
// widthWorld * (P0, P5) / (2 * depth) * (width, height). With FORESHORTEN, each axis as the blur does it: s is
// multiplied by cos(tilt) = 1 / sqrt(1 + (slope / pixelWorld)^2) of the surface along that axis
// (shaders/common/surfaceSlope.glsl), and the depth rule compares each pixel with the plane through c,
// depth + slopeX * di + slopeY * dj (the cross term of a diagonal tilt is left out, as the
// separable blur must). Offsets (di, dj) with (di / s.x)^2 + (dj / s.y)^2 <= radius^2 count with
// E(di, dj) = the energy over [di - 1/2, di + 1/2] / s.x × [dj - 1/2, dj + 1/2] / s.y mm, times the
// tap rule's weight (shaders/common/surfaceTap.glsl: 0 off the mask, 1 - farness in 'drop' mode); each
// channel is renormalised by the weights used. E is the same at (±di, ±dj): it is computed once per
// quadrant offset, from two new table reads (the left edge is carried along the row).

uniform sampler2D tDiffuse;  // the multi-target's diffuse light, linear HDR; alpha: the mask
uniform sampler2D tSurface;  // the multi-target's surface: r linear view depth (world units), g world units per profile mm
uniform sampler2D tQuadrant; // QuadrantEnergyLookup.texture
uniform float quadrantRangeMm; // QuadrantEnergyLookup.rangeMm
uniform float radiusMm;        // the radius holding `coverage` of the energy (widest channel)
uniform vec2 projectionScale;  // camera.projectionMatrix.elements[0], [5]
uniform vec2 resolution;       // the view's pixels: the frame, or an ArrayCamera view's viewport
uniform vec2 viewOrigin;       // the view's first pixel (0, 0 for the frame)
uniform float depthFalloff;    // 1 / depth threshold (world units)
uniform bool perspective;      // false for an orthographic camera
uniform int maxRadiusPx;       // bound on the loops (the bench checks the radius stays below it)

#include "common/finite.glsl"
#include "common/carriedDepth.glsl"
#include "common/screenScale.glsl"
#include "common/surfaceSample.glsl"
#include "common/surfaceSlope.glsl"
#include "common/surfaceTap.glsl"
#include "common/quadrantEnergy.glsl"

varying vec2 vUv;

// Adds the pixel at `offset` from the centre with profile energy `energy` to the sums; its depth
// is compared with `expectedDepth`, the centre's plane there.
void addPixel( const in ivec2 pixel, const in ivec2 offset, const in vec3 energy, const in float expectedDepth, const in vec3 centre, inout vec3 sum, inout vec3 weightSum ) {
	ivec2 texel = pixel + offset;
	ivec2 inView = texel - ivec2( viewOrigin );
	if ( any( lessThan( inView, ivec2( 0 ) ) ) || any( greaterThanEqual( inView, ivec2( resolution ) ) ) ) return;
	vec3 colour;
	float keep = sssTapWeight( texel, expectedDepth, centre, colour );
	sum += energy * keep * colour;
	weightSum += energy * keep;
}

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	SssCentre pixelCentre = sssCentreAt( pixel );
	vec3 centre = pixelCentre.colour;
	if ( ! ( pixelCentre.coverage > 0.0 ) ) {
		gl_FragColor = vec4( centre, 0.0 ); // not subsurface: as it was, like the blur
		return;
	}
	vec2 surface = pixelCentre.surface;
	if ( ! ( surface.g > 0.0 ) ) {
		gl_FragColor = sssCovered( centre, pixelCentre.coverage ); // no width (widthScale 0): no scattering
		return;
	}

	vec2 pxPerMm = sssPixelsPerMm( surface );
	vec2 slope = vec2( 0.0 ); // depth change per pixel along x and y, world units
	#if FORESHORTEN == 1
		vec2 pixelWorld = sssPixelWorld( surface ); // world units per pixel across
		slope = vec2( sssSurfaceSlope( pixel, 0, surface, pixelWorld.x ), sssSurfaceSlope( pixel, 1, surface, pixelWorld.y ) );
		vec2 tilt = slope / pixelWorld;
		pxPerMm *= inversesqrt( 1.0 + tilt * tilt ); // cos(tilt) per axis
	#endif
	ivec2 radiusPx = min( ivec2( floor( radiusMm * pxPerMm ) ), ivec2( maxRadiusPx ) );
	vec3 sum = vec3( 0.0 );
	vec3 weightSum = vec3( 0.0 );
	for ( int dj = 0; dj <= radiusPx.y; dj ++ ) {
		float yMm = float( dj ) / pxPerMm.y;
		float y0 = ( float( dj ) - 0.5 ) / pxPerMm.y;
		float y1 = ( float( dj ) + 0.5 ) / pxPerMm.y;
		int diMax = min( radiusPx.x, int( floor( sqrt( max( radiusMm * radiusMm - yMm * yMm, 0.0 ) ) * pxPerMm.x ) ) );
		float x0 = - 0.5 / pxPerMm.x;
		vec3 lowLeft = sssQuadrantEnergy( tQuadrant, x0, y0, quadrantRangeMm );
		vec3 highLeft = sssQuadrantEnergy( tQuadrant, x0, y1, quadrantRangeMm );
		for ( int di = 0; di <= diMax; di ++ ) {
			float x1 = ( float( di ) + 0.5 ) / pxPerMm.x;
			vec3 lowRight = sssQuadrantEnergy( tQuadrant, x1, y0, quadrantRangeMm );
			vec3 highRight = sssQuadrantEnergy( tQuadrant, x1, y1, quadrantRangeMm );
			vec3 energy = highRight - highLeft - lowRight + lowLeft;
			lowLeft = lowRight;
			highLeft = highRight;
			vec2 dz = slope * vec2( di, dj );
			addPixel( pixel, ivec2( di, dj ), energy, surface.r + dz.x + dz.y, centre, sum, weightSum );
			if ( di > 0 ) addPixel( pixel, ivec2( - di, dj ), energy, surface.r - dz.x + dz.y, centre, sum, weightSum );
			if ( dj > 0 ) {
				addPixel( pixel, ivec2( di, - dj ), energy, surface.r + dz.x - dz.y, centre, sum, weightSum );
				if ( di > 0 ) addPixel( pixel, ivec2( - di, - dj ), energy, surface.r - dz.x - dz.y, centre, sum, weightSum );
			}
		}
	}
	vec3 result = sum / weightSum;
	gl_FragColor = sssCovered( sssFinite( result ) ? result : centre, pixelCentre.coverage );
}
