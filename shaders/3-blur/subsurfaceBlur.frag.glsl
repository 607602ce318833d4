// Stage 3: one direction of the separable, depth- and mask-aware subsurface blur.
// Defines (src/3-blur/SubsurfaceBlurPass.js sets them): AXIS (0 = horizontal, 1 = vertical: an
// index into vectors), SAMPLES (the taps compiled for, odd; KERNEL_MODE_TAPS runs tapCount of them), FOLLOW_SURFACE (FOLLOW_SURFACE_OFF, _DROP, _LERP),
// FORESHORTEN (0 or 1: grazing-angle correction, below), SSS_COVERAGE (0 or 1: the inputs were
// resolved from MSAA, shaders/common/surfaceSample.glsl), SSS_MAX_SLOPE, SSS_MIN_KERNEL_PIXELS,
// SSS_ENERGY_LEFT (the numbers of src/3-blur/samplingModel.js), PROFILE_COUNT (the profiles in the
// frame; above 1 each pixel blurs with its own, shaders/common/surfaceSample.glsl), SSS_GROUPS (1:
// one kernel; 4: the isotropic blur's groups, 'footprint' only, shaders/3-blur/kernelGroups.glsl:
// the horizontal pass then writes the groups, the vertical one sums them) and KERNEL_MODE:
//   KERNEL_MODE_TAPS: fixed weights and offsets (computeKernel's reference or marginal kernel);
//   KERNEL_MODE_FOOTPRINT: per pixel, footprints of whole pixels from the FootprintTable, weighted
//     by the profile marginal's exact energy from the ProfileLookup.
//
// The sampling model this implements is stated once, numbered, in docs/ARCHITECTURE.md ("Stage 3:
// the sampling model"); the float64 oracle in test/oracle/convolution.js implements the same.

uniform sampler2D tDiffuse;  // the multi-target's diffuse light (or the horizontal pass's output, SSS_GROUPS 1); alpha: the mask
uniform sampler2D tSurface;  // the multi-target's surface: r linear view depth (world units), g world units per profile mm
uniform vec4 kernel[ SAMPLES ]; // (weight R, G, B, offset in kernel mm), centre tap first
uniform int tapCount;           // KERNEL_MODE_TAPS: the kernel's taps (<= SAMPLES; 'auto' sets it per frame)
uniform float kernelRadiusMm;   // the kernel's reach: below SSS_MIN_KERNEL_PIXELS of it a pixel does no work
uniform vec3 strength;          // KERNEL_MODE_FOOTPRINT: mix with no scattering (the reference's strength)
uniform vec2 projectionScale;   // camera.projectionMatrix.elements[0], [5]
uniform vec2 resolution;        // pixels (width, height)
uniform float depthFalloff;     // 1 / depth threshold (world units): dz beyond it is another surface
uniform bool perspective;       // false for an orthographic camera: the step does not shrink with depth

#include "common/finite.glsl"
#include "common/screenScale.glsl"
#include "common/surfaceSample.glsl"
#include "common/surfaceSlope.glsl"
#include "common/surfaceTap.glsl"

#if SSS_GROUPS > 1
	#if KERNEL_MODE != KERNEL_MODE_FOOTPRINT
		#error "SSS_GROUPS > 1 needs KERNEL_MODE_FOOTPRINT"
	#endif
	#include "3-blur/kernelGroups.glsl"
	#if PROFILE_COUNT > 1
		#define SSS_GROUP_SLOT sssSlot
	#else
		#define SSS_GROUP_SLOT 0
	#endif
#endif
#if SSS_GROUPS == 1 || AXIS == 1
	layout( location = 0 ) out highp vec4 sssFragColor; // GLSL 3 (the horizontal groups write two integer attachments)
	#define gl_FragColor sssFragColor
#endif

