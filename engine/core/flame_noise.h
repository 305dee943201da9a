// Noise that flame variations share: slobo777's simplex noise (Perlin's simplex noise as Stefan
// Gustavson describes it, with the plugin's own hash and gradient tables), which the Crackle plugin
// uses to jitter its cell centres. A variation that uses it must get the plugin's exact values, or
// its cells fall elsewhere than in the flame's author's picture.
#pragma once

namespace voxflame::core {

// 3D simplex noise at (x, y, z), roughly in [−1, 1]; 0 at every lattice point.
double simplexNoise3D(double x, double y, double z);

}  // namespace voxflame::core
