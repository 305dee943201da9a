// flam3's last stage (flame/image.h) and the points method's projection (point_renderer.h),
// against hand-computed expectations.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera.h"
#include "core/flame/image.h"
#include "core/packed_volume.h"
#include "core/point_renderer.h"

using namespace voxflame;

namespace {

core::ToneMapSettings plainTone() {
  core::ToneMapSettings tone;
  tone.brightness = 1.0;
  tone.gamma = 1.0;
  tone.gammaThreshold = 0.0;
  tone.vibrancy = 1.0;
  tone.background = glm::vec3(0.0f);
  return tone;
}

double channelSum(const core::DensityImage& image, int channel) {
  double sum = 0.0;
  for (std::size_t i = static_cast<std::size_t>(channel); i < image.values.size(); i += 4) sum += image.values[i];
  return sum;
}

// A cubic grid of unit voxels around the origin.
core::GridGeometry cubeGrid(int size) {
  core::GridGeometry g;
  g.size = glm::ivec3(size);
  g.origin = glm::dvec3(-0.5 * size);
  g.voxelSize = 1.0;
  return g;
}

// Looking down −z from +z, orthographic, `height` world units tall.
core::CameraFrame frontCamera(const core::GridGeometry& grid, double height) {
  core::CameraSettings settings;
  settings.azimuthDeg = 0.0;
  settings.elevationDeg = 0.0;
  settings.projection = core::Projection::Orthographic;
  const double radius = 0.5 * glm::length(grid.box().extent());
  settings.orthoHeight = height / radius;
  return core::orbitCamera(settings, grid.box(), 1.0);
}

}  // namespace

TEST(FlameImage, DensityEstimationLeavesADenseRegionAndSpreadsALoneHit) {
  core::DensityImage image;
  image.resize(64, 64);
  image.hitsPerUnitDensity = 1e4;  // D = 1 is ten thousand points per pixel
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 24; ++x) {
      float* p = image.at(x, y);
      p[0] = p[1] = p[2] = p[3] = 1.0f;
    }
  image.at(48, 32)[3] = 1e-4f;  // one point, alone
  image.at(48, 32)[0] = 1e-4f;
  core::ToneMapSettings tone = plainTone();
  core::DensityImage estimated;
  core::estimateDensity(image, tone, 1, estimated);
  const double dense = core::logDensity(1.0, tone);
  // Deep inside the dense block nothing moves: its kernel is a single pixel.
  for (int y = 8; y < 56; y += 8) EXPECT_NEAR(estimated.at(12, y)[3], dense, 1e-5 * dense) << y;
  // The lone hit keeps its total but spreads over a kernel of about estimator_radius pixels.
  const double lone = core::logDensity(1e-4, tone);
  double total = 0.0;
  for (int y = 16; y < 48; ++y)
    for (int x = 34; x < 64; ++x) total += estimated.at(x, y)[3];
  EXPECT_NEAR(total, lone, 1e-3 * lone);
  EXPECT_LT(estimated.at(48, 32)[3], 0.1 * lone);
  EXPECT_GT(estimated.at(48 + 5, 32)[3], 0.0f);
  EXPECT_GT(estimated.at(48, 32 - 5)[3], 0.0f);
  EXPECT_EQ(estimated.at(48 + 12, 32)[3], 0.0f);  // beyond radius 9 + 1
  // Radius 0 turns it off: each pixel keeps its own log density.
  tone.estimatorRadius = 0.0;
  core::estimateDensity(image, tone, 1, estimated);
  EXPECT_NEAR(estimated.at(48, 32)[3], lone, 1e-6 * lone);
  EXPECT_EQ(estimated.at(49, 32)[3], 0.0f);
}