#if KERNEL_MODE == KERNEL_MODE_TAPS && PROFILE_COUNT > 1
	// Several profiles: row p holds slot p's kernel, laid out as `kernel` (SubsurfaceBlurPass.setKernel).
	uniform sampler2D tKernels;
	#define SSS_KERNEL_TAP( i ) texelFetch( tKernels, ivec2( i, sssSlot ), 0 )
#else
	#define SSS_KERNEL_TAP( i ) kernel[ i ]
#endif

#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
	#define BLOCKS ( ( SAMPLES - 1 ) / 2 - 1 ) // footprints per side before the tail
	uniform sampler2D tProfile;                 // ProfileLookup.texture, row 1: G(x) = ∫_0^x marginal
	#if PROFILE_COUNT == 1
		uniform float marginalRangeMm;              // ProfileLookup.marginalRangeMm
		#define SSS_MARGINAL_ROW 1
		#define SSS_MARGINAL_RANGE_MM marginalRangeMm
		#define SSS_FOOTPRINT_ROW( row ) row
	#else
		// Several profiles: tProfile and tFootprints are ProfileStack's, slot p's rows at 2p + 1 and
		// from p * SSS_FOOTPRINT_ROWS; the pixel reads its own slot's (sssSlot).
		uniform float marginalRangesMm[ PROFILE_COUNT ]; // ProfileStack.marginalRangesMm
		#define SSS_MARGINAL_ROW ( 2 * sssSlot + 1 )
		#define SSS_MARGINAL_RANGE_MM marginalRangesMm[ sssSlot ]
		#define SSS_FOOTPRINT_ROW( row ) ( sssSlot * SSS_FOOTPRINT_ROWS + row )
	#endif
	// FootprintTable.texture: row r is scale SSS_FOOTPRINT_SCALE_MIN * 2^(r / SSS_FOOTPRINT_PER_OCTAVE)
	// px/mm; texel j holds footprint j's outer edge (infinite for the last one) and where it is
	// sampled (where it keeps the kernel's variance: footprintSamplePosition), in profile mm.
	uniform sampler2D tFootprints;
	#include "common/profileLookup.glsl"
#endif

varying vec2 vUv;

// The two texels around a tap at `offsetPx` along the axis (centres at integer + 0.5, clamped) and
// the second one's share; false when the tap is off screen.
bool sssTapTexels( const in float offsetPx, const in ivec2 pixel, out ivec2 texel0, out ivec2 texel1, out float fraction ) {
	float position = float( pixel[ AXIS ] ) + 0.5 + offsetPx;
	texel0 = texel1 = pixel;
	fraction = 0.0;
	if ( position < 0.0 || position >= resolution[ AXIS ] ) return false;
	float u = position - 0.5;
	float below = floor( u );
	fraction = u - below;
	int last = int( resolution[ AXIS ] ) - 1;
	texel0[ AXIS ] = clamp( int( below ), 0, last );
	texel1[ AXIS ] = clamp( int( below ) + 1, 0, last );
	return true;
}

// The light of a tap at `offsetPx`: its two texels' light, each times its share and the tap rule's
// weight, in `light`; returns the sum of those weights (0: nothing kept). Texels are compared with
// the depth the centre's plane predicts there: centreDepth + slope * (texel offset).
float sssLinearTap( const in float offsetPx, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre, out vec3 light ) {
	ivec2 texel0, texel1;
	float fraction;
	light = vec3( 0.0 );
	if ( ! sssTapTexels( offsetPx, pixel, texel0, texel1, fraction ) ) return 0.0;
	vec3 colour0, colour1 = vec3( 0.0 );
	float weight0 = ( 1.0 - fraction ) * sssTapWeight( texel0, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre, colour0 );
	float weight1 = 0.0;
	// A tap on a texel centre (every footprint one pixel wide: most of them at small scales) weighs
	// its second texel 0: not fetching it gives the same sums (SSS_SKIP_EMPTY_TEXELS 0: fetched).
	if ( SSS_SKIP_EMPTY_TEXELS == 0 || fraction > 0.0 ) weight1 = fraction * sssTapWeight( texel1, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre, colour1 );
	light = colour0 * weight0 + colour1 * weight1;
	return weight0 + weight1;
}

