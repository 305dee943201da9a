// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_2d_d.cpp, variations_2d_m.cpp and variations_2d_s.cpp
// (engine/core/flame/), in float.
