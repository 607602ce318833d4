// Transmittance through thin parts (Jimenez et al. 2010, "Real-Time Realistic Skin Translucency").
// Self-contained (it includes shaders/common/profileLookup.glsl; transmittanceChunk is the two put
// together): needs only these uniforms, so a custom ShaderMaterial can include it too.
// Positions and normals are in the camera's view space; lengths in world units unless named Mm.

#include "common/profileLookup.glsl"

uniform sampler2D sssLightDepthMap;   // LightDepthTarget.texture: r linear light depth (0 = no surface), g the entry cosine |N·L|
uniform mat4 sssViewToLightView;       // camera view space -> light view space
uniform mat4 sssLightProjection;       // the light camera's projection matrix
uniform float sssShrinkWorld;          // inward shrink along the vertex normal, world units: where the map is read, and the fade-in
uniform sampler2D sssProfileLookup;   // ProfileLookup.texture: row 0 is T(d), d in profile mm
uniform float sssTransmittanceRangeMm; // ProfileLookup.transmittanceRangeMm
uniform float sssThicknessToProfileMm; // worldUnitInMm * (1 - translucency) / widthMm

// The profile's transmitted fraction for `thicknessWorld` of material: T(d) at d in profile mm.
vec3 sssProfileTransmittance( const in float thicknessWorld ) {
	return sssReadProfile( sssProfileLookup, 0, thicknessWorld * sssThicknessToProfileMm, sssTransmittanceRangeMm );
}

// On the side of a surface the light reaches, within the first shrink below the recorded surface a
// point reads as that surface (a lit surface measures about 0 there): the light fades in over it,
// so a lit surface and its terminator get no second share of their own light.
float sssLitSideFade( const in float thicknessWorld ) {
	return sssShrinkWorld > 0.0 ? smoothstep( 0.0, sssShrinkWorld, thicknessWorld ) : 1.0;
}

// The normal of the triangle drawn at this fragment, turned to the camera, from the screen
// derivatives of its view-space position: the plane the light's map rasterised too, whatever the
// vertex normals say (a hook that bends a leaf moves its vertices, not its normals). Call it in
// uniform control flow (derivatives are undefined elsewhere).
vec3 sssFaceNormal( const in vec3 viewPosition ) {
	vec3 n = normalize( cross( dFdx( viewPosition ), dFdy( viewPosition ) ) );
	return dot( n, viewPosition ) > 0.0 ? - n : n;
}

// The point's own surface as the light sees it, for the sheet's test below: its triangle's plane,
// from the point and the face normal (sssFaceNormal) in a light view space (the light's axis −z,
// depth −z) and that view's projection, as the depth the map records along the ray of a texel
// centre at `ndc`: ( plane.num · (1, ndc) ) / ( plane.den · (1, ndc) ) (sssPlaneDepth). `facing`:
// the cosine between that normal and the direction to the light; positive on the side the light
// reaches (lit), negative on the far side.
struct SssPlane { vec3 num; vec3 den; float facing; };

SssPlane sssTangentPlane( const in vec3 point, const in vec3 faceNormal, const in mat4 projection ) {
	vec3 n = normalize( faceNormal );
	SssPlane plane;
	vec2 scale = vec2( projection[ 0 ][ 0 ], projection[ 1 ][ 1 ] );
	if ( projection[ 2 ][ 3 ] > - 0.5 ) { // orthographic (three's perspective matrices hold −1 there): rays along −z
		vec2 origin = - vec2( projection[ 3 ][ 0 ], projection[ 3 ][ 1 ] ) / scale; // where ndc 0 is
		plane.num = vec3( - point.z * n.z + dot( n.xy, origin - point.xy ), n.xy / scale );
		plane.den = vec3( n.z, 0.0, 0.0 );
		plane.facing = n.z;
	} else { // perspective: rays from the light through ( (ndc + offset) / scale, −1 )
		vec2 offset = vec2( projection[ 2 ][ 0 ], projection[ 2 ][ 1 ] );
		plane.num = vec3( dot( n, point ), 0.0, 0.0 );
		plane.den = vec3( dot( n.xy, offset / scale ) - n.z, n.xy / scale );
		plane.facing = dot( n, normalize( - point ) );
	}
	return plane;
}

float sssPlaneDepth( const in SssPlane plane, const in vec2 ndc ) {
	vec3 at = vec3( 1.0, ndc );
	return dot( plane.num, at ) / dot( plane.den, at );
}

