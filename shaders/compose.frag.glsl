// Stage 4: scattered diffuse light back on top of the specular light, in linear HDR, before
// OutputPass. Pixels that are not subsurface keep exactly what their material wrote.

uniform sampler2D tLight;     // location 0: specular + emissive of subsurface pixels, full colour elsewhere
uniform sampler2D tScattered; // blurred diffuse light
uniform sampler2D tSurface;   // g > 0 on subsurface pixels

varying vec2 vUv;

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	vec4 light = texelFetch( tLight, pixel, 0 );
	vec3 colour = light.rgb;
	if ( texelFetch( tSurface, pixel, 0 ).g > 0.0 ) colour += texelFetch( tScattered, pixel, 0 ).rgb;
	// Never hand NaN or Inf to tone mapping.
	if ( any( isnan( colour ) ) || any( isinf( colour ) ) ) colour = vec3( 0.0 );
	gl_FragColor = vec4( colour, light.a );
}
