// Fractorium's remaining random 2D variations (core/flame/variations_blurs_more.cpp) and its 3D
// ones that read the running sum (variations_3d_sum.cpp), each at points whose expected values were
// worked out from Fractorium's published formulas (Variations02-08.h) by a separate Python script in
// double precision, independently of the code under test. That script replays voxflame's lane
// generator (xorshift32, Ψ from the top 24 bits): Ψ = 0.879466, 0.545326, 0.394069, … from
// 0x2545F491; 0.316594, 0.875707, … from 0x9E3779B9; 0.529668, 0.083422, … from 0x12345678;
// 0.000691, 0.911483, … from 0x0BADF00D. The main point is (0.3, −0.7, 0.5) with weight 0.8, and
// (1.1, −0.9, 0.5), beyond the depth blurs' radius 1. Where Fractorium draws ln Ψ, the script draws
// ln(1 − Ψ) as voxflame does (depth_gaussian2), and a 2D variation's z is w z (voxflame's rule).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/chaos_game.h"
#include "core/flame/flame.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

constexpr std::uint32_t kSeed3 = 0x12345678u;  // first Ψ = 0.529668
constexpr std::uint32_t kSeed4 = 0x0BADF00Du;  // first Ψ = 0.000691

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // asteria: outside the unit disc (of w p) the point is kept; inside it (and outside the corner discs) bent.
      {"asteria", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"asteria", {0.3}, {0.2, 0.1, 0.5}, 0.8, kHighSeed, {0.1503413014910787, 0.09329405800296124, 0.4}},
      // Within both discs: kept for Ψ = 0.879 > 0.35, bent for Ψ = 0.317.
      {"asteria", {0.3}, {0.6, 0.5, 0.5}, 0.8, kHighSeed, {0.48, 0.4, 0.4}},
      {"asteria", {0.3}, {0.6, 0.5, 0.5}, 0.8, kLowSeed, {0.5020806315220413, 0.3696086179804767, 0.4}},
      // Circle_Rand: a random cell and a disc point; a cell whose hash is not below density adds nothing.
      {"Circle_Rand", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-1.3369545862055678, -8.248680908436535, 0.4}},
      {"Circle_Rand", {4.0, 6.0, 0.5, 2.0, 0.7, 3.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"Circle_Rand",
       {4.0, 6.0, 0.5, 2.0, 0.9, 3.0},
       {0.3, -0.7, 0.5},
       0.8,
       kSeed4,
       {1.884492508295807, 1.6012360298702668, 0.4}},
      // CircleRand: redrawn until the point falls in its cell's disc (10 and 9 tries here).
      {"CircleRand", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {6.829128265380859, -2.612781524658203, 0.4}},
      {"CircleRand", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {7.095479965209961, 0.61773681640625, 0.4}},
      {"CircleRand",
       {0.7, 0.8, 3.0, 4.0, 5.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {1.6773679733276368, -2.597064971923828, 0.4}},
      // CircleTrans1: (p + (X, Y))/2 kept outside the discs; inside one, a random circle point of a random cell.
      {"CircleTrans1", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {4.12, 3.7200000000000006, 0.4}},
      {"CircleTrans1",
       {0.7, 0.8, 3.0, 4.0, 5.0},
       {1.3, 2.1, 0.5},
       0.8,
       kHighSeed,
       {-1.9647530031024432, -0.3364425169648314, 0.4}},
      {"CircleTrans1",
       {0.7, 0.8, 3.0, 4.0, 5.0},
       {3.0, -1.0, 0.5},
       0.8,
       kHighSeed,
       {2.4000000000000004, 1.2000000000000002, 0.4}},
      // cpow2: the defaults are the identity up to the random branch (2π multiples).
      {"cpow2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24000000000064775, -0.5599999999997224, 0.4}},
      {"cpow2", {1.2, 0.3, 2.0, 3.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.7282293279187586, -0.6102578612577414, 0.4}},
      {"cpow2", {1.2, 0.3, 2.0, 3.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {12.368025436095504, -26.376422308601313, 0.4}},
      // depth_blur and its kin at (1.1, −0.9), beyond the radius 1; within it the point is kept.
      {"depth_blur", {}, {1.1, -0.9, 0.5}, 0.8, kHighSeed, {0.8704711824387843, -0.7280050654690021, 0.4}},
      {"depth_blur", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_blur",
       {3.0, 0.6, 2.0, 0.5},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {0.8155240869250904, -0.7710795492971547, 0.4}},
      {"depth_blur2", {}, {1.1, -0.9, 0.5}, 0.8, kHighSeed, {0.8675857652303631, -0.7191246644287616, 0.4}},
      {"depth_blur2",
       {3.0, 0.6, 2.0, 0.5, 0.1, -0.2, 1.5, 0.7, 1.3},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {0.9241702548171669, -0.7549928616874344, 0.4}},
      {"depth_gaussian2", {}, {1.1, -0.9, 0.5}, 0.8, kHighSeed, {0.813465399542378, -0.7394777448342023, 0.4}},
      {"depth_gaussian2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"depth_gaussian2",
       {2.0, 0.5, 0.1, -0.2, 1.5, 0.7, 1.3},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {1.0892118560154087, -0.9273614137734504, 0.4}},
      {"depth_ngon2", {}, {1.1, -0.9, 0.5}, 0.8, kHighSeed, {0.907895297917359, -0.7463719786143765, 0.4}},
      {"depth_ngon2",
       {3.0, 2.0, 0.5, 0.1, -0.2, 1.5, 0.7, 1.3},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {0.8197749798860555, -0.584564923976465, 0.4}},
      {"depth_sine2", {}, {1.1, -0.9, 0.5}, 0.8, kHighSeed, {0.8915372503486099, -0.7309072188568709, 0.4}},
      {"depth_sine2",
       {2.0, 2.0, 0.5, 0.1, -0.2, 1.5, 0.7, 1.3},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {0.8422249137317744, -0.635050726909626, 0.4}},
      // GlynnSim2/3: a ring point within; beyond, p or α² p by the contrast draw.
      {"GlynnSim2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.7156462332713088, -0.2095026441482092, 0.4}},
      {"GlynnSim2", {}, {1.05, 0.2, 0.5}, 0.8, kSeed3, {0.8400000000000001, 0.16000000000000003, 0.4}},
      {"GlynnSim2", {}, {1.05, 0.2, 0.5}, 0.8, kSeed4, {0.7352297592997812, 0.1400437636761488, 0.4}},
      {"GlynnSim2",
       {1.5, 0.3, 0.9, -2.0, 30.0, 200.0},
       {1.1, -0.9, 0.5},
       0.8,
       kLowSeed,
       {-1.3004459749915234, 0.025646807215510183, 0.4}},
      {"GlynnSim3", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.8445545331824013, -0.24724004627296228, 0.4}},
      {"GlynnSim3", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.6250118887885466, -0.6194837680464061, 0.4}},
      {"GlynnSim3", {}, {1.15, 0.2, 0.5}, 0.8, kSeed4, {0.6752293577981653, 0.11743119266055049, 0.4}},
      {"GlynnSim3",
       {0.6, 0.2, 0.1, 0.9, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.4545541009371249, -0.4505336494882954, 0.4}},
      {"hex_truchet", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.9703768868596518, -1.7379342740577586, 0.4}},
      {"hex_truchet", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.07879107300041373, -1.6694370397968272, 0.4}},
      {"hex_truchet",
       {0.3, 2.0, 5.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.8568316918597749, -2.8472139235329332, 0.4}},
      // juliaNab: b added unweighted, z kept as it is.
      {"juliaNab", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {1.24, 0.43999999999999995, 0.5}},
      {"juliaNab",
       {3.0, 0.7, -0.2, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.8194207167173588, -0.6241809365171291, 0.5}},
      {"juliaNab",
       {3.0, 0.7, -0.2, 1.5},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.4770618251835876, -0.5243436080490324, 0.5}},
      // crob: outside the inner borders (±0.5 by default) a random point of the band, unweighted; inside nothing.
      {"crob", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.45467448234558105, 0.9223548522990495, 0.4}},
      {"crob", {}, {3.0, 0.2, 0.5}, 0.8, kLowSeed, {0.8832104827752669, 0.12429302930831909, 0.4}},
      {"crob", {}, {0.3, -0.7, 0.5}, 0.8, kSeed4, {-0.6567368584228959, -0.08851706981658936, 0.4}},
      {"crob", {}, {0.1, 0.2, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"crob", {0.5, -2.0, -1.0, 3.0, 1.0, 0.3, 1.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      {"crob",
       {0.5, -2.0, -1.0, 3.0, 1.0, 0.3, 1.5},
       {2.9, -1.9, 0.5},
       0.8,
       kHighSeed,
       {1.909348964691162, 0.40723385597932804, 0.4}},
      {"crob",
       {0.5, -2.0, -1.0, 3.0, 1.0, 0.3, 1.5},
       {2.9, -1.9, 0.5},
       0.8,
       kSeed3,
       {2.833156108856201, 0.44391668373167903, 0.4}},
      {"crob", {-1.0, 1.0, -1.0, 1.0, 0.0, 0.5, 2.0}, {3.0, 0.2, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.4}},
      // The running-sum variations: an ordinary term, the sum before it being the harness's start (0.125, −0.25, 0.5).
      {"cubic3D", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.34687500000000004, -0.51875, -0.275}},
      {"cubic3D", {}, {0.3, -0.7, 0.5}, 0.3, kHighSeed, {-0.06812499999999999, -0.32125, 0.12499999999999997}},
      {"cubic3D",
       {1.8, 1.6},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.6588611955835025, 0.5705054233836051, 0.04617472130979977}},
      {"cubic3D",
       {0.6, -1.4},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.2721081055457095, -0.7548287386414594, 0.13670510600479713}},
      {"cubicLattice_3D", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.7575000000000001, -0.895, -0.7000000000000001}},
      {"cubicLattice_3D", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.8425, 0.7050000000000001, -0.7000000000000001}},
      {"cubicLattice_3D",
       {1.5, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {1.0231696383919642, 1.2733925503815589, -0.7866014581297792}},
      {"popcorn2_3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.15961392341453406, -0.2419144513889732, -0.004546057188671247}},
      {"popcorn2_3D",
       {0.3, -0.2, 0.5, 1.7},
       {0.3, -0.7, 0.0},
       1.4,
       kHighSeed,
       {0.08396771988763155, -0.5642899860201371, -1.1145193965487818}},
      // roundspher3D replaces the sum's z (0.5) by itself plus its own: the change is that less 0.5.
      {"roundspher3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.14367102965215908, -0.3352324025217045, 0.23945171608693183}},
      {"roundspher3D",
       {},
       {0.3, -0.7, 0.0},
       0.8,
       kHighSeed,
       {0.13265549235531413, -0.30952948216239967, 0.32003069719009525}},
      // extrude adds z alone (the chaos game clears the sum's z first).
      {"extrude", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.43626041412353517}},
      {"extrude", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.0, 0.0, 0.8}},
      {"extrude", {0.9}, {0.3, -0.7, 0.5}, -0.8, kHighSeed, {0.0, 0.0, 0.0}},
      // octapol: 2 w q in the disc or a triangle; elsewhere w q, the sum's x and y discarded (the change less the
      // start).
      {"octapol", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.072, -0.168, 0.4}},
      {"octapol", {}, {-2.8, -2.2, 0.5}, 0.8, kHighSeed, {-0.672, -0.528, 0.4}},
      {"octapol", {}, {0.9, 3.2, 0.5}, 0.8, kHighSeed, {-0.016999999999999987, 0.634, 0.4}},
      {"octapol", {}, {6.0, 0.0, 0.5}, 0.8, kHighSeed, {0.595, 0.25, 0.4}},
      {"octapol",
       {0.7, 1.2, 0.6, 0.4},
       {0.2, 0.1, 0.5},
       0.8,
       kHighSeed,
       {-1.2730196184398337, -0.03248146147161511, 0.4}},
  };
  return cases;
}

class RemainingVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(RemainingVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Remaining, RemainingVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// One lane of a variation at a given stage, the outputs starting at `start` (the sum before an
// ordinary term; a pre_/post_ term's scratch, which the chaos game clears).
glm::dvec3 runAt(const PointCase& c, VariationStage stage, glm::dvec3 start) {
  const VariationInfo& info = variationOrThrow(c.name);
  const std::vector<double> params = c.params.empty() ? info.defaultParams() : c.params;
  double x = c.point.x, y = c.point.y, z = c.point.z, ox = start.x, oy = start.y, oz = start.z, colour = 0.5;
  std::uint32_t random = c.seed;
  VariationInput in;
  in.x = in.tx = &x;
  in.y = in.ty = &y;
  in.z = in.tz = &z;
  in.random = &random;
  in.count = 1;
  in.weight = c.weight;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = &colour;
  in.stage = stage;
  info.apply(in, &ox, &oy, &oz);
  return {ox, oy, oz};
}

void expectNear(glm::dvec3 got, glm::dvec3 expected) {
  EXPECT_NEAR(got.x, expected.x, 1e-12 * std::max(1.0, std::abs(expected.x)));
  EXPECT_NEAR(got.y, expected.y, 1e-12 * std::max(1.0, std::abs(expected.y)));
  EXPECT_NEAR(got.z, expected.z, 1e-12 * std::max(1.0, std::abs(expected.z)));
}

}  // namespace