// flam3-render's density estimation (filters.c, rect.c) normalises a kernel of width h over every
// offset within h but spreads only over offsets of at most ⌈h⌉ − 1 pixels along each axis: the
// narrowest kernel, of width 1 where the density is highest, keeps its pixel's value divided by
// 1 + 4 e^(−2 · 1.5²) and drops the rest. The flat view does as flam3 does; voxflame's own finish
// keeps every pixel's total.
TEST(FlameImage, Flam3sDensityEstimationDropsTheRingOfAWholeWidthKernel) {
  core::DensityImage image;
  image.resize(48, 48);
  image.hitsPerUnitDensity = 1.0;  // D is the hit count
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      float* p = image.at(x, y);
      p[0] = p[1] = p[2] = p[3] = 5000.0f;  // dense: the narrowest kernel everywhere
    }
  image.wholeHits = true;
  core::ToneMapSettings tone = plainTone();
  tone.estimatorRadius = 9.0;
  tone.estimatorMinimum = 0.0;
  tone.estimatorCurve = 0.4;
  core::DensityImage ours, flam3s;
  core::estimateDensity(image, tone, 1, ours);
  core::estimateDensity(image, tone, 1, flam3s, true);
  const double dense = core::logDensity(5000.0, tone);
  const double kept = 1.0 / (1.0 + 4.0 * std::exp(-2.0 * 1.5 * 1.5));
  EXPECT_NEAR(ours.at(24, 24)[3], dense, 1e-4 * dense);
  EXPECT_NEAR(flam3s.at(24, 24)[3], kept * dense, 1e-4 * dense);
  // A lone point's kernel (width 10, the widest) spreads all it has in both.
  core::DensityImage lone;
  lone.resize(48, 48);
  lone.hitsPerUnitDensity = 1.0;
  lone.wholeHits = true;
  lone.at(24, 24)[3] = lone.at(24, 24)[0] = 1.0f;
  core::estimateDensity(lone, tone, 1, ours);
  core::estimateDensity(lone, tone, 1, flam3s, true);
  double oursTotal = 0.0, flam3Total = 0.0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      oursTotal += ours.at(x, y)[3];
      flam3Total += flam3s.at(x, y)[3];
    }
  const double one = core::logDensity(1.0, tone);
  EXPECT_NEAR(oursTotal, one, 1e-4 * one);
  EXPECT_NEAR(flam3Total, one, 1e-4 * one);
  EXPECT_EQ(flam3s.at(24 + 10, 24)[3], 0.0f);  // ⌈10⌉ − 1 = 9 pixels at most
}

TEST(FlameImage, SpatialFilterKeepsTheTotalAndDownsamples) {
  core::DensityImage image;
  image.resize(40, 20);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) image.at(x, y)[3] = 1.0f;
  core::DensityImage filtered;
  core::spatialFilter(image, 2, 0.5, filtered);
  ASSERT_EQ(filtered.width, 20);
  ASSERT_EQ(filtered.height, 10);
  // A uniform image stays uniform away from the edges (the filter is normalised).
  EXPECT_NEAR(filtered.at(10, 5)[3], 1.0f, 1e-5f);
}

TEST(FlameImage, BrightnessDoesNotDependOnSupersampling) {
  // The same density at oversample 1 and 3 finishes to the same pixels.
  core::DensityImage one, three;
  one.resize(10, 10);
  three.resize(30, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x) {
      float* p = three.at(x, y);
      p[0] = p[3] = 0.3f;
      if (x < 10 && y < 10) {
        p = one.at(x, y);
        p[0] = p[3] = 0.3f;
      }
    }
  core::FinishSettings settings;
  settings.tone = plainTone();
  settings.tone.estimatorRadius = 0.0;
  settings.oversample = 1;
  const core::FinishedImage a = core::finishImage(one, settings);
  settings.oversample = 3;
  const core::FinishedImage b = core::finishImage(three, settings);
  EXPECT_NEAR(a.image.at(5, 5)[0], b.image.at(5, 5)[0], 1e-4f);
  EXPECT_GT(a.image.at(5, 5)[0], 0.1f);
}

TEST(FlameImage, RelativeRmseOfIdenticalAndDifferentImages) {
  core::ImageRGBA a;
  a.width = 4;
  a.height = 1;
  a.pixels = {0.5f, 0.5f, 0.5f, 1, 0.5f, 0.5f, 0.5f, 1, 0.5f, 0.5f, 0.5f, 1, 0.5f, 0.5f, 0.5f, 1};
  EXPECT_DOUBLE_EQ(core::relativeLuminanceRmse(a, a, 1.0), 0.0);
  core::ImageRGBA b = a;
  for (int c = 0; c < 3; ++c) b.pixels[static_cast<std::size_t>(c)] = 1.0f;  // one pixel doubled
  // Differences 0.5, 0, 0, 0 against a mean of 0.5: RMS 0.25, relative 0.5.
  EXPECT_NEAR(core::relativeLuminanceRmse(b, a, 1.0), 0.5, 1e-6);
}

