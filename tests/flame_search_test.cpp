// The exploration of chaos-game patterns: random and mutated flame genomes and Julia constants,
// and the fill test that keeps volumes and rejects dust, sheets and escapes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "core/flame/flame.h"
#include "core/flame/search.h"
#include "core/flame/variations.h"

using namespace voxflame;

namespace {

// Every transform a plain contraction (or expansion) by `scale` about a different point.
core::FlameGenome scaledGenome(double scale) {
  core::FlameGenome g;
  const double offsets[3][3] = {{0.5, 0.1, -0.2}, {-0.4, 0.3, 0.2}, {0.1, -0.5, 0.4}};
  for (const auto& offset : offsets) {
    core::FlameXform x;
    x.weight = 1.0;
    x.affine.m = {scale, 0, 0, offset[0], 0, scale, 0, offset[1], 0, 0, scale, offset[2]};
    x.variations = {{"linear", 1.0, {}}};
    g.xforms.push_back(x);
  }
  return g;
}

TEST(FlameSearch, RandomFlamesAreDeterministicValidAndVaried) {
  EXPECT_EQ(core::randomFlame(7), core::randomFlame(7));
  EXPECT_NE(core::randomFlame(7), core::randomFlame(8));
  std::set<std::string> names;
  bool sawSymmetry = false, sawFinal = false;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const core::FlameGenome g = core::randomFlame(seed);
    EXPECT_NO_THROW(core::validateFlame(g, "random flame " + std::to_string(seed)));
    ASSERT_GE(g.xforms.size(), 2u);
    ASSERT_LE(g.xforms.size(), 5u);
    double lowest = 1.0, highest = 0.0;
    for (const core::FlameXform& x : g.xforms) {
      ASSERT_GE(x.variations.size(), 1u);
      ASSERT_LE(x.variations.size(), 3u);
      for (const auto& term : x.variations) names.insert(term.name);
      lowest = std::min(lowest, x.color);
      highest = std::max(highest, x.color);
      // Contractive: no column of the 3×3 part longer than the largest scale plus the shear.
      for (int col = 0; col < 3; ++col) {
        const double length =
            std::hypot(x.affine.m[static_cast<std::size_t>(col)], x.affine.m[static_cast<std::size_t>(4 + col)],
                       x.affine.m[static_cast<std::size_t>(8 + col)]);
        EXPECT_LT(length, 1.2);
      }
    }
    EXPECT_GT(highest - lowest, 0.3) << "colours spread over the gradient";
    sawSymmetry |= g.symmetry.rotational > 1 || g.symmetry.mirror;
    sawFinal |= g.hasFinal;
  }
  EXPECT_TRUE(sawSymmetry);
  EXPECT_TRUE(sawFinal);
  EXPECT_GE(names.size(), std::min<std::size_t>(5, core::variationCatalogue().size()))
      << "variations come from across the catalogue";
}

TEST(FlameSearch, NoiseLikeVariationsAreNeverATransformsOnlyTerm) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed)
    for (const core::FlameXform& x : core::randomFlame(seed).xforms)
      if (x.variations.size() == 1) {
        EXPECT_NE(x.variations[0].name, "zscale") << "seed " << seed;
      }
}

TEST(FlameSearch, FillTestRejectsCollapseAndEscapeAndKeepsAVolume) {
  const core::FillReport collapsed = core::measureFlameFill(scaledGenome(0.01), 1);
  EXPECT_FALSE(collapsed.passes);
  EXPECT_FALSE(collapsed.reason.empty());
  EXPECT_LT(collapsed.occupancy, 0.02) << collapsed.reason;

  const core::FillReport escaped = core::measureFlameFill(scaledGenome(3.0), 1);
  EXPECT_FALSE(escaped.passes);
  EXPECT_GT(escaped.badFraction, 0.05) << escaped.reason;

  // A flat genome: every map squashes z to 0, so the set is a sheet.
  core::FlameGenome flat = scaledGenome(0.55);
  for (auto& x : flat.xforms) x.affine.m[10] = 0.0, x.affine.m[11] = 0.0;
  const core::FillReport sheet = core::measureFlameFill(flat, 1);
  EXPECT_FALSE(sheet.passes);
  EXPECT_LT(sheet.extentRatio, 0.12);

  // Three maps of scale 0.55 about three points: a solid Sierpinski-like volume.
  const core::FillReport solid = core::measureFlameFill(scaledGenome(0.55), 1);
  EXPECT_TRUE(solid.passes) << solid.reason;
  EXPECT_GT(solid.score, 0.0);
  EXPECT_EQ(core::measureFlameFill(scaledGenome(0.55), 1).score, solid.score) << "deterministic for a seed";

  EXPECT_TRUE(core::measureFlameFill(core::defaultFlame(), 3).passes) << "the default flame is a volume";
}

