// Stage 1 (light pass): writes the linear light depth (world units) into a single-channel float
// target. The target is cleared to 0, which the transmittance lookup reads as "no surface".
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

varying float vLightDepth;

void main() {
	#include <clipping_planes_fragment>
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		vec4 diffuseColor = vec4( 1.0, 1.0, 1.0, opacity );
		#include <map_fragment>
		#include <alphamap_fragment>
		#include <alphatest_fragment>
	#endif
	gl_FragColor = vec4( vLightDepth, 0.0, 0.0, 1.0 );
}
