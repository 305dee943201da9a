// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_jwildfire*.cpp
// (engine/core/flame/), in float.
