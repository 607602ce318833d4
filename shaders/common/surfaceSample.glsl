// Reading the multi-target's surface (r: linear view depth, g: world units per profile mm) and
// diffuse light at a texel. Without SSS_COVERAGE they are read as stored. With SSS_COVERAGE (the
// multi-target was rendered with MSAA and resolved by averaging) a texel holds the average of its
// samples, and samples off subsurface surfaces hold 0: its diffuse alpha is the coverage c, and
// colour, depth and width are c times the covered samples' values. Dividing by c gives them back
// exactly where one surface meets the background or an ordinary material (silhouettes); where two
// subsurface surfaces share a pixel, their coverage-weighted mean. Needs `tSurface`, `tDiffuse`.

// Divides a premultiplied value by its coverage (a no-op without SSS_COVERAGE).
vec2 sssUncovered( const in vec2 value, const in float coverage ) {
	#if SSS_COVERAGE == 1
		return coverage > 0.0 ? value / coverage : vec2( 0.0 );
	#else
		return value;
	#endif
}

vec2 sssSurfaceAt( const in ivec2 texel ) {
	vec2 surface = texelFetch( tSurface, texel, 0 ).rg;
	#if SSS_COVERAGE == 1
		surface = sssUncovered( surface, texelFetch( tDiffuse, texel, 0 ).a );
	#endif
	return surface;
}
