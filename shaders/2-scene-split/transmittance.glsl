// Transmittance through thin parts (Jimenez et al. 2010, "Real-Time Realistic Skin Translucency").
// Self-contained (it includes shaders/common/profileLookup.glsl; transmittanceChunk is the two put
// together): needs only these uniforms, so a custom ShaderMaterial can include it too.
// Positions and normals are in the camera's view space; lengths in world units unless named Mm.

#include "common/profileLookup.glsl"

uniform sampler2D sssLightDepthMap;   // LightDepthTarget.texture: linear light depth, 0 = no surface
uniform mat4 sssViewToLightView;       // camera view space -> light view space
uniform mat4 sssLightProjection;       // the light camera's projection matrix
uniform float sssShrinkWorld;          // inward shrink along the vertex normal, against acne
uniform sampler2D sssProfileLookup;   // ProfileLookup.texture: row 0 is T(d), d in profile mm
uniform float sssTransmittanceRangeMm; // ProfileLookup.transmittanceRangeMm
uniform float sssThicknessToProfileMm; // worldUnitInMm * (1 - translucency) / widthMm

// Thickness between the light's nearest surface and this point, in world units; negative when
// the point is outside the light's frustum or nothing was recorded there.
float sssThicknessWorld( const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	// Shrink inward along the (vertex, not bump-mapped) normal so the lit surface itself does not
	// read as a thin shell (REFERENCE §5: about 0.6 mm in the reference).
	vec3 shrunk = viewPosition - sssShrinkWorld * viewVertexNormal;
	vec4 lightView = sssViewToLightView * vec4( shrunk, 1.0 );
	vec4 clip = sssLightProjection * lightView;
	vec3 ndc = clip.xyz / clip.w;
	if ( clip.w <= 0.0 || any( greaterThan( abs( ndc.xy ), vec2( 1.0 ) ) ) ) return - 1.0;
	float nearest = texture( sssLightDepthMap, ndc.xy * 0.5 + 0.5 ).r;
	if ( nearest <= 0.0 ) return - 1.0;
	return max( - lightView.z - nearest, 0.0 );
}

// T(d) of the profile for this thickness (world units), per RGB; 0 where nothing was recorded.
vec3 sssTransmittanceProfile( const in float thicknessWorld ) {
	if ( thicknessWorld < 0.0 ) return vec3( 0.0 );
	return sssReadProfile( sssProfileLookup, 0, thicknessWorld * sssThicknessToProfileMm, sssTransmittanceRangeMm );
}

vec3 sssTransmittance( const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	return sssTransmittanceProfile( sssThicknessWorld( viewPosition, viewVertexNormal ) );
}
