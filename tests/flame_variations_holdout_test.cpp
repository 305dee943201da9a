// The variations of core/flame/variations_jwildfire_holdout.cpp (hopalong, szubieta, dc_gnarly, dc_triTile), each at
// points whose expected values were worked out from JWildfire's Java classes (HopalongFunc, SZubietaFunc with
// DrawFunc's nBlur polygon, DCGnarlyFunc, DCTriTileFunc) by a separate Python script in double precision, independently
// of the code under test. The point is (0.3, −0.7, 0.5) with weight 0.8, so a carried z is 0.4. Random draws are
// replayed from the lane's seed: xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594 first from
// 0x9E3779B9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // hopalong: w · (iterate k + 1 of the start under (x, y) → (y − sign x √|b x − c|, a − x)), k = ⌊2²⁰ Ψ⌋, the
      // point unused: k = 922187 (high seed), 331972 (low seed).
      {"hopalong", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-5.122070354772366, 8.210775176824288, 0.4}},
      {"hopalong", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {9.901557381738094, -2.1710944120407087, 0.4}},
      {"hopalong",
       {7.0, -0.4, 0.9, -0.6, 0.2, -0.3},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {2.9639583069952913, -28.448215865774745, 0.4}},
      // szubieta: cell (112, 73) of 128 × 128 (high seed), (40, 67) (low seed), (12, 39) of 40 × 60; a point of the
      // 20-gon of radius scale about the cell, times 0.1 w.
      {"szubieta", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {3.8395710150137834, 0.7193914115350925, 0.4}},
      {"szubieta", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-1.923001439430437, 0.24059540482539715, 0.4}},
      {"szubieta",
       {40.0, 60.0, 1.0, 0.8},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.6448023030886988, 0.7209526477206354, 0.4}},
      // dc_gnarly: w (p₀ + g)/2, p₀ blurred by blur (Ψ₂ + … + Ψ₇ − 3) along 2πΨ₁; z carried plus the colour's dz.
      {"dc_gnarly", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.7290720015684279, -0.8474334462795744, 0.4}},
      // mode 2 with the parameters of a published flame.
      {"dc_gnarly",
       {2.0, 0.07, 0.066, 7.0, 7.668, 4.0, 2.0, 5.0, 5.0, 1.0, 15.0, 24.0, 1.0, 0.0, 15.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-2.2559756214715945, 5.032326361244844, 0.4}},
      // mode 5 (asinh), a negative blur (uniform), distort, fmag 0.6 and reset_z: the sum's z (0.5 in the harness)
      // becomes colour · 0.4 + 0.1.
      {"dc_gnarly",
       {5.0, 0.254, 0.07, 5.724, 11.0, 2.0, 2.0, 5.0, 5.0, 1.0, 25.0, 15.0, 0.6, 0.3, -0.5, 0.4, 0.1, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.2859286528638417, -0.4071977670120497, -0.2777425061408366}},
      // mode 7 without blur and without dc: dz from the harness's colour 0.375, 0.4 + 0.375 · 0.5 − 0.2.
      {"dc_gnarly",
       {7.0, 0.2, 0.3, 1.5, 2.5, 0.7, 0.9, 1.1, 1.3, 0.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.5, -0.2, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.05061239979041274, -0.16081601787455105, 0.3875}},
      // modes 3, 4, 6, 8 and 0 (the default form) at the defaults without blur.
      {"dc_gnarly",
       {3.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.12169341714633253, -0.2807938738622564, 0.4}},
      {"dc_gnarly",
       {4.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.10008555975092695, -0.26056262294570487, 0.4}},
      {"dc_gnarly",
       {6.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.10021870381370596, -0.26191827339146034, 0.4}},
      {"dc_gnarly",
       {8.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.10014280162522478, -0.26225196262212824, 0.4}},
      {"dc_gnarly",
       {0.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.10724470595730994, -0.26265153548811965, 0.4}},
      // dc_triTile: a uniform point of the tile a random walk of subdivisions ends on (the point unused); the
      // comments give the last tile's kind and the path m of the second walk.
      // kind, m: (2, 1)
      {"dc_triTile", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6306701364484335, 0.3611117383547912, 0.4}},
      // kind, m: (2, 1)
      {"dc_triTile", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.4262260911302109, 0.17991990863096577, 0.4}},
      // kind, m: (2, 0)
      {"dc_triTile",
       {2.0, 2.0, 0.222, 0.868, 0.0, 4.0, 1.0, 2.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.11610859520733362, 0.0645616562233369, 0.4}},
      // kind, m: (1, 2)
      {"dc_triTile",
       {3.0, 1.0, 0.3, 0.6, 1.0, 2.0, 2.0, 3.0, 1.0, 3.0, 1.0, 2.0, 0.0, 2.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.2155975275569492, 0.2720811812372243, 0.4}},
      // kind, m: (2, 1)
      {"dc_triTile",
       {4.0, 1.0, 0.1, 0.9, 0.0, 5.0, 0.0, 0.0, 0.0, 2.0, 2.0, 1.0, 1.0, 3.0, 0.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.316436071729844, 0.12105574321767916, 0.4}},
      // kind, m: (2, 1)
      {"dc_triTile",
       {5.0, 2.0, 0.4, 0.55, 0.0, 3.0, 1.0, 2.0, 0.0, 2.0, 1.0, 1.0, 0.0, 2.0, 2.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.07174289833068849, 0.5167467641448974, 0.4}},
      // kind, m: (2, 3)
      {"dc_triTile",
       {6.0, 1.0, 0.2, 0.7, 1.0, 4.0, 2.0, 2.0, 0.0, 3.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.39902406583279104, 0.3957021074416638, 0.4}},
      // kind, m: (2, 31)
      {"dc_triTile",
       {6.0, 2.0, 0.2, 0.7, 0.0, 6.0, 1.0, 1.0, 0.0, 3.0, 2.0, 2.0, 0.0, 4.0, 1.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.016459955645685802, 0.3089374904779719, 0.4}},
      // dc_quadtree and dc_ducks: w · (a uniform point of the square, or with ColorOnly the point); z from the grey
      // level of the pattern's RGB colour (given in the comments) · scale_z + offset_z, with reset_z replacing the
      // harness's 0.5.
      // RGB [255, 255, 255]
      {"dc_quadtree",
       {1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 0.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3035731315612793, 0.03626041412353516, -0.5}},
      // RGB [10, 10, 255]
      {"dc_quadtree",
       {1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 2.0, 0.5, 0.1, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, -0.32941176470588235}},
      // RGB [99, 99, 255]
      {"dc_quadtree",
       {2.5, 10000.0, 1.3, 300.0, 12.0, 0.0, 2.0, 1.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3035731315612793, 0.03626041412353516, 0.8549019607843138}},
      // RGB [43, 43, 255]
      {"dc_quadtree",
       {1.5, 10000.0, 0.7, 800.0, 20.0, 1.0, 2.0, -0.4, 0.2, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.4964705882352941}},
      // RGB [0, 0, 232]
      {"dc_ducks",
       {10000.0, 10.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.6071462631225586, 0.07252082824707032, -0.5}},
      // RGB [232, 232, 232]
      {"dc_ducks",
       {10000.0, 10.0, 1.0, 0.0, 2.0, 0.5, 0.1, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.29345035552978516, 0.6011311531066895, 0.05294117647058827}},
      // RGB [0, 0, 0]
      {"dc_ducks",
       {10000.0, 25.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.6071462631225586, 0.07252082824707032, 0.4}},
      // RGB [0, 0, 232]
      {"dc_ducks",
       {10000.0, 3.0, 0.7, 1.0, 2.0, -0.4, 0.2, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.24, -0.5599999999999999, 0.5592156862745099}},
  };
  return cases;
}

class HoldoutVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(HoldoutVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireHoldout, HoldoutVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// The colour index a row's variation leaves in every one of 37 lanes (the harness's colour was 0.375), from the
// same script, at the point (0.3, −0.7, 0.5).
constexpr glm::dvec3 kPoint{0.3, -0.7, 0.5};

const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      // CircleSquares |(i² − 2 (i | j) + j²) mod 255| / 255 at (112, 73) and (40, 67); Square Tile at (12, 39).
      {"szubieta", {}, kPoint, kHighSeed, 0.1411764705882353},
      {"szubieta", {}, kPoint, kLowSeed, 0.0392156862745098},
      {"szubieta", {40.0, 60.0, 1.0, 0.8}, kPoint, kLowSeed, 0.03137254901960784},
      // |cos(x₀ + g_x color1 + s) + sin(y₀ + g_y color2 + s)| mod fmag.
      {"dc_gnarly", {}, kPoint, kHighSeed, 0.09727156000757842},
      {"dc_gnarly",
       {2.0, 0.07, 0.066, 7.0, 7.668, 4.0, 2.0, 5.0, 5.0, 1.0, 15.0, 24.0, 1.0, 0.0, 15.0, 0.0, 0.0, 0.0},
       kPoint,
       kLowSeed,
       0.8055933998421834},
      {"dc_gnarly",
       {5.0, 0.254, 0.07, 5.724, 11.0, 2.0, 2.0, 5.0, 5.0, 1.0, 25.0, 15.0, 0.6, 0.3, -0.5, 0.4, 0.1, 1.0},
       kPoint,
       kLowSeed,
       0.3056437346479085},
      // dc 0 leaves the colour alone.
      {"dc_gnarly",
       {7.0, 0.2, 0.3, 1.5, 2.5, 0.7, 0.9, 1.1, 1.3, 0.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.5, -0.2, 0.0},
       kPoint,
       kLowSeed,
       0.375},
      {"dc_gnarly",
       {4.0, 0.05, 0.05, 3.5, 3.5, 2.0, 2.0, 5.0, 5.0, 1.0, 5.0, 5.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       kPoint,
       kLowSeed,
       0.5574088588914152},
      // dc_triTile: (noise(m + 43 or 31) + col1 or col2 of the last tile's kind) mod 1.
      {"dc_triTile", {}, kPoint, kHighSeed, 0.10814591374161919},
      {"dc_triTile", {}, kPoint, kLowSeed, 0.10814591374161919},
      {"dc_triTile",
       {2.0, 2.0, 0.222, 0.868, 0.0, 4.0, 1.0, 2.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0, 2.0},
       kPoint,
       kHighSeed,
       0.47167875807158577},
      {"dc_triTile",
       {3.0, 1.0, 0.3, 0.6, 1.0, 2.0, 2.0, 3.0, 1.0, 3.0, 1.0, 2.0, 0.0, 2.0, 1.0, 1.0},
       kPoint,
       kLowSeed,
       0.9792050775509351},
      {"dc_triTile",
       {4.0, 1.0, 0.1, 0.9, 0.0, 5.0, 0.0, 0.0, 0.0, 2.0, 2.0, 1.0, 1.0, 3.0, 0.0, 2.0},
       kPoint,
       kHighSeed,
       0.06984446773763953},
      {"dc_triTile",
       {5.0, 2.0, 0.4, 0.55, 0.0, 3.0, 1.0, 2.0, 0.0, 2.0, 1.0, 1.0, 0.0, 2.0, 2.0, 1.0},
       kPoint,
       kLowSeed,
       0.9081459137416193},
      {"dc_triTile",
       {6.0, 1.0, 0.2, 0.7, 1.0, 4.0, 2.0, 2.0, 0.0, 3.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0},
       kPoint,
       kHighSeed,
       0.03456224917180939},
      {"dc_triTile",
       {6.0, 2.0, 0.2, 0.7, 0.0, 6.0, 1.0, 1.0, 0.0, 3.0, 2.0, 2.0, 0.0, 4.0, 1.0, 1.0},
       kPoint,
       kLowSeed,
       0.9959153555780255},
      // Gradient 2: the grey level; Gradient 0 (RGB) leaves the colour index.
      {"dc_quadtree", {1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 0.0, 0.0, 0.0, 1.0}, kPoint, kHighSeed, 0.375},
      {"dc_quadtree", {1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 2.0, 0.5, 0.1, 1.0}, kPoint, kLowSeed, 0.1411764705882353},
      {"dc_quadtree", {2.5, 10000.0, 1.3, 300.0, 12.0, 0.0, 2.0, 1.0, 0.0, 0.0}, kPoint, kHighSeed, 0.4549019607843137},
      {"dc_quadtree",
       {1.5, 10000.0, 0.7, 800.0, 20.0, 1.0, 2.0, -0.4, 0.2, 0.0},
       kPoint,
       kHighSeed,
       0.25882352941176473},
      {"dc_ducks", {10000.0, 10.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0}, kPoint, kHighSeed, 0.375},
      {"dc_ducks", {10000.0, 10.0, 1.0, 0.0, 2.0, 0.5, 0.1, 1.0}, kPoint, kLowSeed, 0.9058823529411765},
      {"dc_ducks", {10000.0, 25.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0}, kPoint, kHighSeed, 0.0},
      {"dc_ducks", {10000.0, 3.0, 0.7, 1.0, 2.0, -0.4, 0.2, 0.0}, kPoint, kLowSeed, 0.10196078431372549},
  };
  return cases;
}

class HoldoutVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(HoldoutVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireHoldout, HoldoutVariationSetsColour, testing::ValuesIn(colourCases()),
                         colourCaseLabel);

// hopalong ignores the point: lanes with the same draw land on the same orbit point wherever they start, and
// other parameters give another orbit (built and kept beside the first).
TEST(FlameVariationJwildfireHoldout, HopalongDependsOnTheDrawAndTheParametersAlone) {
  const VariationInfo& info = variationOrThrow("hopalong");
  const Outputs a = run(info, info.defaultParams(), {0.3, -0.7, 0.5}, 1.0, kHighSeed, 4);
  const Outputs b = run(info, info.defaultParams(), {-5.0, 2.0, 0.0}, 1.0, kHighSeed, 4);
  EXPECT_EQ(a.x[0], b.x[0]);
  EXPECT_EQ(a.y[0], b.y[0]);
  const Outputs other = run(info, {1.0, 0.5, 0.5, 0.25, 0.0, 0.0}, {0.3, -0.7, 0.5}, 1.0, kHighSeed, 4);
  EXPECT_NE(a.x[0], other.x[0]);
  const Outputs again = run(info, info.defaultParams(), {0.3, -0.7, 0.5}, 1.0, kHighSeed, 4);
  EXPECT_EQ(a.x[0], again.x[0]);
  EXPECT_EQ(a.y[0], again.y[0]);
}

