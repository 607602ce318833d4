// Stage 1 (light pass): writes the linear light depth (world units) and the entry cosine into a
// two-channel float target. The target is cleared to 0, which the transmittance lookup reads as
// "no surface".
// The entry cosine, |N·L| at the surface the light meets first, is the share of the light's
// irradiance that enters there (Dachsbacher and Stamminger 2003's translucent shadow maps store
// the irradiance for the same reason): where the light grazes the surface, near the terminator as
// the light sees it, little enters, and the transmittance behind it is that much weaker. |N·L|:
// the pass draws both sides, and an open shell's back face lets in as much as its front.
// A cut-out material's alpha test and clipping planes apply as in its own pass (three defines
// USE_MAP, USE_ALPHAMAP and USE_ALPHATEST from the fields LightDepthTarget copies).
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <clipping_planes_pars_fragment>

#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	uniform float opacity;
#endif

varying vec3 vLightViewNormal;   // light view space, not normalised
varying vec3 vLightViewPosition; // light view space

void main() {
	#include <clipping_planes_fragment>
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		vec4 diffuseColor = vec4( 1.0, 1.0, 1.0, opacity );
		#include <map_fragment>
		#include <alphamap_fragment>
		#include <alphatest_fragment>
	#endif
	// Towards the light: the view axis for a directional light (orthographic), the eye for a spot.
	vec3 toLight = isOrthographic ? vec3( 0.0, 0.0, 1.0 ) : normalize( - vLightViewPosition );
	float normalLength = length( vLightViewNormal );
	// A mesh without normals lets the whole light in, as before the entry cosine.
	float entry = normalLength > 0.0 ? abs( dot( vLightViewNormal / normalLength, toLight ) ) : 1.0;
	// Distance along the light's view axis (world units), for perspective and orthographic lights
	// alike: linear, unlike the depth buffer, so thickness is a plain difference (Jimenez et al. 2010).
	gl_FragColor = vec4( - vLightViewPosition.z, entry, 0.0, 1.0 );
}
