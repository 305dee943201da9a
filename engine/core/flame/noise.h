// Noise that flame variations share: 3D simplex noise (Perlin's, as Stefan Gustavson describes it,
// hashed as slobo777's Hexes and Crackle plugins hash it), which crackle uses to jitter its cell
// centres. Its tables are voxflame's own (flame_noise.cpp says why).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace voxflame::core {

// The tables simplexNoise3D hashes with, for a copy elsewhere (the GPU's crackle): `hash` a
// permutation of 0–1023, gradient g (a unit vector) at gradients[3g], [3g + 1], [3g + 2].
struct SimplexNoiseTables {
  static constexpr std::size_t kSize = 1024;
  std::array<std::uint16_t, kSize> hash{};
  std::array<double, kSize * 3> gradients{};
};
const SimplexNoiseTables& simplexNoiseTables();

// 3D simplex noise at (x, y, z), roughly in [−1, 1]; 0 at every lattice point.
double simplexNoise3D(double x, double y, double z);

// One step of slobo777's crackle (JWildfire's CrackleFunc, which dc_crackle_wf extends): the cells
// form a square grid of side halfSize whose centres move by distort · simplex noise of the cell's
// coordinates (noise slice `slice`); the point u is pulled towards the centre C of its Voronoi cell
// to C + (u − C) L^power · scale / L, L the Voronoi distance of u from C (0 at C, 1 on the edge).
struct CrackleStep {
  double x, y;      // the pulled point
  double distance;  // L
};
CrackleStep crackleStep(double ux, double uy, double halfSize, double distort, double slice, double power,
                        double scale);

}  // namespace voxflame::core
