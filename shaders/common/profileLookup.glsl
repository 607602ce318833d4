// Reads a ProfileLookup table (src/profiles/ProfileLookup.js): float RGBA, one row per function of the
// diffusion profile, texel i of a row holding x = (i / (size - 1))^2 * range (square-root spacing:
// dense near 0, where the narrow Gaussians change fastest), linearly interpolated here because
// 32-bit float filtering is an extension. Past the range the row's last value holds.
//   row 0: transmittance T(d), d in profile mm
//   row 1: G(x), the marginal's integral from 0 to x (0 .. 0.5), x in profile mm

vec3 sssReadProfile( const in sampler2D table, const in int row, const in float xMm, const in float rangeMm ) {
	int size = textureSize( table, 0 ).x;
	float position = sqrt( clamp( xMm / rangeMm, 0.0, 1.0 ) ) * float( size - 1 );
	int below = min( int( position ), size - 2 );
	float fraction = position - float( below );
	vec3 a = texelFetch( table, ivec2( below, row ), 0 ).rgb;
	vec3 b = texelFetch( table, ivec2( below + 1, row ), 0 ).rgb;
	return mix( a, b, fraction );
}