// T times the entry cosine over the four texels around `texel` (continuous, texel centres at .5)
// of the map's part from `origin`, `size` texels (the whole map, or a point light's face: a texel
// beyond its edge is its edge's), for a point at light depth `depth` on the surface `plane`
// (sssTangentPlane, in the same light view), `texelWorld` a texel's width at that depth.
// A texel on the point's far side that records the point's own surface, within SSS_SHEET_TEXELS of a
// texel's width of its triangle's plane (the map holds each texel centre's depth: exact on the same
// triangle; the tolerance is for a curved sheet's next triangle, a few degrees apart), is a sheet: a leaf, a card, paper, of no thickness, through
// which T(0) = 1 of what entered comes, at most the sheet's own entry cosine (so that what lies
// behind a sheet's edge at a grazing light adds no halo). The fade over the first shrink is the lit
// side's alone.
vec3 sssTransmittanceAround( sampler2D lightDepthMap, const in vec2 texel, const in ivec2 origin, const in ivec2 size, const in float depth, const in SssPlane plane, const in float texelWorld ) {
	ivec2 base = ivec2( floor( texel ) );
	vec2 f = texel - vec2( base );
	bool farSide = plane.facing < 0.0;
	vec3 light = vec3( 0.0 );
	for ( int k = 0; k < 4; k ++ ) {
		ivec2 offset = ivec2( k & 1, k >> 1 );
		float weight = ( offset.x == 1 ? f.x : 1.0 - f.x ) * ( offset.y == 1 ? f.y : 1.0 - f.y );
		ivec2 at = clamp( base + offset, ivec2( 0 ), size - 1 );
		vec2 recorded = texelFetch( lightDepthMap, origin + at, 0 ).rg; // depth, entry cosine
		float thickness = depth - recorded.r;
		bool sheet = farSide && abs( recorded.r - sssPlaneDepth( plane, ( vec2( at ) + 0.5 ) / vec2( size ) * 2.0 - 1.0 ) ) <= SSS_SHEET_TEXELS * texelWorld;
		// The share of the light that entered and comes through.
		float share = 0.0;
		if ( recorded.r > 0.0 && sheet ) share = min( recorded.g, - plane.facing );
		else if ( recorded.r > 0.0 && thickness > 0.0 ) share = recorded.g * ( farSide ? 1.0 : sssLitSideFade( thickness ) );
		if ( share > 0.0 ) light += weight * share * sssProfileTransmittance( sheet ? 0.0 : thickness );
	}
	return light;
}

// The light through this point, per RGB: T of the thickness between the light's nearest surface and
// the point, times the share of the light that entered there (the entry cosine |N·L|, the map's g:
// a grazing entry near the light's terminator lets little in), as a fraction of the light,
// averaged over the four map texels around the point's projection with their bilinear weights (a
// texel with nothing recorded, or whose surface is not in front of the point, sends nothing).
// Without the entry cosine the back-lit head gained light away from its thin parts that the
// surface truth does not have (bench:truth, the head back-lit: "rest" 1.67 of the effect with
// transmittance, 0.43 without it; 0.50 with the entry cosine, the whole head 0.74 -> 0.51).
// Averaging T, not depth, keeps silhouettes in the light's view from mixing a near surface's depth
// with a far one's, and turns their aliasing (lines of single lit pixels where the map's texels
// step along a rim) into a smooth edge.
// The map is read a little inward along the (vertex, not bump-mapped) normal, so that a lit surface
// finds itself and not a texel of whatever lies beside it (REFERENCE §5's shrink, about 0.6 mm);
// the thickness is measured from the point itself, so the shrink does not shorten it. A sheet
// (sssTransmittanceAround) is found wherever the map is read: the shrink does not change its light.
// The map and the light's matrices are arguments: the material reads one map per light.
vec3 sssTransmittanceOfFace( sampler2D lightDepthMap, const in mat4 viewToLightView, const in mat4 lightProjection, const in vec3 viewPosition, const in vec3 viewVertexNormal, const in vec3 viewFaceNormal ) {
	vec3 shrunk = viewPosition - sssShrinkWorld * viewVertexNormal;
	vec4 lightView = viewToLightView * vec4( shrunk, 1.0 );
	vec4 clip = lightProjection * lightView;
	vec3 ndc = clip.xyz / clip.w;
	if ( clip.w <= 0.0 || any( greaterThan( abs( ndc.xy ), vec2( 1.0 ) ) ) ) return vec3( 0.0 );
	vec3 point = ( viewToLightView * vec4( viewPosition, 1.0 ) ).xyz;
	float depth = - point.z; // the point's own light depth
	SssPlane plane = sssTangentPlane( point, mat3( viewToLightView ) * viewFaceNormal, lightProjection );
	ivec2 size = textureSize( lightDepthMap, 0 );
	bool orthographic = lightProjection[ 2 ][ 3 ] > - 0.5;
	float texelWorld = 2.0 * ( orthographic ? 1.0 : depth ) / ( lightProjection[ 0 ][ 0 ] * float( size.x ) );
	return sssTransmittanceAround( lightDepthMap, ( ndc.xy * 0.5 + 0.5 ) * vec2( size ) - 0.5, ivec2( 0 ), size, depth, plane, texelWorld );
}

// The same with the face normal from the position's derivatives: call it in uniform control flow.
vec3 sssTransmittanceFrom( sampler2D lightDepthMap, const in mat4 viewToLightView, const in mat4 lightProjection, const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	return sssTransmittanceOfFace( lightDepthMap, viewToLightView, lightProjection, viewPosition, viewVertexNormal, sssFaceNormal( viewPosition ) );
}

