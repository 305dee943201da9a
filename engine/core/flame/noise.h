// Noise that flame variations share: 3D simplex noise (Perlin's, as Stefan Gustavson describes it,
// hashed as slobo777's Hexes and Crackle plugins hash it), which crackle uses to jitter its cell
// centres. Its tables are voxflame's own (flame_noise.cpp says why).
#pragma once

namespace voxflame::core {

// 3D simplex noise at (x, y, z), roughly in [−1, 1]; 0 at every lattice point.
double simplexNoise3D(double x, double y, double z);

}  // namespace voxflame::core
