// Stage 2 (material split), for a material whose own onBeforeCompile left out a point the split
// goes in at (src/2-scene-split/subsurfaceMaterial.js): its shading as three's, and the split's
// attachments (outputs.glsl) written 0, so that the program keeps them (a draw into the split call
// without an output for an active draw buffer is refused; unsplit.vert.glsl draws nothing there).
// The material's own main() was renamed sssMaterialMain before it.
#undef main
void main() {
	sssMaterialMain();
	sssDiffuseOutput = vec4( 0.0 );
	sssSurfaceOutput = vec4( 0.0 );
}
