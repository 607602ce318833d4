// Stage 4: the scattered diffuse light back on top of the rest of the scene's light, in linear
// HDR, before OutputPass (on the screen, as the last pass: tone-mapped and encoded, see the end).
// Pixels that are not subsurface keep exactly what their material wrote.
// The scene's depth goes out with the colour (gl_FragDepth), so that later passes and the
// transparent objects drawn after this one depth-test against the scene; with WRITE_DEPTH 0 the
// output has taken the split's depth per sample instead (src/4-compose/multisampledDepth.js).
// With KEEP_BACKGROUND (the pass's clear = false) pixels where the scene drew nothing are left as
// the target had them.
// DEBUG_VIEW (src/4-compose/debugViews.js) shows one ingredient instead; the thickness and
// transmittance views need the materials to write them into the diffuse target
// (SubsurfaceScattering.setDebugView does that).

uniform sampler2D tColor;      // the multi-target's colour: specular + emissive of subsurface pixels, full colour elsewhere
uniform sampler2D tScattered;  // the blurred diffuse light; alpha: the mask (not 0 on it)
uniform sampler2D tDiffuse;    // the diffuse light before the blur; alpha: the mask (1, the coverage, or a carried depth)
uniform sampler2D tSurface;    // r: linear view depth (world units)
uniform sampler2D tDepth;      // the multi-target's depth texture
uniform float farDepth;        // the depth buffer's cleared value: 1 (0 with a reversed depth buffer)
uniform float splitX;          // pixels left of this column show the unblurred diffuse light
uniform float debugDepthRange; // world units mapped to white in the depth view
uniform float debugThicknessRangeMm; // millimetres mapped to white in the thickness view
uniform highp ivec4 maskBox;   // the subsurface pixels lie in [xy, zw) (device pixels)
uniform float scatteredShare;   // the share of the scattered light shown, the rest unblurred (the blur fading in: plan.fade)

varying vec2 vUv;

#include "common/finite.glsl"
#include "common/carriedDepth.glsl"

void main() {
	ivec2 pixel = ivec2( gl_FragCoord.xy );
	#if KEEP_BACKGROUND == 1 || WRITE_DEPTH == 1
		float depth = texelFetch( tDepth, pixel, 0 ).r;
	#endif
	#if KEEP_BACKGROUND == 1
		if ( depth == farDepth ) discard; // the scene drew nothing here
	#endif
	#if WRITE_DEPTH == 1
		gl_FragDepth = depth;
	#endif
	vec4 light = texelFetch( tColor, pixel, 0 );
	// The mask from the scattered light's alpha: the blur writes its centre's coverage there, 0 off
	// the mask and outside its box (cleared), as the diffuse alpha would say, in 8 B where the
	// diffuse is 16. Outside `maskBox` (the subsurface pixels' screen box) nothing is fetched. The
	// diffuse attachment is read only where its unblurred light is shown: the split's left, the
	// thickness and transmittance views.
	bool inBox = all( greaterThanEqual( pixel, maskBox.xy ) ) && all( lessThan( pixel, maskBox.zw ) );
	vec4 scattered = inBox ? texelFetch( tScattered, pixel, 0 ) : vec4( 0.0 );
	bool subsurface = sssCarriesSurface( scattered.a );
	bool showsUnscattered = gl_FragCoord.x < splitX || DEBUG_VIEW == DEBUG_VIEW_THICKNESS || DEBUG_VIEW == DEBUG_VIEW_TRANSMITTANCE;
	vec4 unscattered = subsurface && showsUnscattered ? texelFetch( tDiffuse, pixel, 0 ) : vec4( 0.0 );
	vec3 diffuse = gl_FragCoord.x < splitX ? unscattered.rgb : scattered.rgb;
	// The blur fades in where it starts to move light (src/3-blur/blurPlan.js): no step when it starts.
	if ( subsurface && scatteredShare < 1.0 && gl_FragCoord.x >= splitX ) diffuse = mix( texelFetch( tDiffuse, pixel, 0 ).rgb, diffuse, scatteredShare );
	vec3 colour;
	#if DEBUG_VIEW == DEBUG_VIEW_FINAL
		colour = light.rgb + ( subsurface ? diffuse : vec3( 0.0 ) );
	#elif DEBUG_VIEW == DEBUG_VIEW_DIFFUSE
		colour = subsurface ? diffuse : vec3( 0.0 );
	#elif DEBUG_VIEW == DEBUG_VIEW_SPECULAR
		colour = subsurface ? light.rgb : vec3( 0.0 );
	#elif DEBUG_VIEW == DEBUG_VIEW_DEPTH
		float viewDepth = texelFetch( tSurface, pixel, 0 ).r;
		colour = vec3( viewDepth > 0.0 ? 1.0 - viewDepth / debugDepthRange : 0.0 );
	#elif DEBUG_VIEW == DEBUG_VIEW_MASK
		colour = vec3( subsurface ? 1.0 : 0.0 );
	#elif DEBUG_VIEW == DEBUG_VIEW_THICKNESS
		colour = subsurface ? vec3( unscattered.r / debugThicknessRangeMm ) : vec3( 0.0 );
	#elif DEBUG_VIEW == DEBUG_VIEW_TRANSMITTANCE
		colour = subsurface ? unscattered.rgb : vec3( 0.0 );
	#else
		#error "DEBUG_VIEW is not one of src/4-compose/debugViews.js's views"
	#endif
	// Never hand NaN or Inf to tone mapping.
	if ( ! sssFinite( colour ) ) colour = vec3( 0.0 );
	gl_FragColor = vec4( colour, light.a );
	// Drawn to the screen (the composer's last pass), the light leaves as three draws any material
	// there, and so as a RenderPass in this place would: the renderer's tone mapping and output colour
	// space (the transparent objects drawn after this pass then blend over it, as under that
	// RenderPass). Into a render target three turns both off (NoToneMapping, linear), so the next
	// pass (OutputPass, an EffectPass) gets linear HDR as before.
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}
