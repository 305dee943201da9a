// Simplex noise for flame variations (crackle's cell jitter), with hash and gradient tables of
// voxflame's own: a permutation of 0–1023 drawn once from a fixed seed, and 1024 unit gradients
// spread evenly over the sphere (a Fibonacci lattice) in that permuted order. The Crackle plugin
// ships tables of its own; they are its authors' data and are not copied here, so a crackle
// flame's cells have the plugin's size, spread and jitter but not the very same places.
#include "core/flame/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <utility>

namespace voxflame::core {

namespace {

constexpr std::size_t kTableSize = SimplexNoiseTables::kSize;

// splitmix64 (Steele, Lea and Flood 2014): a fixed, well-mixed sequence for the shuffle.
std::uint64_t splitMix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

const SimplexNoiseTables& tables() {
  static const SimplexNoiseTables built = [] {
    SimplexNoiseTables t;
    for (std::size_t i = 0; i < kTableSize; ++i) t.hash[i] = static_cast<std::uint16_t>(i);
    std::uint64_t state = 0x766F78666C616D65ull;  // "voxflame"
    for (std::size_t i = kTableSize - 1; i > 0; --i) std::swap(t.hash[i], t.hash[splitMix(state) % (i + 1)]);
    // Point k of the Fibonacci lattice: z evenly spaced in (−1, 1), longitude turning by the golden
    // angle; gradient g is the lattice point the permutation sends g to, so neighbouring hash values
    // do not get neighbouring directions.
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t g = 0; g < kTableSize; ++g) {
      const double k = static_cast<double>(t.hash[g]);
      const double z = 1.0 - (2.0 * k + 1.0) / static_cast<double>(kTableSize);
      const double ring = std::sqrt(1.0 - z * z);
      t.gradients[g * 3 + 0] = ring * std::cos(goldenAngle * k);
      t.gradients[g * 3 + 1] = ring * std::sin(goldenAngle * k);
      t.gradients[g * 3 + 2] = z;
    }
    return t;
  }();
  return built;
}

std::int64_t lattice(double v) {
  const double f = std::floor(v);
  if (!(f == f)) return 0;
  if (f >= 2147483647.0) return 2147483647;
  if (f <= -2147483648.0) return -2147483648LL;
  return static_cast<std::int64_t>(f);
}

int hashed(std::int64_t index) {
  return tables().hash[static_cast<std::size_t>(index & 0x3ff)];
}

}  // namespace

const SimplexNoiseTables& simplexNoiseTables() {
  return tables();
}

double simplexNoise3D(double x, double y, double z) {
  constexpr double kSkew = 1.0 / 3.0, kUnskew = 1.0 / 6.0;
  const double skew = (x + y + z) * kSkew;
  const std::int64_t i = lattice(x + skew), j = lattice(y + skew), k = lattice(z + skew);
  const double t = static_cast<double>(i + j + k) * kUnskew;
  // The point's offsets from the four corners of its simplex (a tetrahedron), in input space.
  double corner[4][3];
  corner[0][0] = x - (static_cast<double>(i) - t);
  corner[0][1] = y - (static_cast<double>(j) - t);
  corner[0][2] = z - (static_cast<double>(k) - t);
  const double x0 = corner[0][0], y0 = corner[0][1], z0 = corner[0][2];
  // Which simplex of the skewed cube: the order of the offsets decides the second and third corner.
  int i1, j1, k1, i2, j2, k2;
  if (x0 >= y0) {
    if (y0 >= z0) {
      i1 = 1, j1 = 0, k1 = 0, i2 = 1, j2 = 1, k2 = 0;
    } else if (x0 >= z0) {
      i1 = 1, j1 = 0, k1 = 0, i2 = 1, j2 = 0, k2 = 1;
    } else {
      i1 = 0, j1 = 0, k1 = 1, i2 = 1, j2 = 0, k2 = 1;
    }
  } else if (y0 < z0) {
    i1 = 0, j1 = 0, k1 = 1, i2 = 0, j2 = 1, k2 = 1;
  } else if (x0 < z0) {
    i1 = 0, j1 = 1, k1 = 0, i2 = 0, j2 = 1, k2 = 1;
  } else {
    i1 = 0, j1 = 1, k1 = 0, i2 = 1, j2 = 1, k2 = 0;
  }
  const int step[4][3] = {{0, 0, 0}, {i1, j1, k1}, {i2, j2, k2}, {1, 1, 1}};
  double total = 0.0;
  for (int c = 0; c < 4; ++c) {
    if (c > 0) {
      for (int axis = 0; axis < 3; ++axis)
        corner[c][axis] = corner[0][axis] - step[c][axis] + static_cast<double>(c) * kUnskew;
    }
    // The plugin's hashing: three nested look-ups of the corner's lattice coordinates mod 1024.
    const int gradient =
        hashed((i & 0x3ff) + step[c][0] + hashed((j & 0x3ff) + step[c][1] + hashed((k & 0x3ff) + step[c][2])));
    double falloff = 0.6 - corner[c][0] * corner[c][0] - corner[c][1] * corner[c][1] - corner[c][2] * corner[c][2];
    if (falloff > 0.0) {
      const double* g = &tables().gradients[static_cast<std::size_t>(gradient) * 3];
      falloff *= falloff;
      total += falloff * falloff * (g[0] * corner[c][0] + g[1] * corner[c][1] + g[2] * corner[c][2]);
    }
  }
  return 32.0 * total;
}