// A point light's map (LightDepthView's POINT_FACES): six faces side by side, three across and two
// up, face k = 2 · axis (x, y, z) + (1 where it looks along −axis), its up +y (+z for the ±y
// faces). `viewToLight` takes view space to the light's place with the world's axes; the face is
// the one the shrunk point's largest axis falls in, its depth the distance along that axis.
vec3 sssPointTransmittanceFrom( sampler2D lightDepthMap, const in mat4 viewToLight, const in vec3 viewPosition, const in vec3 viewVertexNormal, const in vec3 viewFaceNormal ) {
	vec3 shrunk = ( viewToLight * vec4( viewPosition - sssShrinkWorld * viewVertexNormal, 1.0 ) ).xyz;
	vec3 a = abs( shrunk );
	int axis = a.x >= a.y && a.x >= a.z ? 0 : ( a.y >= a.z ? 1 : 2 );
	vec3 forward = vec3( 0.0 );
	forward[ axis ] = shrunk[ axis ] < 0.0 ? - 1.0 : 1.0;
	vec3 up = axis == 1 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 0.0, 1.0, 0.0 );
	vec3 x = normalize( cross( up, - forward ) );
	vec3 y = cross( - forward, x );
	vec2 ndc = vec2( dot( shrunk, x ), dot( shrunk, y ) ) / dot( shrunk, forward );
	mat3 toFace = transpose( mat3( x, y, - forward ) ); // the face's view space: x, y, and −forward as z
	vec3 point = toFace * ( viewToLight * vec4( viewPosition, 1.0 ) ).xyz;
	float depth = - point.z; // the point's own, on that face
	SssPlane plane = sssTangentPlane( point, toFace * mat3( viewToLight ) * viewFaceNormal, mat4( 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, - 1.0, - 1.0, 0.0, 0.0, - 1.0, 0.0 ) ); // a 90° face's projection
	int face = 2 * axis + ( shrunk[ axis ] < 0.0 ? 1 : 0 );
	ivec2 size = textureSize( lightDepthMap, 0 ) / ivec2( 3, 2 );
	float texelWorld = 2.0 * depth / float( size.x );
	return sssTransmittanceAround( lightDepthMap, ( ndc * 0.5 + 0.5 ) * vec2( size ) - 0.5, ivec2( face % 3, face / 3 ) * size, size, depth, plane, texelWorld );
}

// The thickness the light crosses to this point (world units, the map's nearest texel), for the
// debug view: 0 on a sheet's far side; negative where nothing was recorded or the point is not
// behind the recorded surface. In uniform control flow (sssFaceNormal).
float sssThicknessWorldFrom( sampler2D lightDepthMap, const in mat4 viewToLightView, const in mat4 lightProjection, const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	vec4 clip = lightProjection * viewToLightView * vec4( viewPosition - sssShrinkWorld * viewVertexNormal, 1.0 );
	vec3 ndc = clip.xyz / clip.w;
	if ( clip.w <= 0.0 || any( greaterThan( abs( ndc.xy ), vec2( 1.0 ) ) ) ) return - 1.0;
	ivec2 size = textureSize( lightDepthMap, 0 );
	ivec2 at = clamp( ivec2( floor( ( ndc.xy * 0.5 + 0.5 ) * vec2( size ) ) ), ivec2( 0 ), size - 1 );
	float nearest = texelFetch( lightDepthMap, at, 0 ).r;
	vec3 point = ( viewToLightView * vec4( viewPosition, 1.0 ) ).xyz;
	SssPlane plane = sssTangentPlane( point, mat3( viewToLightView ) * sssFaceNormal( viewPosition ), lightProjection );
	bool orthographic = lightProjection[ 2 ][ 3 ] > - 0.5;
	float texelWorld = 2.0 * ( orthographic ? 1.0 : - point.z ) / ( lightProjection[ 0 ][ 0 ] * float( size.x ) );
	if ( nearest <= 0.0 ) return - 1.0;
	if ( plane.facing < 0.0 && abs( nearest - sssPlaneDepth( plane, ( vec2( at ) + 0.5 ) / vec2( size ) * 2.0 - 1.0 ) ) <= SSS_SHEET_TEXELS * texelWorld ) return 0.0;
	float thickness = - point.z - nearest;
	return thickness > 0.0 ? thickness : - 1.0;
}

// The same for the one light of the uniforms above (a custom ShaderMaterial's).
vec3 sssTransmittance( const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	return sssTransmittanceFrom( sssLightDepthMap, sssViewToLightView, sssLightProjection, viewPosition, viewVertexNormal );
}

float sssThicknessWorld( const in vec3 viewPosition, const in vec3 viewVertexNormal ) {
	return sssThicknessWorldFrom( sssLightDepthMap, sssViewToLightView, sssLightProjection, viewPosition, viewVertexNormal );
}