// As pre_ (and post_) terms the running-sum variations read the point they map, not the outputs:
// the same values whatever the scratch held, and as pre_ and post_ alike.
TEST(RemainingVariations, PreAndPostTermsReadThePointNotTheSum) {
  const std::vector<PointCase> cases = {
      {"cubic3D", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.32500000000000007, -0.5750000000000001, -0.275}},
      {"cubicLattice_3D",
       {1.5, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {1.1150630189063022, 1.4976311268780866, -0.7866014581297792}},
      {"popcorn2_3D",
       {},
       {0.3, -0.7, 0.0},
       0.8,
       kHighSeed,
       {0.15961392341453406, -0.2419144513889732, 0.10504156136554406}},
      {"roundspher3D",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.14367102965215908, -0.3352324025217045, 0.7394517160869318}},
      {"extrude", {0.9}, {0.3, -0.7, 0.5}, -0.8, kHighSeed, {0.3, -0.7, 0.0}},
      {"octapol", {}, {0.9, 3.2, 0.5}, 0.8, kHighSeed, {0.10800000000000001, 0.384, 0.4}},
  };
  for (const PointCase& c : cases) {
    SCOPED_TRACE(c.name);
    expectNear(runAt(c, VariationStage::Pre, {0.0, 0.0, 0.0}), c.expected);
    expectNear(runAt(c, VariationStage::Post, {0.0, 0.0, 0.0}), c.expected);
  }
}

