#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <limits>

#include <glm/geometric.hpp>
#include <memory>

#include "core/accumulator.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"
#include "core/lyapunov.h"
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
  accumulator.setTargetPoints(2'000'000);
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
  // Only the new generation's points are in the grid: at most a batch per work stream over the new
  // target, far below the 2 M of the old one.
  EXPECT_LT(total, 400'000.0);
  EXPECT_GE(total, 1'000.0);
}

TEST(Accumulator, TheVolumeDoesNotDependOnTheNumberOfThreads) {
  const auto mask = bunnyMask(40);
  const auto layers = defaultScene().layers;
  const VolumeSnapshot one = accumulate(mask, layers, 300'000, 1, 11);
  const VolumeSnapshot two = accumulate(mask, layers, 300'000, 2, 11);
  const VolumeSnapshot five = accumulate(mask, layers, 300'000, 5, 11);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.density, two.density);
  EXPECT_EQ(one.rgba, two.rgba);
  EXPECT_EQ(one.density, five.density);
  EXPECT_EQ(one.rgba, five.rgba);
  const VolumeSnapshot otherSeed = accumulate(mask, layers, 300'000, 2, 12);
  EXPECT_NE(one.density, otherSeed.density);
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

namespace {

PatternLayer layerFor(const std::string& id) {
  const AttractorInfo& info = attractorOrThrow(id);
  PatternLayer layer;
  layer.attractor = id;
  layer.params = info.defaultParams();
  layer.step = info.defaultStep;
  layer.integrator = info.defaultIntegrator;
  layer.color.gradient = {{0.0f, glm::vec3(0.0f)}, {1.0f, glm::vec3(1.0f)}};
  return layer;
}

double maskExtent(const InsideMask& mask) {
  return static_cast<double>(std::max({mask.geometry.size.x, mask.geometry.size.y, mask.geometry.size.z}));
}

}  // namespace

namespace {

struct FitChange {
  double scale = 0.0;   // relative change of the scale
  double centre = 0.0;  // centre shift in units of the grid's longest side
};

FitChange fitChange(const PreparedLayer& a, const PreparedLayer& b, const InsideMask& mask) {
  return {std::abs(b.automaticFit.scale / a.automaticFit.scale - 1.0),
          glm::length(b.automaticFit.center - a.automaticFit.center) * a.automaticFit.scale / maskExtent(mask)};
}

}  // namespace

// The seed's fit made animation frames jump because it came from one short orbit and its extreme
// tails. The estimator's own noise — the same parameters probed from independent phases (seeds)
// — must now move the fit well under 1%. (Thomas's slow, symmetric attractor is the known
// exception: its median wanders by ~2% between probes.)
TEST(Fit, ProbeNoiseMovesTheFitLessThanOnePercent) {
  const auto mask = bunnyMask(64);
  for (const char* id : {"lorenz84", "lorenz", "rossler", "aizawa", "polynomial_a", "pickover"}) {
    const PatternLayer layer = layerFor(id);
    const PreparedLayer reference = prepareLayer(layer, *mask, 1);
    ASSERT_TRUE(reference.bounded) << id;
    for (std::uint64_t seed = 2; seed <= 4; ++seed) {
      const FitChange change = fitChange(reference, prepareLayer(layer, *mask, seed), *mask);
      EXPECT_LT(change.scale, 0.01) << id << " seed " << seed;
      EXPECT_LT(change.centre, 0.01) << id << " seed " << seed;
    }
  }
}

// A 1% change of a parameter moves the fit by < 2% where the attractor itself keeps its size
// (Lorenz, the seed's flagship flow, on every parameter). Elsewhere the attractor's own extent can
// change by a few percent per 1% (Thomas, the polynomial maps), and a fit that follows it moves as
// much — but never jumps: < 10%. Changes that cross into a periodic window or out of the basin
// (Lorenz-84's a = 1.122 is periodic) change the attractor's nature and are skipped.
TEST(Fit, OnePercentParameterChangeMovesTheFitSmoothly) {
  const auto mask = bunnyMask(64);
  for (const char* id : {"lorenz", "lorenz84", "rossler", "aizawa", "polynomial_a", "thomas"}) {
    const bool strict = std::string(id) == "lorenz";
    const PatternLayer base = layerFor(id);
    const PreparedLayer reference = prepareLayer(base, *mask, 1);
    ASSERT_TRUE(reference.bounded) << id;
    int checked = 0;
    for (std::size_t p = 0; p < base.params.size(); ++p)
      for (double factor : {1.01, 0.99}) {
        PatternLayer changed = base;
        changed.params[p] *= factor;
        OrbitSpec spec = defaultOrbitSpec(attractorOrThrow(id));
        spec.params = changed.params;
        if (analyseOrbit(spec, {2'000, 20'000, 1e6}).verdict != OrbitVerdict::Chaotic) continue;
        const PreparedLayer moved = prepareLayer(changed, *mask, 1);
        ASSERT_TRUE(moved.bounded) << id << " param " << p;
        const FitChange change = fitChange(reference, moved, *mask);
        const double limit = strict ? 0.02 : 0.10;
        EXPECT_LT(change.scale, limit) << id << " param " << p << " x" << factor;
        EXPECT_LT(change.centre, limit) << id << " param " << p << " x" << factor;
        ++checked;
      }
    EXPECT_GE(checked, 1) << id;
  }
}

TEST(Fit, UserTransformAppliesAndALockedFitIgnoresParameterChanges) {
  const auto mask = bunnyMask(48);
  PatternLayer layer = layerFor("lorenz84");
  const PreparedLayer automatic = prepareLayer(layer, *mask, 1);
  layer.transform.scale = 0.5;
  layer.transform.offset = {0.1, 0.0, 0.0};
  const PreparedLayer scaled = prepareLayer(layer, *mask, 1);
  EXPECT_DOUBLE_EQ(scaled.fit.scale, 0.5 * automatic.fit.scale);
  EXPECT_NEAR(scaled.fit.gridCenter.x - automatic.fit.gridCenter.x, 0.1 * maskExtent(*mask), 1e-9);
  layer.transform.rotationDeg = {0.0, 0.0, 90.0};
  const PreparedLayer rotated = prepareLayer(layer, *mask, 1);
  const glm::dvec3 moved = rotated.fit.apply(rotated.fit.attractorCenter + glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_NEAR(moved.x - rotated.fit.gridCenter.x, 0.0, 1e-9);  // x turned into y
  EXPECT_NEAR(moved.y - rotated.fit.gridCenter.y, rotated.fit.scale, 1e-9);

  layer = layerFor("lorenz84");
  layer.transform.lockFit = true;
  layer.transform.lockedCenter = automatic.automaticFit.center;
  layer.transform.lockedScale = automatic.automaticFit.scale;
  layer.params[1] *= 1.01;  // still chaotic, a slightly different attractor
  const PreparedLayer locked = prepareLayer(layer, *mask, 1);
  EXPECT_EQ(locked.fit.attractorCenter, automatic.fit.attractorCenter);
  EXPECT_EQ(locked.fit.scale, automatic.fit.scale);

  layer.transform.scale = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(prepareLayer(layer, *mask, 1), Error);
  layer = layerFor("lorenz84");
  layer.color.period = 0.0;
  EXPECT_THROW(prepareLayer(layer, *mask, 1), Error);
}

// Near-unstable settings (the seed's Lorenz with an Euler step just below where it blows up; a
// map with a small basin): nothing non-finite or outside the mask may reach the grid, and the
// snapshot's point count is exactly the density it holds.
TEST(Accumulator, NaNNeverReachesTheGrid) {
  const auto mask = bunnyMask(32);
  PatternLayer edgy = layerFor("lorenz");
  edgy.step = 0.0125;
  for (const PatternLayer& layer : {edgy, layerFor("polynomial_a"), layerFor("henon_3d")}) {
    Accumulator accumulator(mask, 2);
    accumulator.setTargetPoints(20'000);
    accumulator.setPattern({layer}, 3);
    ASSERT_TRUE(accumulator.waitUntilDone(60.0)) << layer.attractor;
    EXPECT_TRUE(accumulator.stats().problem.empty()) << accumulator.stats().problem;
    // Past the target, threads still finish the batch they are in; wait until they rest so the
    // snapshot and the point count describe the same grid.
    for (std::uint64_t before = ~std::uint64_t{0}; before != accumulator.stats().points;) {
      before = accumulator.stats().points;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    VolumeSnapshot snapshot;
    accumulator.snapshot(snapshot);
    double total = 0.0;
    for (std::size_t v = 0; v < snapshot.density.size(); ++v) {
      ASSERT_TRUE(std::isfinite(snapshot.density[v]));
      if (snapshot.density[v] > 0.0f) {
        EXPECT_TRUE(mask->inside[v]);
      }
      total += snapshot.density[v];
    }
    EXPECT_EQ(static_cast<std::uint64_t>(total), snapshot.points) << layer.attractor;
  }
}

TEST(Accumulator, AxisColouringFollowsPosition) {
  const auto mask = bunnyMask(40);
  PatternLayer layer = layerFor("lorenz84");
  layer.color.mode = ColorMode::Axis;
  layer.color.axis = {1.0, 0.0, 0.0};
  const VolumeSnapshot snapshot = accumulate(mask, {layer}, 200'000, 1);
  const GridGeometry& g = snapshot.geometry;
  double lowSum = 0.0, highSum = 0.0;
  int lowCount = 0, highCount = 0;
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const std::size_t v = g.index(i, j, k);
        if (snapshot.density[v] <= 0.0f) continue;
        (i < g.size.x / 2 ? lowSum : highSum) += snapshot.rgba[4 * v];
        ++(i < g.size.x / 2 ? lowCount : highCount);
      }
  ASSERT_GT(lowCount, 0);
  ASSERT_GT(highCount, 0);
  EXPECT_LT(lowSum / lowCount + 40.0, highSum / highCount);  // black → white along +x
}

TEST(Accumulator, EveryColourModeSpreadsOverTheGradient) {
  const auto mask = bunnyMask(32);
  for (ColorMode mode :
       {ColorMode::Speed, ColorMode::Curvature, ColorMode::Time, ColorMode::Axis, ColorMode::Distance}) {
    PatternLayer layer = layerFor("lorenz84");
    layer.color.mode = mode;
    layer.color.axis = {1.0, 0.0, 0.0};
    layer.color.period = 200.0;
    const VolumeSnapshot snapshot = accumulate(mask, {layer}, 100'000, 1);
    int darkest = 255, brightest = 0;
    for (std::size_t v = 0; v < snapshot.density.size(); ++v)
      if (snapshot.density[v] > 0.0f) {
        darkest = std::min<int>(darkest, snapshot.rgba[4 * v]);
        brightest = std::max<int>(brightest, snapshot.rgba[4 * v]);
      }
    EXPECT_GT(brightest - darkest, 40) << toString(mode);
  }
}

TEST(Accumulator, LayersKeepTheirOwnColoursAndWeights) {
  const auto mask = bunnyMask(32);
  PatternLayer red = layerFor("lorenz84");
  red.color.gradient = {{0.0f, {1.0f, 0.0f, 0.0f}}, {1.0f, {1.0f, 0.0f, 0.0f}}};
  PatternLayer blue = layerFor("rossler");
  blue.color.gradient = {{0.0f, {0.0f, 0.0f, 1.0f}}, {1.0f, {0.0f, 0.0f, 1.0f}}};
  const auto colourTotals = [&](const VolumeSnapshot& s) {
    glm::dvec3 sum(0.0);
    for (std::size_t v = 0; v < s.density.size(); ++v)
      for (int c = 0; c < 3; ++c) sum[c] += s.density[v] * s.rgba[4 * v + static_cast<std::size_t>(c)];
    return sum;
  };
  const glm::dvec3 both = colourTotals(accumulate(mask, {red, blue}, 200'000, 1));
  EXPECT_GT(both.r, 0.0);
  EXPECT_GT(both.b, 0.0);
  EXPECT_EQ(both.g, 0.0);
  blue.weight = 0.0;
  const glm::dvec3 redOnly = colourTotals(accumulate(mask, {red, blue}, 100'000, 1));
  EXPECT_GT(redOnly.r, 0.0);
  EXPECT_EQ(redOnly.b, 0.0);
}

// A generation change must get the grid even while many workers and snapshots keep reading it:
// a shared_mutex may otherwise let readers starve the writer, and the explorer waits for it.
TEST(Accumulator, PatternChangesAreNotStarvedByBusyReaders) {
  const auto mask = bunnyMask(64);
  Accumulator accumulator(mask, 6);  // more threads than cores: readers overlap all the time
  accumulator.setPattern(defaultScene().layers, 1);
  std::atomic<bool> stop{false};
  std::jthread snapshots([&] {
    VolumeSnapshot snapshot;
    while (!stop) accumulator.snapshot(snapshot);
  });
  auto layers = defaultScene().layers;
  for (int change = 0; change < 20; ++change) {
    layers[0].params[0] *= 1.001;
    const auto start = std::chrono::steady_clock::now();
    accumulator.setPattern(layers, 1);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 2.0) << "change " << change;
  }
  stop = true;
}
