// Stage 4: scattered diffuse light back on top of the specular light, in linear HDR, before
// OutputPass. Pixels that are not subsurface keep exactly what their material wrote.
// DEBUG_VIEW (define) shows one ingredient instead: 0 final, 1 scattered diffuse, 2 specular,
// 3 linear depth, 4 mask, 5 thickness, 6 transmitted light (5 and 6 need the materials to write
// them into the diffuse target: SubsurfaceScattering.setDebugView does that).

uniform sampler2D tLight;       // location 0: specular + emissive of subsurface pixels, full colour elsewhere
uniform sampler2D tScattered;   // blurred diffuse light
uniform sampler2D tUnscattered; // the diffuse light before the blur; alpha 1 on subsurface pixels (the mask)
uniform sampler2D tSurface;     // r: linear view depth (world units)
uniform float splitX;           // pixels left of this column show the unblurred diffuse light
uniform float debugDepthRange;  // world units mapped to white in the depth view
uniform float debugThicknessRangeMm; // millimetres mapped to white in the thickness view

varying vec2 vUv;

// shaders/finite.glsl, inlined by the pass.
FINITE_GLSL

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	vec4 light = texelFetch( tLight, pixel, 0 );
	vec2 surface = texelFetch( tSurface, pixel, 0 ).rg;
	bool subsurface = texelFetch( tUnscattered, pixel, 0 ).a > 0.0;
	vec3 diffuse = gl_FragCoord.x < splitX ? texelFetch( tUnscattered, pixel, 0 ).rgb : texelFetch( tScattered, pixel, 0 ).rgb;
	vec3 colour;
	#if DEBUG_VIEW == 0
		colour = light.rgb + ( subsurface ? diffuse : vec3( 0.0 ) );
	#elif DEBUG_VIEW == 1
		colour = subsurface ? diffuse : vec3( 0.0 );
	#elif DEBUG_VIEW == 2
		colour = subsurface ? light.rgb : vec3( 0.0 );
	#elif DEBUG_VIEW == 3
		colour = vec3( surface.r > 0.0 ? 1.0 - surface.r / debugDepthRange : 0.0 );
	#elif DEBUG_VIEW == 4
		colour = vec3( subsurface ? 1.0 : 0.0 );
	#elif DEBUG_VIEW == 5
		colour = subsurface ? vec3( texelFetch( tUnscattered, pixel, 0 ).r / debugThicknessRangeMm ) : vec3( 0.0 );
	#else
		colour = subsurface ? texelFetch( tUnscattered, pixel, 0 ).rgb : vec3( 0.0 );
	#endif
	// Never hand NaN or Inf to tone mapping.
	if ( ! sssFinite( colour ) ) colour = vec3( 0.0 );
	gl_FragColor = vec4( colour, light.a );
}
