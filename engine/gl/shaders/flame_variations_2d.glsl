// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_2d_a.cpp, variations_2d_b.cpp and variations_2d_c.cpp
// (engine/core/flame/), in float.