// Mutation draws parameters within their sliders, so every slider lies within what a flame may hold: a slider past
// ±kFlameCoefficientLimit (hopalong's seed once reached 10⁷) made a mutated flame invalid.
TEST(FlameSearch, EverySliderLiesWithinWhatAFlameMayHold) {
  for (const core::VariationInfo& info : core::variationCatalogue())
    for (const core::VariationParam& p : info.params) {
      EXPECT_LE(std::abs(p.sliderMin), core::kFlameCoefficientLimit) << info.name << " " << p.name;
      EXPECT_LE(std::abs(p.sliderMax), core::kFlameCoefficientLimit) << info.name << " " << p.name;
    }
}

TEST(FlameSearch, MutateWithStrengthZeroChangesNothingAndStaysValid) {
  const core::FlameGenome base = core::defaultFlame();
  EXPECT_EQ(core::mutateFlame(base, 0.0, 5), base);
  EXPECT_EQ(core::mutateFlame(base, 0.2, 5), core::mutateFlame(base, 0.2, 5));
  double smallChange = 0.0, largeChange = 0.0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const core::FlameGenome small = core::mutateFlame(base, 0.02, seed);
    const core::FlameGenome large = core::mutateFlame(base, 0.8, seed);
    EXPECT_NE(small, base);
    EXPECT_NO_THROW(core::validateFlame(small, "small mutation"));
    EXPECT_NO_THROW(core::validateFlame(large, "large mutation"));
    smallChange += std::abs(small.xforms[0].affine.m[0] - base.xforms[0].affine.m[0]);
    largeChange += std::abs(large.xforms[0].affine.m[0] - base.xforms[0].affine.m[0]);
  }
  EXPECT_GT(largeChange, 5.0 * smallChange) << "the change scales with the strength";
}

// Issue 25: a flame with xaos keeps it through mutations (factors move, columns follow removed
// transforms); one without xaos is never given any.
TEST(FlameSearch, MutationKeepsXaosConsistentAndGivesNoneToFlamesWithout) {
  core::FlameGenome base = core::defaultFlame();
  EXPECT_FALSE(core::hasXaos(core::mutateFlame(base, 0.8, 3)));
  base.xforms[0].xaos = {0.0, 2.0, 1.0};
  base.xforms[1].xaos = {1.0, 0.5};
  bool moved = false;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const core::FlameGenome mutated = core::mutateFlame(base, 0.8, seed);
    EXPECT_NO_THROW(core::validateFlame(mutated, "mutation"));
    for (const core::FlameXform& x : mutated.xforms) EXPECT_LE(x.xaos.size(), mutated.xforms.size());
    moved = moved || mutated.xforms[0].xaos != base.xforms[0].xaos;
  }
  EXPECT_TRUE(moved);
}

TEST(FlameSearch, SearchReturnsTheBestCandidatesThatPassTheFillTest) {
  core::FlameSearchOptions options;
  options.seed = 11;
  options.count = 3;
  const auto found = core::searchFlames(std::nullopt, options);
  ASSERT_EQ(found.size(), 3u);
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_NO_THROW(core::validateFlame(found[i].genome, "found"));
    EXPECT_TRUE(found[i].fill.passes);
    EXPECT_TRUE(core::measureFlameFill(found[i].genome, 99).passes) << "passes again with another probe seed";
    if (i > 0) {
      EXPECT_GE(found[i - 1].fill.score, found[i].fill.score) << "best first";
    }
  }
  const auto again = core::searchFlames(std::nullopt, options);
  ASSERT_EQ(again.size(), found.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_EQ(again[i].genome, found[i].genome) << "deterministic";

  // Mutations of a base are near it, never identical to it.
  options.count = 1;
  options.strength = 0.1;
  const auto nearby = core::searchFlames(core::defaultFlame(), options);
  ASSERT_EQ(nearby.size(), 1u);
  EXPECT_NE(nearby[0].genome, core::defaultFlame());
  EXPECT_TRUE(nearby[0].fill.passes);

  // A base that escapes everywhere yields nothing, not a crash or a bad genome.
  options.maxCandidates = 10;
  options.strength = 0.01;
  EXPECT_TRUE(core::searchFlames(scaledGenome(3.0), options).empty());
}

