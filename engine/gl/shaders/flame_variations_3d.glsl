// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_3d_more.cpp, variations_3d_quaternion.cpp, variations_3d_shapes.cpp, variations_3d_sum.cpp, variations_apophysis.cpp, variations_fractorium.cpp and the rest of variations_flam3.cpp and variations_plugins.cpp
// (engine/core/flame/), in float.