// szubieta's points stay within scale of their cell's centre: over many lanes, every point is at most 0.1 w
// (scale · r_max) from a grid point (i − width/2, j − height/2) · 0.1 w, r_max the 20-gon's corner radius.
TEST(FlameVariationJwildfireHoldout, SzubietaDrawsDiscsAtTheGridCells) {
  const VariationInfo& info = variationOrThrow("szubieta");
  const std::vector<double> params = {32.0, 40.0, 0.0, 0.3};
  for (std::uint32_t seed = 1; seed < 400; ++seed) {
    const Outputs out = run(info, params, {0.0, 0.0, 0.0}, 1.0, seed * 2654435761u, 1);
    const double gx = (out.x[0] - kStartX) * 10.0, gy = (out.y[0] - kStartY) * 10.0;
    const double dx = gx - std::round(gx), dy = gy - std::round(gy);
    EXPECT_LE(std::hypot(dx, dy), 0.3 / std::cos(std::numbers::pi / 20.0) + 1e-9) << seed;
    EXPECT_GE(std::round(gx), -16.0);
    EXPECT_LE(std::round(gx), 15.0);
    EXPECT_GE(std::round(gy), -20.0);
    EXPECT_LE(std::round(gy), 19.0);
  }
}

// A JWildfire transform with the four variations, their parameters under JWildfire's names, imports whole.
TEST(FlameVariationJwildfireHoldout, ImportsJwildfiresParameterNames) {
  const std::string text =
      "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" "
      R"(hopalong="0.4" hopalong_fx_priority="0" hopalong_random="3" hopalong_a="0.7" hopalong_b="0.4" )"
      R"(hopalong_c="0.2" hopalong_startx="0.1" hopalong_starty="-0.1" szubieta="1.0" szubieta_width="64" )"
      R"(szubieta_height="100" szubieta_type="1" szubieta_scale="0.25" dc_gnarly="0.5" dc_gnarly_mode="2" )"
      R"(dc_gnarly_scalex="0.07" dc_gnarly_scaley="0.066" dc_gnarly_freqx1="7.0" dc_gnarly_freqy1="7.5" )"
      R"(dc_gnarly_freqx2="4.0" dc_gnarly_freqy2="2.0" dc_gnarly_freqx3="5.0" dc_gnarly_freqy3="5.0" )"
      R"(dc_gnarly_dc="1" dc_gnarly_color1="15.0" dc_gnarly_color2="24.0" dc_gnarly_fmag="0.9" )"
      R"(dc_gnarly_distort="0.1" dc_gnarly_blur="12.0" dc_gnarly_scale_z="0.2" dc_gnarly_offset_z="0.3" )"
      R"(dc_gnarly_reset_z="1" dc_triTile="5.0" dc_triTile_type="2" dc_triTile_t="2" dc_triTile_col1="0.222" )"
      R"(dc_triTile_col2="0.868" dc_triTile_on="0" dc_triTile_itt="4" dc_triTile_eq="1" dc_triTile_depth="2" )"
      R"(dc_triTile_on1="1" dc_triTile_itt1="3" dc_triTile_eq1="2" dc_triTile_depth1="1" dc_triTile_on2="0" )"
      R"(dc_triTile_itt2="2" dc_triTile_eq2="0" dc_triTile_depth2="3" coefs="1 0 0 1 0 0"/>)"
      R"(<color index="0" rgb="255 255 255"/></flame></flames>)";
  const ImportedFlame flame = readFlameXml(text, "t.flame").flame;
  EXPECT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 4u);
  EXPECT_EQ(terms.at(0).name, "hopalong");
  EXPECT_EQ(terms.at(0).params, (std::vector<double>{3.0, 0.7, 0.4, 0.2, 0.1, -0.1}));
  EXPECT_EQ(terms.at(1).name, "szubieta");
  EXPECT_EQ(terms.at(1).params, (std::vector<double>{64.0, 100.0, 1.0, 0.25}));
  EXPECT_EQ(terms.at(2).name, "dc_gnarly");
  EXPECT_EQ(terms.at(2).params, (std::vector<double>{2.0, 0.07, 0.066, 7.0, 7.5, 4.0, 2.0, 5.0, 5.0, 1.0, 15.0, 24.0,
                                                     0.9, 0.1, 12.0, 0.2, 0.3, 1.0}));
  EXPECT_EQ(terms.at(3).name, "dc_triTile");
  EXPECT_EQ(terms.at(3).weight, 5.0);
  EXPECT_EQ(terms.at(3).params,
            (std::vector<double>{2.0, 2.0, 0.222, 0.868, 0.0, 4.0, 1.0, 2.0, 1.0, 3.0, 2.0, 1.0, 0.0, 2.0, 0.0, 3.0}));
}

