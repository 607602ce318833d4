// Stage 2 (material split): declarations added before main() of MeshStandard/MeshPhysical.
// Location 0 keeps three's pc_fragColor: specular + emissive while split, full colour otherwise.
layout( location = 1 ) out highp vec4 sssDiffuseOutput; // diffuse light (+ transmittance), a = 1: the mask
layout( location = 2 ) out highp vec4 sssSurfaceOutput; // r: linear view depth, g: world units per kernel mm x strength

uniform bool sssSplit;      // true only while drawn into the subsurface multi-target
uniform bool sssDepthOnly;  // true in the scene pass's first call: lay down depth, shade nothing
uniform float sssWidthWorld; // widthMm / worldUnitInMm: world units per profile millimetre
uniform float sssStrength;   // 0..1, scales the width (0 = no scattering)
uniform int sssDebugOutput;  // what location 1 holds: 0 diffuse light, 1 transmitted light only, 2 thickness (mm)

#ifdef SSS_TRANSMITTANCE
	uniform vec3 sssLightColor;          // colour * intensity
	uniform vec3 sssLightPositionView;   // point/spot position, view space
	uniform vec3 sssLightDirectionView;  // unit vector towards the light (directional and spot axis)
	uniform float sssLightCutoffDistance;
	uniform float sssLightDecay;
	uniform float sssSpotConeCos;
	uniform float sssSpotPenumbraCos;
#endif