// With no terms before them (the sum 0), popcorn2_3D adds v sin(tan c) φ to z and roundspher3D keeps
// cos r there.
TEST(RemainingVariations, AZeroSumBeforeTheTermIsFilledIn) {
  const std::vector<PointCase> cases = {
      {"popcorn2_3D",
       {0.3, -0.2, 0.5, 1.7},
       {0.3, -0.7, 0.0},
       1.4,
       kHighSeed,
       {0.08396771988763155, -0.5642899860201371, 0.49757441270828595}},
      {"roundspher3D",
       {},
       {0.3, -0.7, 0.0},
       0.8,
       kHighSeed,
       {0.13265549235531413, -0.30952948216239967, 1.0437791636302975}},
  };
  for (const PointCase& c : cases) {
    SCOPED_TRACE(c.name);
    expectNear(runAt(c, VariationStage::Normal, {0.0, 0.0, 0.0}), c.expected);
  }
}

TEST(RemainingVariations, WhatTheyReplaceAndRead) {
  EXPECT_EQ(variationOrThrow("juliaNab").replaces, VariationInfo::Replaces::Z);
  EXPECT_EQ(variationOrThrow("extrude").replaces, VariationInfo::Replaces::Z);
  for (const char* name : {"cubic3D", "cubicLattice_3D", "popcorn2_3D", "roundspher3D", "octapol"}) {
    EXPECT_TRUE(variationOrThrow(name).readsSum) << name;
    EXPECT_EQ(variationOrThrow(name).replaces, VariationInfo::Replaces::Nothing) << name;
  }
  EXPECT_FALSE(variationOrThrow("linear").readsSum);
  // extrude's result ignores the point as an ordinary term, but its pre_/post_ forms keep x and y:
  // they replace the point, they do not add to it.
  EXPECT_FALSE(variationOrThrow("extrude").additive);
  EXPECT_TRUE(variationOrThrow("Circle_Rand").additive);
}