TEST(PointRenderer, ASinglePointRendersAsOneSmoothSpot) {
  const core::GridGeometry grid = cubeGrid(32);
  core::PointProjection projection;
  projection.grid = grid;
  projection.camera = frontCamera(grid, 32.0);
  projection.width = projection.height = 65;
  projection.totalPoints = 1.0;
  projection.insideVoxels = 32.0 * 32 * 32;
  core::PointProjector projector(projection, 1);
  const float x = 16.0f, y = 16.0f, z = 16.0f;  // the grid's centre, projected to the middle pixel
  const std::uint32_t white = 0xffffffu;
  projector.consume(0, {&x, &y, &z, &white, 1});
  const core::DensityImage density = projector.merge();
  EXPECT_NEAR(channelSum(density, 3), density.at(32, 32)[3], 1e-6);
  // One point is one hit: density estimation spreads it over a disc of about nine pixels.
  core::FinishSettings settings;
  settings.tone = plainTone();
  const core::FinishedImage image = core::finishImage(density, settings);
  auto at = [&](int dx, int dy) { return image.alpha[static_cast<std::size_t>((32 + dy) * 65 + 32 + dx)]; };
  EXPECT_GT(at(0, 0), 0.0f);
  // Monotonic from the centre outwards (no ring), the same in every direction, round not square.
  for (int r = 0; r < 8; ++r) {
    EXPECT_GE(at(r, 0), at(r + 1, 0)) << r;
    EXPECT_NEAR(at(r, 0), at(0, r), 1e-6f) << r;
    EXPECT_NEAR(at(-r, 0), at(0, -r), 1e-6f) << r;
  }
  EXPECT_GT(at(6, 0), 0.0f);
  EXPECT_GT(at(2, 2), at(3, 0));          // at radius 2.83 brighter than at radius 3
  EXPECT_EQ(at(9, 9), 0.0f);              // the corner of the kernel's square stays dark
  EXPECT_LT(at(0, 0), 20.0f * at(4, 0));  // a soft spot, not a lone bright pixel
}

TEST(PointRenderer, TransmittanceDimsAPointBehindASlabByBeerLambert) {
  // A slab of relative density 4 and 4 voxels thick (z 20..23) in a 32³ grid, in front of points
  // deeper in the grid as seen from +z.
  core::VolumeSnapshot snapshot;
  snapshot.geometry = cubeGrid(32);
  const std::size_t voxels = snapshot.geometry.voxelCount();
  snapshot.density.assign(voxels, 0.0f);
  snapshot.rgba.assign(4 * voxels, 255);
  for (int k = 20; k < 24; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) snapshot.density[snapshot.geometry.index(i, j, k)] = 4.0f;
  snapshot.maxDensity = 4.0f;
  snapshot.insideVoxels = voxels;  // mean density over the mesh: 4 × 4 / 32 = 0.5
  core::PackedVolume volume;
  core::packVolume(snapshot, volume);
  ASSERT_NEAR(volume.referenceDensity, 0.5, 1e-9);
  const core::CameraFrame camera = frontCamera(snapshot.geometry, 32.0);
  const double absorption = 2.0;
  const core::ViewTransmittance t = core::buildViewTransmittance(volume, camera, absorption, 16, 16, 64);
  auto depthOf = [&](double gridZ) {
    return -(camera.view * glm::dvec4(snapshot.geometry.origin + glm::dvec3(16.0, 16.0, gridZ), 1.0)).z;
  };
  // Column density of the slab: relative density 8 over 4 voxels of a 32-voxel side = 1.
  const double expected = std::exp(-absorption * 1.0);
  EXPECT_NEAR(t.at(0.5f, 0.5f, static_cast<float>(depthOf(28.0))), 1.0, 0.01);  // in front of the slab
  EXPECT_NEAR(t.at(0.5f, 0.5f, static_cast<float>(depthOf(10.0))), expected, 0.03 * expected);
  EXPECT_NEAR(t.at(0.5f, 0.5f, static_cast<float>(depthOf(2.0))), expected, 0.03 * expected);

  // A point behind the slab lands in its pixel dimmed by exactly that factor.
  core::PointProjection projection;
  projection.grid = snapshot.geometry;
  projection.camera = camera;
  projection.width = projection.height = 33;
  projection.insideVoxels = static_cast<double>(voxels);
  const float x = 16.2f, y = 16.2f, front = 28.0f, behind = 8.0f;
  const std::uint32_t white = 0xffffffu;
  core::PointProjector clear(projection, 1);
  clear.consume(0, {&x, &y, &behind, &white, 1});
  projection.transmittance = &t;
  core::PointProjector dimmed(projection, 1);
  dimmed.consume(0, {&x, &y, &behind, &white, 1});
  core::PointProjector inFront(projection, 1);
  inFront.consume(0, {&x, &y, &front, &white, 1});
  const double open = channelSum(clear.merge(), 3);
  EXPECT_NEAR(channelSum(dimmed.merge(), 3) / open, expected, 0.03 * expected);
  EXPECT_NEAR(channelSum(inFront.merge(), 3) / open, 1.0, 0.01);
}

