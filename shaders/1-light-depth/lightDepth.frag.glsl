// Stage 1 (light pass): writes the linear light depth (world units) into a single-channel float
// target. The target is cleared to 0, which the transmittance lookup reads as "no surface".
#include <clipping_planes_pars_fragment>

varying float vLightDepth;

void main() {
	#include <clipping_planes_fragment>
	gl_FragColor = vec4( vLightDepth, 0.0, 0.0, 1.0 );
}
