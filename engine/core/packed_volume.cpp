#include "packed_volume.h"

#include <Imath/half.h>

#include <algorithm>

namespace voxflame::core {

std::uint16_t floatToHalf(float value) {
  return Imath::half(value).bits();
}

float halfToFloat(std::uint16_t bits) {
  Imath::half half;
  half.setBits(bits);
  return static_cast<float>(half);
}

void packVolume(const VolumeSnapshot& snapshot, PackedVolume& out) {
  const GridGeometry& g = snapshot.geometry;
  out.geometry = g;
  out.version = snapshot.version;
  out.generation = snapshot.generation;
  out.points = snapshot.points;
  out.maxDensity = snapshot.maxDensity;
  const std::size_t voxels = g.voxelCount();
  out.texels.resize(4 * voxels);
  out.density.resize(voxels);
  out.brickCount = (g.size + (kBrickSize - 1)) / kBrickSize;
  out.occupancy.assign(static_cast<std::size_t>(out.brickCount.x) * out.brickCount.y * out.brickCount.z, 0);
  // The mean over the inside voxels first: it is the normalisation of every texel.
  double densitySum = 0.0;
  std::size_t occupied = 0;
  for (const float density : snapshot.density)
    if (density > 0.0f) {
      densitySum += density;
      ++occupied;
    }
  out.meanDensity = occupied ? static_cast<float>(densitySum / static_cast<double>(occupied)) : 0.0f;
  out.insideVoxels = static_cast<double>(snapshot.insideVoxels ? snapshot.insideVoxels : occupied);
  out.referenceDensity = out.insideVoxels > 0.0 && densitySum > 0.0 ? densitySum / out.insideVoxels : 1.0;
  out.texelDensity = static_cast<float>(out.referenceDensity);
  const float inverseScale = 1.0f / out.texelDensity;
  // Half floats end at 65504; a voxel that much denser than the mean is saturated, not infinite.
  constexpr float kLargestHalf = 65504.0f;
  auto markBricks = [&](int i, int j, int k) {
    // A voxel's density reaches samples up to one voxel away (trilinear filtering), so every
    // brick within one voxel of it must be marched.
    const int i0 = std::max(0, i - 1) / kBrickSize, i1 = std::min(g.size.x - 1, i + 1) / kBrickSize;
    const int j0 = std::max(0, j - 1) / kBrickSize, j1 = std::min(g.size.y - 1, j + 1) / kBrickSize;
    const int k0 = std::max(0, k - 1) / kBrickSize, k1 = std::min(g.size.z - 1, k + 1) / kBrickSize;
    for (int bk = k0; bk <= k1; ++bk)
      for (int bj = j0; bj <= j1; ++bj)
        for (int bi = i0; bi <= i1; ++bi)
          out.occupancy[static_cast<std::size_t>(bi) + static_cast<std::size_t>(out.brickCount.x) *
                                                           (bj + static_cast<std::size_t>(out.brickCount.y) * bk)] = 1;
  };
  constexpr std::uint16_t kZero = 0;
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const std::size_t v = g.index(i, j, k);
        std::uint16_t* texel = &out.texels[4 * v];
        const float density = snapshot.density[v];
        if (density <= 0.0f) {
          texel[0] = texel[1] = texel[2] = texel[3] = kZero;
          out.density[v] = kZero;
          continue;
        }
        const float weight = std::min(density * inverseScale, kLargestHalf);
        const std::uint8_t* rgba = &snapshot.rgba[4 * v];
        for (int c = 0; c < 3; ++c) texel[c] = floatToHalf(weight * static_cast<float>(rgba[c]) * (1.0f / 255.0f));
        texel[3] = floatToHalf(weight);
        out.density[v] = texel[3];
        markBricks(i, j, k);
      }
  out.coarseCount = (out.brickCount + (kCoarseBricks - 1)) / kCoarseBricks;
  out.coarseOccupancy.assign(static_cast<std::size_t>(out.coarseCount.x) * out.coarseCount.y * out.coarseCount.z, 0);
  for (int k = 0; k < out.brickCount.z; ++k)
    for (int j = 0; j < out.brickCount.y; ++j)
      for (int i = 0; i < out.brickCount.x; ++i)
        if (out.occupancy[static_cast<std::size_t>(i) + static_cast<std::size_t>(out.brickCount.x) *
                                                            (j + static_cast<std::size_t>(out.brickCount.y) * k)])
          out.coarseOccupancy[static_cast<std::size_t>(i / kCoarseBricks) +
                              static_cast<std::size_t>(out.coarseCount.x) *
                                  (j / kCoarseBricks +
                                   static_cast<std::size_t>(out.coarseCount.y) * (k / kCoarseBricks))] = 1;
}

}  // namespace voxflame::core
