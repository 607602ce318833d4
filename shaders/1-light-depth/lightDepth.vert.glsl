// Stage 1 (light pass): linear depth seen from the light, and the surface's vertex normal and
// position in the light's view space for the fragment's entry cosine (lightDepth.frag.glsl).
// Three's chunks keep skinned, morphed, instanced and batched meshes in step with the main pass.
#include <common>
#include <uv_pars_vertex>
#include <batching_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>

varying vec3 vLightViewNormal;
varying vec3 vLightViewPosition; // its -z is the linear light depth (lightDepth.frag.glsl)

void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex> // an InstancedMesh's own morph influences (setMorphAt): without it the shader does not compile
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <clipping_planes_vertex>
	vLightViewNormal = transformedNormal;
	vLightViewPosition = mvPosition.xyz;
}
