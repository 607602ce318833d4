// Reads a QuadrantEnergyLookup table (src/profiles/QuadrantEnergyLookup.js): float RGBA, texel (i, j)
// holding Q(x_i, x_j) = ∫_0^x_i ∫_0^x_j R dA with x_k = (k / (size - 1))^2 * range. Bilinear between
// texels in square-root coordinates (32-bit float filtering is an extension), held past the range,
// odd in each argument so that double differences give the energy of any rectangle.

vec3 sssQuadrantEnergy( const in sampler2D table, const in float aMm, const in float bMm, const in float rangeMm ) {
	int size = textureSize( table, 0 ).x;
	vec2 position = sqrt( clamp( abs( vec2( aMm, bMm ) ) / rangeMm, 0.0, 1.0 ) ) * float( size - 1 );
	ivec2 below = min( ivec2( position ), ivec2( size - 2 ) );
	vec2 fraction = position - vec2( below );
	vec3 bottom = mix( texelFetch( table, below, 0 ).rgb, texelFetch( table, below + ivec2( 1, 0 ), 0 ).rgb, fraction.x );
	vec3 top = mix( texelFetch( table, below + ivec2( 0, 1 ), 0 ).rgb, texelFetch( table, below + ivec2( 1, 1 ), 0 ).rgb, fraction.x );
	return sign( aMm ) * sign( bMm ) * mix( bottom, top, fraction.y );
}