// A caller holds the search to its own check of each candidate that passed the fill test (the
// explorer: does its live view run it bounded?): a refused one is never returned.
TEST(FlameSearch, SearchKeepsOnlyWhatTheCallerAccepts) {
  core::FlameSearchOptions options;
  options.seed = 11;
  options.count = 1;
  const auto unchecked = core::searchFlames(std::nullopt, options);
  ASSERT_EQ(unchecked.size(), 1u);
  int asked = 0;
  options.acceptFlame = [&](const core::FlameGenome& genome) {
    ++asked;
    return !(genome == unchecked.front().genome);
  };
  const auto checked = core::searchFlames(std::nullopt, options);
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_NE(checked.front().genome, unchecked.front().genome) << "the best one was refused";
  EXPECT_GE(asked, 3) << "asked of every candidate that passed, until the pool was full";

  options.acceptFlame = [](const core::FlameGenome&) { return false; };
  options.maxCandidates = 30;
  EXPECT_TRUE(core::searchFlames(std::nullopt, options).empty());
  options.acceptJulia = [](const core::QuaternionJuliaSettings&) { return false; };
  EXPECT_TRUE(core::searchQuaternionJulia(std::nullopt, options).empty());
  options.acceptJulia = {};
  EXPECT_FALSE(core::searchQuaternionJulia(std::nullopt, options).empty()) << "the Julia search asks acceptJulia";
}

TEST(FlameSearch, QuaternionJuliaSearchKeepsSetsThatAreNeitherDustNorEmpty) {
  core::QuaternionJuliaSettings dust;
  // Far outside the Mandelbrot set the set is a Cantor dust huddled around ±√(−c).
  dust.c = {5.0, 5.0, 0.0, 0.0};
  EXPECT_FALSE(core::measureJuliaFill(dust, 1).passes);
  core::QuaternionJuliaSettings classic;  // -0.2 + 0.8i: connected
  EXPECT_TRUE(core::measureJuliaFill(classic, 1).passes) << core::measureJuliaFill(classic, 1).reason;
  core::QuaternionJuliaSettings missed = classic;
  missed.view = core::QuaternionView::Slice;
  missed.sliceW = 5.0;  // a slice far from the set: nothing is drawn
  EXPECT_FALSE(core::measureJuliaFill(missed, 1).passes);

  EXPECT_EQ(core::mutateJulia(classic, 0.0, 3), classic);
  EXPECT_LE(glm::length(core::mutateJulia(classic, 0.1, 3).c - classic.c), 0.1 + 1e-12);
  EXPECT_EQ(core::randomJulia(4), core::randomJulia(4));

  core::FlameSearchOptions options;
  options.seed = 5;
  options.count = 2;
  const auto fresh = core::searchQuaternionJulia(std::nullopt, options);
  ASSERT_EQ(fresh.size(), 2u);
  for (const auto& candidate : fresh) {
    EXPECT_TRUE(candidate.fill.passes);
    EXPECT_NO_THROW(core::validateQuaternionJulia(candidate.julia, "found"));
    EXPECT_LE(glm::length(candidate.julia.c), 1.1 + 1e-12);
  }
  options.count = 1;
  const auto nearby = core::searchQuaternionJulia(classic, options);
  ASSERT_EQ(nearby.size(), 1u);
  EXPECT_NE(nearby[0].julia, classic);
  EXPECT_LE(glm::length(nearby[0].julia.c - classic.c), options.strength + 1e-12);
}

}  // namespace