// Adds one tap at `offsetPx` along the axis with kernel weight `weight` to the sums.
void addTap( const in float offsetPx, const in vec3 weight, const in ivec2 pixel, const in float centreDepth, const in float slope, const in vec3 centre, inout vec3 sum, inout vec3 weightSum ) {
	vec3 light;
	float kept = sssLinearTap( offsetPx, pixel, centreDepth, slope, centre, light );
	if ( kept <= 0.0 ) return;
	sum += weight * light;
	weightSum += weight * kept;
}

#if SSS_GROUPS > 1
	// Adds `light` kept with `kept` at the groups' weights `parts` to their sums.
	void sssAddGroups( const in SssGroupLight parts, const in SssGroupLight light, const in float kept, inout SssGroupLight sums, inout SssGroupLight weightSums ) {
		for ( int g = 0; g < SSS_GROUPS; g ++ ) {
			sums.group[ g ] += parts.group[ g ] * light.group[ g ];
			weightSums.group[ g ] += parts.group[ g ] * kept;
		}
	}

	#if AXIS == 1
		// The vertical pass's tap over the groups: as sssLinearTap, each group apart.
		float sssLinearGroupTap( const in float offsetPx, const in ivec2 pixel, const in float centreDepth, const in float slope, const in SssGroupLight centre, out SssGroupLight light ) {
			ivec2 texel0, texel1;
			float fraction;
			light = sssNoGroups();
			if ( ! sssTapTexels( offsetPx, pixel, texel0, texel1, fraction ) ) return 0.0;
			SssGroupLight light0, light1 = light;
			float weight0 = ( 1.0 - fraction ) * sssGroupTapWeight( texel0, centreDepth + slope * float( texel0[ AXIS ] - pixel[ AXIS ] ), centre, light0 );
			float weight1 = 0.0;
			if ( SSS_SKIP_EMPTY_TEXELS == 0 || fraction > 0.0 ) weight1 = fraction * sssGroupTapWeight( texel1, centreDepth + slope * float( texel1[ AXIS ] - pixel[ AXIS ] ), centre, light1 );
			for ( int g = 0; g < SSS_GROUPS; g ++ ) light.group[ g ] = light0.group[ g ] * weight0 + light1.group[ g ] * weight1;
			return weight0 + weight1;
		}
	#endif

	// One tap of the groups at `offsetPx`: the horizontal pass splits the diffuse light's tap, the
	// vertical one reads each group's own.
	void sssAddGroupTap( const in float offsetPx, const in SssGroupLight parts, const in ivec2 pixel, const in float centreDepth, const in float slope, const in SssGroupLight centre, inout SssGroupLight sums, inout SssGroupLight weightSums ) {
		SssGroupLight light;
		#if AXIS == 0
			vec3 tap;
			float kept = sssLinearTap( offsetPx, pixel, centreDepth, slope, centre.group[ 0 ], tap ); // the horizontal centre: the diffuse light in each
			for ( int g = 0; g < SSS_GROUPS; g ++ ) light.group[ g ] = tap;
		#else
			float kept = sssLinearGroupTap( offsetPx, pixel, centreDepth, slope, centre, light );
		#endif
		if ( kept <= 0.0 ) return;
		sssAddGroups( parts, light, kept, sums, weightSums );
	}
#endif

