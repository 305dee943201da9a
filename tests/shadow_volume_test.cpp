#include <gtest/gtest.h>

#include <cmath>

#include "core/shadow_volume.h"

using namespace voxflame::core;

namespace {
PackedVolume uniformVolume(int n) {
  VolumeSnapshot snapshot;
  snapshot.geometry.size = glm::ivec3(n);
  snapshot.geometry.voxelSize = 1.0;
  snapshot.density.assign(snapshot.geometry.voxelCount(), 4.0f);
  snapshot.rgba.assign(4 * snapshot.geometry.voxelCount(), 255);
  snapshot.maxDensity = 4.0f;
  PackedVolume volume;
  packVolume(snapshot, volume);
  return volume;
}
}  // namespace

TEST(ShadowVolume, AxisLightFollowsBeerLambert) {
  const PackedVolume volume = uniformVolume(32);
  ShadowVolume shadow;
  // Uniform density is the mean density (relative 1) and a voxel is 1/32 of the grid's side, so
  // an extinction of 1.6 per unit of column density is 0.05 per voxel.
  const double sigma = 0.05;
  computeShadowVolume(volume, {0.0, 1.0, 0.0}, sigma * 32.0, 1, shadow);
  ASSERT_EQ(shadow.size, glm::ivec3(32));
  for (int j = 0; j < 32; ++j) {
    // Light enters at the top (y = 32) and reaches the centre of cell j after 32 − j − 0.5 voxels.
    const double expected = std::exp(-sigma * (32 - j - 0.5));
    const double actual = shadow.transmittance[16 + 32 * (j + 32 * 16)] / 255.0;
    EXPECT_NEAR(actual, expected, 0.01) << "row " << j;
  }
}

TEST(ShadowVolume, DiagonalLightDarkensAwayFromTheLight) {
  const PackedVolume volume = uniformVolume(24);
  ShadowVolume shadow;
  computeShadowVolume(volume, lightDirection(45.0, 40.0), 0.1, 2, shadow);
  ASSERT_EQ(shadow.size, glm::ivec3(12));
  auto at = [&](int i, int j, int k) { return shadow.transmittance[i + 12 * (j + 12 * k)]; };
  // The light sits toward +x, +y, +z: the far corner is the darkest, the near one the brightest.
  EXPECT_GT(at(11, 11, 11), at(6, 6, 6));
  EXPECT_GT(at(6, 6, 6), at(0, 0, 0));
}

// A shadow job for a volume no longer shown is stopped (the user began to drag): the work ends at
// the next slice and says so, and an unstopped one says it finished.
TEST(ShadowVolume, AStopEndsTheWorkAndIsReported) {
  const PackedVolume volume = uniformVolume(16);
  ShadowVolume shadow;
  std::stop_source source;
  EXPECT_TRUE(computeShadowVolume(volume, {0.0, 1.0, 0.0}, 0.1, 1, shadow, source.get_token()));
  EXPECT_EQ(shadow.transmittance.size(), 16u * 16u * 16u);
  source.request_stop();
  ShadowVolume stopped;
  EXPECT_FALSE(computeShadowVolume(volume, {0.0, 1.0, 0.0}, 0.1, 1, stopped, source.get_token()));
}