namespace {

constexpr std::size_t kLanes = 64;

PatternLayer oneTransformLayer(std::vector<VariationTerm> terms, bool field = false) {
  FlameXform x;
  x.weight = 1.0;
  x.variations = std::move(terms);
  if (field) {
    x.fieldKind = WeightFieldKind::Noise;
    x.fieldAmount = 0.6;
    x.fieldFrequency = 3.0;
  }
  FlameGenome genome;
  genome.xforms = {x};
  PatternLayer layer;
  layer.kind = PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = std::move(genome);
  layer.color.mode = ColorMode::Index;
  return layer;
}

// One chaos-game step of every lane from one point (by default (0.3, −0.7, 0.5)) under the identity map.
struct Stepped {
  std::vector<double> x, y, z;
};
Stepped stepFromThePoint(const PatternLayer& layer, glm::dvec3 from = {0.3, -0.7, 0.5}) {
  const ChaosGame game(layer, "test");
  ChaosLanes lanes;
  lanes.resize(kLanes);
  SplitMix64 rng(5);
  for (std::size_t i = 0; i < kLanes; ++i) {
    game.seedLane(lanes, i, rng);
    lanes.x[i] = from.x;
    lanes.y[i] = from.y;
    lanes.z[i] = from.z;
  }
  Stepped s{std::vector<double>(kLanes), std::vector<double>(kLanes), std::vector<double>(kLanes)};
  std::vector<double> colour(kLanes);
  game.step(lanes, s.x.data(), s.y.data(), s.z.data(), colour.data(), kLanes);
  return s;
}

}  // namespace

// Replaces::Z: juliaNab and extrude discard the z of the terms before them (x and y are kept), and
// the terms after them add as usual.
TEST(RemainingVariations, AZReplacingTermDiscardsOnlyTheSumsZ) {
  // juliaNab's defaults: (0.8 (0.3, −0.7) + (1, 1), z) with its one branch; linear3D 2 before it.
  const Stepped nab =
      stepFromThePoint(oneTransformLayer({{"linear3D", 2.0, {}}, {"juliaNab", 0.8, {1.0, 1.0, 1.0, 1.0}}}));
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(nab.x[i], 0.6 + 1.24, 1e-12);
    EXPECT_NEAR(nab.y[i], -1.4 + 0.44, 1e-12);
    EXPECT_NEAR(nab.z[i], 0.5, 1e-12);
  }
  // extrude: z is 0.8 or 0.8 Ψ, then linear3D 0.5 adds 0.25; x and y are linear3D's alone.
  const Stepped ex =
      stepFromThePoint(oneTransformLayer({{"linear3D", 2.0, {}}, {"extrude", 0.8, {0.5}}, {"linear3D", 0.5, {}}}));
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(ex.x[i], 2.5 * 0.3, 1e-12);
    EXPECT_NEAR(ex.y[i], 2.5 * -0.7, 1e-12);
    EXPECT_GE(ex.z[i], 0.25);
    EXPECT_LE(ex.z[i], 0.8 + 0.25 + 1e-12);
  }
  // pre_extrude keeps x and y of the point and sets its z: linear3D then maps (0.3, −0.7, z').
  const Stepped pre = stepFromThePoint(oneTransformLayer({{"pre_extrude", 0.8, {0.5}}, {"linear3D", 1.0, {}}}));
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(pre.x[i], 0.3, 1e-12);
    EXPECT_NEAR(pre.y[i], -0.7, 1e-12);
    EXPECT_GE(pre.z[i], 0.0);
    EXPECT_LE(pre.z[i], 0.8);
  }
}

// An ordinary term that reads the sum before it sees that sum in the chaos game, with and without a
// weighting field. roundspher3D after linear3D 2: the sum's z (1, or f under a field's factor f) is
// kept and roundspher3D's own w² (x, y, z)/(d e) added, so z = f (1 + ρ_z) and x = f (0.6 + ρ_x).
TEST(RemainingVariations, ATermThatReadsTheSumSeesItUnderAWeightingFieldToo) {
  // ρ = (0.14367102965215908, −0.3352324025217045, 0.23945171608693183) at weight 0.8 (the point
  // case above; its z is the change of the sum's z).
  const double rx = 0.14367102965215908, ry = -0.3352324025217045, rz = 0.23945171608693183;
  for (const bool field : {false, true}) {
    SCOPED_TRACE(field ? "field" : "no field");
    const Stepped s = stepFromThePoint(oneTransformLayer({{"linear3D", 2.0, {}}, {"roundspher3D", 0.8, {}}}, field));
    bool someFactorDiffers = false;
    for (std::size_t i = 0; i < kLanes; ++i) {
      const double f = s.x[i] / (0.6 + rx);
      someFactorDiffers = someFactorDiffers || std::abs(f - 1.0) > 1e-6;
      EXPECT_NEAR(s.y[i], f * (-1.4 + ry), 1e-12);
      EXPECT_NEAR(s.z[i], f * (1.0 + rz), 1e-12);
    }
    EXPECT_EQ(someFactorDiffers, field);
  }
}