// The pixel's scale along the axis, px per profile mm (times cos(tilt) with FORESHORTEN), and the
// depth change per pixel along it (world units; 0 without FORESHORTEN).
float sssAxisStep( const in ivec2 pixel, const in vec2 surface, out float slope ) {
	float stepPx = sssPixelsPerMm( surface )[ AXIS ];
	slope = 0.0;
	#if FORESHORTEN == 1
		float pixelWorld = sssPixelWorld( surface )[ AXIS ]; // world units one pixel spans across the view
		slope = sssSurfaceSlope( pixel, AXIS, surface, pixelWorld );
		float tilt = slope / pixelWorld;
		stepPx *= inversesqrt( 1.0 + tilt * tilt ); // cos(theta)
	#endif
	return stepPx;
}

#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
	// The table row nearest a pixel's scale (src/profiles/footprints.js's footprintRowOf).
	int sssFootprintRow( const in float stepPx ) {
		return clamp( int( floor( log2( stepPx / SSS_FOOTPRINT_SCALE_MIN ) * SSS_FOOTPRINT_PER_OCTAVE + 0.5 ) ), 0, SSS_FOOTPRINT_ROWS - 1 );
	}

	// Footprint j of table row `row` at the pixel's scale: its energy per side (`weight`) and where
	// it is sampled (`offsetPx`), snapped to whole pixels; `energyBelow` and `lastEdge` (pixels;
	// footprint j covers pixels lastEdge + 1 .. edge on each side) carry from one to the next.
	// Returns false when nothing is left (the loop ends); `last`: it runs to the kernel's end.
	bool sssFootprint( const in int j, const in int row, const in float stepPx, inout vec3 energyBelow, inout int lastEdge, out vec3 weight, out float offsetPx, out bool last ) {
		weight = vec3( 0.0 );
		offsetPx = 0.0;
		last = true;
		if ( all( greaterThan( energyBelow, vec3( 0.5 - SSS_ENERGY_LEFT ) ) ) ) return false; // nothing left
		vec2 footprint = texelFetch( tFootprints, ivec2( j, SSS_FOOTPRINT_ROW( row ) ), 0 ).rg; // outer edge, sample offset (mm)
		// The last footprint runs to the kernel's end and takes all the energy left.
		last = j == BLOCKS || isinf( footprint.x );
		int edge = last ? lastEdge + 1 : max( int( floor( footprint.x * stepPx + 0.5 ) ), lastEdge + 1 );
		vec3 energy = last ? vec3( 0.5 ) : sssReadProfile( tProfile, SSS_MARGINAL_ROW, ( float( edge ) + 0.5 ) / stepPx, SSS_MARGINAL_RANGE_MM );
		weight = energy - energyBelow;
		// Sampled where the table says, kept inside the footprint as snapped at this pixel's scale.
		offsetPx = max( footprint.y * stepPx, float( lastEdge + 1 ) );
		if ( ! last ) offsetPx = min( offsetPx, float( edge ) );
		energyBelow = energy;
		lastEdge = edge;
		return true;
	}
#endif