namespace {

// Crackle's cell centres (the plugin's `position`): the cell (cx, cy) jittered by two noises whose
// x and y cross over, as in the plugin, so they do not correlate.
struct CrackleCells {
  double halfSize, distort, slice;
  void centre(double cx, double cy, double* out) const {
    const double nx = simplexNoise3D(cx * 2.5, cy * 2.5, slice * 2.5);
    const double ny = simplexNoise3D(cy * 2.5 + 30.2, cx * 2.5 - 12.1, slice * 2.5 + 19.8);
    out[0] = (cx + distort * nx) * halfSize;
    out[1] = (cy + distort * ny) * halfSize;
  }
  // The 3×3 block of centres around cell (cx, cy), column by column (x outer, y inner).
  void block(double cx, double cy, double (*centres)[2]) const {
    int k = 0;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) centre(cx + di, cy + dj, centres[k++]);
  }
};

// Java's (int) floor(v), which saturates, as a double.
double javaFloorToInt(double v) {
  const double f = std::floor(v);
  if (!(f == f)) return 0.0;
  return std::clamp(f, -2147483648.0, 2147483647.0);
}

}  // namespace

CrackleStep crackleStep(double ux, double uy, double halfSize, double distort, double slice, double power,
                        double scale) {
  const CrackleCells cells{halfSize, distort, slice};
  double cx = javaFloorToInt(ux / halfSize), cy = javaFloorToInt(uy / halfSize);
  double centres[9][2];
  cells.block(cx, cy, centres);
  // Re-centre the block on the nearest centre, so that its cell is surrounded on all sides.
  int nearest = 0;
  double nearestD2 = 1.0e100;
  for (int k = 0; k < 9; ++k) {
    const double dx = centres[k][0] - ux, dy = centres[k][1] - uy, d2 = dx * dx + dy * dy;
    if (d2 < nearestD2) nearestD2 = d2, nearest = k;
  }
  if (nearest != 4) {
    cx += nearest / 3 - 1;
    cy += nearest % 3 - 1;
    cells.block(cx, cy, centres);
  }
  // Voronoi distance from centre 4: the largest ratio over its neighbours (1 on a shared edge).
  double distance = -1.0e100;
  for (int k = 0; k < 9; ++k) {
    if (k == 4) continue;
    const double px = centres[k][0] - centres[4][0], py = centres[k][1] - centres[4][1];
    const double ratio = px == 0.0 && py == 0.0
                             ? 1.0
                             : 2.0 * ((ux - centres[4][0]) * px + (uy - centres[4][1]) * py) / (px * px + py * py);
    distance = std::max(distance, ratio);
  }
  const double pull = std::pow(distance + 1e-100, power) * scale / (distance + 1e-100);
  return {(ux - centres[4][0]) * pull + centres[4][0], (uy - centres[4][1]) * pull + centres[4][1], distance};
}

}  // namespace voxflame::core
