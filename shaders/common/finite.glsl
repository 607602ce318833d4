// True when no component is NaN or Inf. Every stage checks its light with it: a non-finite value
// would spread through a blur, and must never reach tone mapping (a NaN pixel is not a NaN frame).
bool sssFinite( const in vec3 c ) {
	return ! ( any( isnan( c ) ) || any( isinf( c ) ) );
}