#if SSS_GROUPS == 1
void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	SssCentre pixelCentre = sssCentreAt( pixel );
	vec3 centre = pixelCentre.colour;
	// Not a subsurface pixel: pass through so the next pass sees the same mask.
	if ( ! ( pixelCentre.coverage > 0.0 ) ) {
		gl_FragColor = vec4( centre, 0.0 );
		return;
	}
	vec2 surface = pixelCentre.surface;
	#if PROFILE_COUNT > 1
		sssSlot = sssNearestSlot( pixel, pixelCentre.coverage );
	#endif

	float slope; // depth change per pixel along the axis, world units
	float stepPx = sssAxisStep( pixel, surface, slope );
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= SSS_MIN_KERNEL_PIXELS ) ) {
		gl_FragColor = sssCovered( centre, pixelCentre.coverage );
		return;
	}

	vec3 sum;
	vec3 weightSum;

	#if KERNEL_MODE == KERNEL_MODE_TAPS
		weightSum = SSS_KERNEL_TAP( 0 ).rgb;
		sum = centre * weightSum;
		for ( int i = 1; i < SAMPLES; i ++ ) {
			if ( i >= tapCount ) break;
			addTap( SSS_KERNEL_TAP( i ).a * stepPx, SSS_KERNEL_TAP( i ).rgb, pixel, surface.r, slope, centre, sum, weightSum );
		}
	#else
		int row = sssFootprintRow( stepPx );
		// The centre pixel is its own footprint: |x| < 0.5 px.
		vec3 energyBelow = sssReadProfile( tProfile, SSS_MARGINAL_ROW, 0.5 / stepPx, SSS_MARGINAL_RANGE_MM );
		weightSum = 2.0 * energyBelow;
		sum = centre * weightSum;
		int lastEdge = 0;
		for ( int j = 0; j <= BLOCKS; j ++ ) {
			vec3 weight;
			float offsetPx;
			bool last;
			if ( ! sssFootprint( j, row, stepPx, energyBelow, lastEdge, weight, offsetPx, last ) ) break;
			addTap( offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			addTap( - offsetPx, weight, pixel, surface.r, slope, centre, sum, weightSum );
			if ( last ) break;
		}
	#endif

	vec3 result = sum / weightSum;
	#if KERNEL_MODE == KERNEL_MODE_FOOTPRINT
		result = mix( centre, result, strength ); // fixed-tap kernels have the strength built in
	#endif
	gl_FragColor = sssCovered( sssFinite( result ) ? result : centre, pixelCentre.coverage );
}
#else
// Each channel's sum over its weights, or `fallback` where nothing was kept.
vec3 sssNormalised( const in vec3 sum, const in vec3 weightSum, const in vec3 fallback ) {
	return vec3(
		weightSum.r > 0.0 ? sum.r / weightSum.r : fallback.r,
		weightSum.g > 0.0 ? sum.g / weightSum.g : fallback.g,
		weightSum.b > 0.0 ? sum.b / weightSum.b : fallback.b
	);
}

// The horizontal pass's output: each group's light over all the groups' kept weight, so the groups
// sum to the one-kernel blur exactly (and the vertical pass, normalising each group by its own,
// gives the one-kernel answer along both axes); `share` is each group's part of that weight, what
// its unblurred light is mixed in by with `strength` < 1. The vertical pass's: the groups' sum, each
// normalised (sssNormalised), mixed with the unblurred sum. Both checked finite.
void sssEndGroups( const in SssGroupLight blurred, const in SssGroupLight centre, const in SssGroupLight share, const in float coverage ) {
	#if AXIS == 0
		SssGroupLight written;
		SssGroupLight unblurred;
		vec3 sum = vec3( 0.0 );
		for ( int g = 0; g < SSS_GROUPS; g ++ ) {
			unblurred.group[ g ] = share.group[ g ] * centre.group[ g ];
			written.group[ g ] = mix( unblurred.group[ g ], blurred.group[ g ], strength );
			sum += written.group[ g ];
		}
		if ( sssFinite( sum ) ) sssWriteGroups( written, coverage );
		else sssWriteGroups( unblurred, coverage );
	#else
		vec3 unblurred = vec3( 0.0 );
		vec3 sum = vec3( 0.0 );
		for ( int g = 0; g < SSS_GROUPS; g ++ ) {
			unblurred += centre.group[ g ];
			sum += blurred.group[ g ];
		}
		vec3 result = mix( unblurred, sum, strength );
		gl_FragColor = sssCovered( sssFinite( result ) ? result : unblurred, coverage );
	#endif
}

