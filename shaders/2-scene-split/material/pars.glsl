// Stage 2 (material split): declarations added before main() of MeshStandard/MeshPhysical.
// Location 0 keeps three's pc_fragColor: the colour attachment (specular + emissive while split,
// full colour otherwise). The locations and what each channel holds come from the multi-target's
// contract (src/2-scene-split/subsurfaceTarget.js), as defines.
#include "2-scene-split/material/outputs.glsl"

uniform bool sssSplit;       // true only while drawn into the multi-target's split call
uniform float sssWidthWorld; // widthMm / worldUnitInMm: world units per profile millimetre
uniform float sssWidthScale; // 0..1, scales the width (0 = no scattering, the light kept)
uniform int sssDebugOutput;  // what the diffuse attachment holds: SSS_OUTPUT_DIFFUSE, _TRANSMITTANCE or _THICKNESS (mm)
uniform int sssProfileSlot;  // the material's profile slot in the drawing pipeline (src/profiles/profileSlots.js)
uniform bool sssDiffuseCarriesDepth; // the diffuse attachment carries the depth in its alpha (subsurfaceTarget.js), else 1

#include "common/carriedDepth.glsl"


// Transmittance (shaders/2-scene-split/material/transmittedLight.glsl), set per draw from the
// drawing pipeline's settings: per light (up to SSS_MAX_LIGHTS, each with its own map), what
// src/2-scene-split/transmittanceModel.js's writer writes for one.
uniform bool sssTransmits;                              // some light of this draw's pipeline transmits through the material
uniform bool sssLightTransmits[ SSS_MAX_LIGHTS ];       // this one has a map as last rendered and shines
uniform int sssLightTypes[ SSS_MAX_LIGHTS ];            // SSS_LIGHT_TYPE_DIRECTIONAL or SSS_LIGHT_TYPE_SPOT
uniform vec3 sssLightColors[ SSS_MAX_LIGHTS ];          // colour * intensity
uniform vec3 sssLightPositionsView[ SSS_MAX_LIGHTS ];   // spot position, view space
uniform vec3 sssLightDirectionsView[ SSS_MAX_LIGHTS ];  // unit vector towards the light (directional and spot axis)
uniform float sssLightCutoffDistances[ SSS_MAX_LIGHTS ];
uniform float sssLightDecays[ SSS_MAX_LIGHTS ];
uniform float sssSpotConeCosines[ SSS_MAX_LIGHTS ];
uniform float sssSpotPenumbraCosines[ SSS_MAX_LIGHTS ];
uniform sampler2D sssLightDepthMaps[ SSS_MAX_LIGHTS ];
uniform mat4 sssViewToLightViews[ SSS_MAX_LIGHTS ];
uniform mat4 sssLightProjections[ SSS_MAX_LIGHTS ];
uniform bool sssLightCubes[ SSS_MAX_LIGHTS ];           // the map is a point light's six faces (else one view: sssLightProjections)

#include "common/finite.glsl"
#include "2-scene-split/transmittance.glsl"

// Light `i`'s light through the point at `position` (view space), before the albedo: T and the
// entry cosine from its map (transmittance.glsl), its colour and attenuation (three's own
// functions, consistent with its front-side light; the shadow does not apply: the light went
// through), and wrap lighting on the back side where the light leaves: saturate(0.3 + dot(-N, L))
// (REFERENCE §5), for light that comes from behind the point as the camera sees it (view space:
// +z to the camera; the constants are transmittanceModel.js's TRANSMITTED_LIGHT, as defines).
// Light from the camera's side reaches what the camera sees through its lit, visible
// neighbourhood, which the blur already spreads: counted again it made a bright band along a
// front light's terminator. The map is read only where some light comes through.
vec3 sssTransmittedFrom( const in int i, sampler2D lightDepthMap, const in vec3 position, const in vec3 normal, const in vec3 face ) {
	if ( ! sssLightTransmits[ i ] ) return vec3( 0.0 );
	vec3 toLight = sssLightDirectionsView[ i ];
	float attenuation = 1.0;
	if ( sssLightTypes[ i ] != SSS_LIGHT_TYPE_DIRECTIONAL ) {
		vec3 lightVector = sssLightPositionsView[ i ] - position;
		float lightDistance = length( lightVector );
		toLight = lightVector / lightDistance;
		attenuation = getDistanceAttenuation( lightDistance, sssLightCutoffDistances[ i ], sssLightDecays[ i ] );
		if ( sssLightTypes[ i ] == SSS_LIGHT_TYPE_SPOT ) attenuation *= getSpotAttenuation( sssSpotConeCosines[ i ], sssSpotPenumbraCosines[ i ], dot( toLight, sssLightDirectionsView[ i ] ) );
	}
	float wrap = saturate( SSS_WRAP_OFFSET + dot( - normal, toLight ) ) * smoothstep( 0.0, SSS_FROM_BEHIND_RANGE, - toLight.z );
	float weight = attenuation * wrap;
	if ( weight <= 0.0 ) return vec3( 0.0 );
	vec3 through = sssLightCubes[ i ]
		? sssPointTransmittanceFrom( lightDepthMap, sssViewToLightViews[ i ], position, normal, face )
		: sssTransmittanceOfFace( lightDepthMap, sssViewToLightViews[ i ], sssLightProjections[ i ], position, normal, face );
	return sssLightColors[ i ] * weight * through;
}
