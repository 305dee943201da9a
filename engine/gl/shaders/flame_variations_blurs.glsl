// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_blurs.cpp, variations_blurs_more.cpp, variations_blur_b2.cpp and variations_truchet.cpp
// (engine/core/flame/), in float.