// A pixel that does no work (its kernel under half a pixel): the horizontal pass writes its light
// split by the groups' shares of the profile's energy, the vertical one their sum.
void sssEndUnblurred( const in SssGroupLight centre, const in float coverage ) {
	#if AXIS == 0
		SssGroupLight energies;
		SssGroupLight split;
		for ( int g = 0; g < SSS_GROUPS; g ++ ) {
			energies.group[ g ] = groupEnergies[ SSS_GROUP_SLOT * SSS_GROUPS + g ];
			split.group[ g ] = energies.group[ g ] * centre.group[ g ];
		}
		sssEndGroups( split, centre, energies, coverage );
	#else
		sssEndGroups( centre, centre, sssNoGroups(), coverage );
	#endif
}

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	SssGroupLight centre;
	float coverage;
	vec2 surface;
	#if AXIS == 0
		SssCentre pixelCentre = sssCentreAt( pixel );
		for ( int g = 0; g < SSS_GROUPS; g ++ ) centre.group[ g ] = pixelCentre.colour; // each group's input: the diffuse light
		coverage = pixelCentre.coverage;
		surface = pixelCentre.surface;
	#else
		coverage = sssGroupsAt( pixel, centre );
		surface = sssUncovered( texelFetch( tSurface, pixel, 0 ).rg, coverage );
	#endif
	// Not a subsurface pixel: nothing (the diffuse attachment is 0 there), the mask kept.
	if ( ! ( coverage > 0.0 ) ) {
		sssEndGroups( sssNoGroups(), sssNoGroups(), sssNoGroups(), 0.0 );
		return;
	}
	#if PROFILE_COUNT > 1
		sssSlot = sssNearestSlot( pixel, coverage );
	#endif

	float slope;
	float stepPx = sssAxisStep( pixel, surface, slope );
	// Below half a pixel the kernel cannot move light to another pixel: no work.
	if ( ! ( stepPx * kernelRadiusMm >= SSS_MIN_KERNEL_PIXELS ) ) {
		sssEndUnblurred( centre, coverage );
		return;
	}

	int row = sssFootprintRow( stepPx );
	vec3 energyBelow = sssReadProfile( tProfile, SSS_MARGINAL_ROW, 0.5 / stepPx, SSS_MARGINAL_RANGE_MM );
	SssGroupLight weightSums = sssSplit( 2.0 * energyBelow, 0, SSS_FOOTPRINT_ROW( row ) );
	SssGroupLight sums;
	for ( int g = 0; g < SSS_GROUPS; g ++ ) sums.group[ g ] = centre.group[ g ] * weightSums.group[ g ];
	int lastEdge = 0;
	for ( int j = 0; j <= BLOCKS; j ++ ) {
		vec3 weight;
		float offsetPx;
		bool last;
		if ( ! sssFootprint( j, row, stepPx, energyBelow, lastEdge, weight, offsetPx, last ) ) break;
		SssGroupLight parts = sssSplit( weight, j + 1, SSS_FOOTPRINT_ROW( row ) );
		sssAddGroupTap( offsetPx, parts, pixel, surface.r, slope, centre, sums, weightSums );
		sssAddGroupTap( - offsetPx, parts, pixel, surface.r, slope, centre, sums, weightSums );
		if ( last ) break;
	}
	SssGroupLight blurred;
	#if AXIS == 0
		vec3 kept = vec3( 0.0 );
		for ( int g = 0; g < SSS_GROUPS; g ++ ) kept += weightSums.group[ g ];
		if ( ! all( greaterThan( kept, vec3( 0.0 ) ) ) ) { // the centre's own weight is 0 only past float range
			sssEndUnblurred( centre, coverage );
			return;
		}
		SssGroupLight share;
		for ( int g = 0; g < SSS_GROUPS; g ++ ) {
			share.group[ g ] = weightSums.group[ g ] / kept;
			blurred.group[ g ] = sums.group[ g ] / kept;
		}
		sssEndGroups( blurred, centre, share, coverage );
	#else
		for ( int g = 0; g < SSS_GROUPS; g ++ ) blurred.group[ g ] = sssNormalised( sums.group[ g ], weightSums.group[ g ], centre.group[ g ] );
		sssEndGroups( blurred, centre, sssNoGroups(), coverage );
	#endif
}
#endif