// dc_quadtree's and dc_ducks' Gradient 0 and 1 paint the point an RGB colour (VariationInfo::paintsRgb): the import
// keeps them whole, as it does Gradient 2 (a grey level as the index).
TEST(FlameVariationJwildfireHoldout, RgbGradientsOfTheDcBaseVariationsImportWhole) {
  const auto import = [](const std::string& attributes) {
    const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + attributes +
                             R"( coefs="1 0 0 1 0 0"/><color index="0" rgb="255 255 255"/></flame></flames>)";
    return readFlameXml(text, "t.flame").flame;
  };
  const ImportedFlame rgb =
      import(R"(dc_quadtree="0.45" dc_quadtree_zoom="1.0" dc_quadtree_seed="10000" dc_quadtree_time="0.0" )"
             R"(dc_quadtree_width="1000.0" dc_quadtree_levels="30" dc_quadtree_ColorOnly="0" dc_quadtree_Gradient="0" )"
             R"(dc_quadtree_scale_z="0.0" dc_quadtree_offset_z="0.0" dc_quadtree_reset_z="1")");
  EXPECT_TRUE(rgb.leftOut.empty()) << rgb.leftOut.front();
  const auto& term = rgb.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "dc_quadtree");
  EXPECT_EQ(term.params, (std::vector<double>{1.0, 10000.0, 0.0, 1000.0, 30.0, 0.0, 0.0, 0.0, 0.0, 1.0}));
  const ImportedFlame grey = import(R"(dc_ducks="1.0" dc_ducks_seed="10000" dc_ducks_time="10.0" dc_ducks_zoom="1.0" )"
                                    R"(dc_ducks_ColorOnly="0" dc_ducks_Gradient="2" dc_ducks_scale_z="0.0" )"
                                    R"(dc_ducks_offset_z="0.0" dc_ducks_reset_z="1")");
  EXPECT_TRUE(grey.leftOut.empty()) << grey.leftOut.front();
  const ImportedFlame ducksRgb = import(R"(dc_ducks="1.0" dc_ducks_Gradient="1")");
  EXPECT_TRUE(ducksRgb.leftOut.empty()) << ducksRgb.leftOut.front();
}

}  // namespace
