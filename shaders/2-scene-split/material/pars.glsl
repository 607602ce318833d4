// Stage 2 (material split): declarations added before main() of MeshStandard/MeshPhysical.
// Location 0 keeps three's pc_fragColor: the colour attachment (specular + emissive while split,
// full colour otherwise). The locations and what each channel holds come from the multi-target's
// contract (src/2-scene-split/subsurfaceTarget.js), as defines.
layout( location = SSS_DIFFUSE_LOCATION ) out highp vec4 sssDiffuseOutput; // diffuse light (+ transmittance); a: 1 (the mask) or the depth (sssDiffuseCarriesDepth)
layout( location = SSS_SURFACE_LOCATION ) out highp vec4 sssSurfaceOutput; // r: linear view depth, g: world units per profile mm, b: profile slot

uniform bool sssSplit;       // true only while drawn into the multi-target's split call
uniform float sssWidthWorld; // widthMm / worldUnitInMm: world units per profile millimetre
uniform float sssWidthScale; // 0..1, scales the width (0 = no scattering, the light kept)
uniform int sssDebugOutput;  // what the diffuse attachment holds: SSS_OUTPUT_DIFFUSE, _TRANSMITTANCE or _THICKNESS (mm)
uniform int sssProfileSlot;  // the material's profile slot in the drawing pipeline (src/profiles/profileSlots.js)
uniform bool sssDiffuseCarriesDepth; // the diffuse attachment carries the depth in its alpha (subsurfaceTarget.js), else 1

#include "common/carriedDepth.glsl"


// Transmittance (shaders/2-scene-split/material/transmittedLight.glsl), set per draw from the
// drawing pipeline's settings.
uniform bool sssTransmits;           // this draw's pipeline has a shining light and the material transmits
uniform int sssLightType;            // SSS_LIGHT_TYPE_DIRECTIONAL or SSS_LIGHT_TYPE_SPOT
uniform vec3 sssLightColor;          // colour * intensity (0 when the light does not shine in this scene)
uniform vec3 sssLightPositionView;   // spot position, view space
uniform vec3 sssLightDirectionView;  // unit vector towards the light (directional and spot axis)
uniform float sssLightCutoffDistance;
uniform float sssLightDecay;
uniform float sssSpotConeCos;
uniform float sssSpotPenumbraCos;

#include "common/finite.glsl"
#include "2-scene-split/transmittance.glsl"
