#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/accumulator.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/scene_io.h"

using namespace voxflame::core;

namespace {

std::shared_ptr<const InsideMask> bunnyMask(int resolution) {
  const TriangleMesh mesh = loadSceneMesh(defaultScene());
  return std::make_shared<const InsideMask>(buildInsideMask(mesh, gridOverBox(mesh.bounds(), resolution)));
}

VolumeSnapshot accumulate(const std::shared_ptr<const InsideMask>& mask, const std::vector<PatternLayer>& layers,
                          std::uint64_t points, int threads, std::uint64_t seed = 7) {
  Accumulator accumulator(mask, threads);
  accumulator.setTargetPoints(points);
  accumulator.setPattern(layers, seed);
  EXPECT_TRUE(accumulator.waitUntilDone(60.0));
  VolumeSnapshot snapshot;
  accumulator.snapshot(snapshot);
  return snapshot;
}

}  // namespace

TEST(Accumulator, FillsOnlyVoxelsInsideTheMask) {
  const auto mask = bunnyMask(48);
  const VolumeSnapshot snapshot = accumulate(mask, defaultScene().layers, 300'000, 2);
  EXPECT_GE(snapshot.points, 300'000u);
  std::size_t lit = 0;
  for (std::size_t v = 0; v < snapshot.density.size(); ++v) {
    if (snapshot.density[v] > 0.0f) {
      ++lit;
      EXPECT_TRUE(mask->inside[v]) << "voxel " << v << " is outside the mesh but has density";
    }
    EXPECT_TRUE(std::isfinite(snapshot.density[v]));
  }
  EXPECT_GT(lit, 500u);  // the pattern spreads through the volume, not into a few voxels
}

TEST(Accumulator, OneThreadWithAFixedSeedIsDeterministic) {
  const auto mask = bunnyMask(32);
  const auto layers = defaultScene().layers;
  Accumulator first(mask, 1), second(mask, 1);
  for (Accumulator* a : {&first, &second}) {
    a->setTargetPoints(100'000);
    a->setPattern(layers, 42);
    ASSERT_TRUE(a->waitUntilDone(60.0));
  }
  VolumeSnapshot one, two;
  first.snapshot(one);
  second.snapshot(two);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.density, two.density);
  EXPECT_EQ(one.rgba, two.rgba);
}

TEST(Accumulator, NewPatternBumpsGenerationAndClearsTheGrid) {
  const auto mask = bunnyMask(32);
  auto layers = defaultScene().layers;
  Accumulator accumulator(mask, 2);
  accumulator.setTargetPoints(200'000);
  accumulator.setPattern(layers, 1);
  ASSERT_TRUE(accumulator.waitUntilDone(60.0));
  const auto generation = accumulator.generation();
  layers[0].params[0] *= 1.01;
  accumulator.setTargetPoints(1'000);
  accumulator.setPattern(layers, 1);
  EXPECT_EQ(accumulator.generation(), generation + 1);
  ASSERT_TRUE(accumulator.waitUntilDone(60.0));
  VolumeSnapshot snapshot;
  accumulator.snapshot(snapshot);
  double total = 0.0;
  for (float d : snapshot.density) total += d;
  // Only the new generation's points are in the grid: a little over the new target, far below 200k.
  EXPECT_LT(total, 100'000.0);
  EXPECT_GE(total, 1'000.0);
}

TEST(Accumulator, EscapingAttractorIsReportedAndNeverSplatted) {
  const auto mask = bunnyMask(32);
  auto layers = defaultScene().layers;
  layers[0].params = {1.111, 1.479, 4.494, 0.44};
  layers[0].step = 0.9;  // Euler with a huge step blows up
  Accumulator accumulator(mask, 2);
  accumulator.setTargetPoints(10'000);
  accumulator.setPattern(layers, 1);
  EXPECT_TRUE(accumulator.waitUntilDone(10.0));
  const AccumulatorStats stats = accumulator.stats();
  EXPECT_NE(stats.problem.find("escapes"), std::string::npos);
  EXPECT_EQ(stats.points, 0u);
}

TEST(Accumulator, RefusesNonFiniteParameters) {
  const auto mask = bunnyMask(32);
  auto layers = defaultScene().layers;
  layers[0].params[1] = std::nan("");
  Accumulator accumulator(mask, 1);
  EXPECT_THROW(accumulator.setPattern(layers, 1), Error);
  layers = defaultScene().layers;
  layers[0].step = std::numeric_limits<double>::infinity();
  EXPECT_THROW(accumulator.setPattern(layers, 1), Error);
}

TEST(Accumulator, DestroyingWhileRefiningJoinsPromptly) {
  const auto mask = bunnyMask(32);
  for (int i = 0; i < 5; ++i) {
    Accumulator accumulator(mask, 2);
    accumulator.setPattern(defaultScene().layers, static_cast<std::uint64_t>(i));
  }
  SUCCEED();
}
