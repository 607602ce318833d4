// Stage 1 (light pass): linear depth seen from the light.
// Three's chunks keep skinned, morphed, instanced and batched meshes in step with the main pass.
#include <common>
#include <uv_pars_vertex>
#include <batching_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>

varying float vLightDepth;

void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <clipping_planes_vertex>
	// Distance along the light's view axis (world units), for perspective and orthographic lights
	// alike: linear, unlike the depth buffer, so thickness is a plain difference (Jimenez et al. 2010).
	vLightDepth = -mvPosition.z;
}