// crob moves the transform's point for the terms after it: linear after it maps the cropped point, so
// a point beyond the frame lands on the band between the inner borders (±0.5) and the frame (±1),
// twice (crob's own result plus linear's), and a point inside is left to linear. Its pre_ form sets
// the point to its result, which inside is the origin.
TEST(RemainingVariations, CrobMovesThePointForTheTermsAfterIt) {
  const std::vector<double> frame = {-1.0, 1.0, -1.0, 1.0, 1.0, 0.5, 2.0};
  const PatternLayer layer = oneTransformLayer({{"crob", 1.0, frame}, {"linear", 1.0, {}}});
  const Stepped outside = stepFromThePoint(layer, {3.0, 0.2, 0.5});
  for (std::size_t i = 0; i < kLanes; ++i) {
    const double cx = outside.x[i] / 2.0, cy = outside.y[i] / 2.0;
    EXPECT_LE(std::abs(cx), 1.0 + 1e-12);
    EXPECT_LE(std::abs(cy), 1.0 + 1e-12);
    EXPECT_TRUE(std::abs(cx) >= 0.5 || std::abs(cy) >= 0.5) << cx << ", " << cy;
    EXPECT_NEAR(outside.z[i], 1.0, 1e-12);
  }
  const Stepped inside = stepFromThePoint(layer, {0.1, 0.2, 0.5});
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_NEAR(inside.x[i], 0.1, 1e-12);
    EXPECT_NEAR(inside.y[i], 0.2, 1e-12);
  }
  const Stepped pre =
      stepFromThePoint(oneTransformLayer({{"pre_crob", 1.0, frame}, {"linear", 1.0, {}}}), {0.1, 0.2, 0.5});
  for (std::size_t i = 0; i < kLanes; ++i) {
    EXPECT_EQ(pre.x[i], 0.0);
    EXPECT_EQ(pre.y[i], 0.0);
    EXPECT_NEAR(pre.z[i], 0.5, 1e-12);
  }
}

// A Fractorium file names these variations' parameters after them; where one name starts another's
// (popcorn2 and popcorn2_3D, depth_blur and depth_blur2, Circle_Rand and CircleRand), each parameter
// goes to its own variation.
TEST(RemainingVariations, FractoriumFilesSetTheirParameters) {
  const std::string text =
      "<flames><flame name=\"f\"><xform weight=\"1\" color=\"0\" coefs=\"1 0 0 1 0 0\" popcorn2=\"0.5\" "
      "popcorn2_x=\"0.2\" popcorn2_3D=\"0.25\" popcorn2_3D_x=\"0.3\" popcorn2_3D_c=\"1.5\" depth_blur=\"0.1\" "
      "depth_blur_power=\"3\" depth_blur2=\"0.2\" depth_blur2_power=\"4\" depth_blur2_exp=\"2\" Circle_Rand=\"0.3\" "
      "Circle_Rand_X=\"4\" CircleRand=\"0.4\" CircleRand_X=\"6\" CircleRand_Seed=\"3\" cubicLattice_3D=\"0.5\" "
      "cubicLattice_3D_style=\"2\"/></flame></flames>";
  const ImportedFlame flame = readFlameXml(text, "f.flame").flame;
  ASSERT_EQ(flame.genome.xforms.size(), 1u);
  const auto param = [&](const std::string& name, const std::string& parameter) {
    for (const VariationTerm& term : flame.genome.xforms[0].variations)
      if (term.name == name)
        return term.params.at(static_cast<std::size_t>(variationOrThrow(name).paramIndex(parameter)));
    ADD_FAILURE() << "no term " << name;
    return 0.0;
  };
  EXPECT_EQ(param("popcorn2", "x"), 0.2);
  EXPECT_EQ(param("popcorn2_3D", "x"), 0.3);
  EXPECT_EQ(param("popcorn2_3D", "c"), 1.5);
  EXPECT_EQ(param("depth_blur", "power"), 3.0);
  EXPECT_EQ(param("depth_blur2", "power"), 4.0);
  EXPECT_EQ(param("depth_blur2", "exp"), 2.0);
  EXPECT_EQ(param("Circle_Rand", "X"), 4.0);
  EXPECT_EQ(param("CircleRand", "X"), 6.0);
  EXPECT_EQ(param("CircleRand", "Seed"), 3.0);
  EXPECT_EQ(param("cubicLattice_3D", "style"), 2.0);
}