TEST(PointRenderer, PointsAndVolumeShareTheDensityScale) {
  // N points spread evenly through a cube give each pixel of a front view D = the cube's depth
  // in grid sides (1), the same as the volume method's column density.
  const core::GridGeometry grid = cubeGrid(16);
  core::PointProjection projection;
  projection.grid = grid;
  projection.camera = frontCamera(grid, 16.0);
  projection.width = projection.height = 16;
  projection.insideVoxels = 16.0 * 16 * 16;
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> rgb;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i)
        for (int s = 0; s < 4; ++s) {
          x.push_back(static_cast<float>(i) + 0.25f + 0.5f * static_cast<float>(s & 1));
          y.push_back(static_cast<float>(j) + 0.25f + 0.5f * static_cast<float>(s >> 1));
          z.push_back(static_cast<float>(k) + 0.5f);
          rgb.push_back(0xffffffu);
        }
  projection.totalPoints = static_cast<double>(x.size());
  core::PointProjector projector(projection, 1);
  projector.consume(0, {x.data(), y.data(), z.data(), rgb.data(), x.size()});
  const core::DensityImage density = projector.merge();
  EXPECT_NEAR(density.at(8, 8)[3], 1.0f, 1e-4f);
  EXPECT_NEAR(density.at(3, 12)[3], 1.0f, 1e-4f);
  // And a pixel with D = 1 holds the hits it was given (64 along its column).
  EXPECT_NEAR(density.hitsPerUnitDensity, 64.0, 1e-6 * 64.0);
}

TEST(FlameImage, CoverageFromTheImagesFourthChannelIsTheCoverageFromItsAlpha) {
  // A 16K print carries its opacity in the image (finishImageOnGpu's alphaInImage): the coverage
  // taken there is the one silhouetteCoverage gives, and the image is left opaque.
  constexpr int kWidth = 7, kHeight = 5;
  core::FinishedImage finished;
  finished.image.width = kWidth;
  finished.image.height = kHeight;
  finished.image.pixels.assign(4 * kWidth * kHeight, 0.5f);
  core::MeshOverlay silhouette;
  silhouette.width = kWidth;
  silhouette.height = kHeight;
  silhouette.rgba.assign(4 * kWidth * kHeight, 0);
  for (int p = 0; p < kWidth * kHeight; ++p) {
    const float alpha = static_cast<float>(p % 4) / 10.0f;  // 0, 0.1, 0.2, 0.3: three of four covered
    finished.alpha.push_back(alpha);
    finished.image.pixels[4 * p + 3] = alpha;
    silhouette.rgba[4 * p + 3] = p < 20 ? 255 : 0;
  }
  const double expected = core::silhouetteCoverage(finished, silhouette);
  EXPECT_NEAR(expected, 15.0 / 20.0, 1e-12);
  EXPECT_EQ(core::takeSilhouetteCoverage(finished.image, silhouette), expected);
  for (int p = 0; p < kWidth * kHeight; ++p) EXPECT_EQ(finished.image.pixels[4 * p + 3], 1.0f);
}
