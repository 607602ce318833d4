// Stage 2 (material split), for a material whose own onBeforeCompile left out a point the split
// goes in at (src/2-scene-split/subsurfaceMaterial.js): drawn as three draws it, in the scene split's
// first call, and not at all in the split call (its triangles beyond the far plane, as
// hidden.vert.glsl's). The material's own main() was renamed sssMaterialMain before it.
#undef main
uniform bool sssSplit;
void main() {
	if ( sssSplit ) {
		gl_Position = vec4( 0.0, 0.0, 2.0, 1.0 );
		return;
	}
	sssMaterialMain();
}
