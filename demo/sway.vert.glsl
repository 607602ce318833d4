	// A gust along the leaf's normal: each leaf bends more towards its tip (x runs from the stem to
	// the tip), the leaves out of phase by their length. Inserted after three's begin_vertex.
	transformed.z += 0.12 * position.x * position.x * sin( 1.7 * windTime + 2.3 * position.x );
