// JWildfire's dc_portal, dc_menger and dc_tesla (variations_jwildfire_holdout.cpp) and Apophysis' post_stun plugin
// (stun, variations_apophysis.cpp), each at points whose expected values were worked out from JWildfire's Java
// classes and the plugin's C by a separate Python script in double precision, independently of the code under test.
// Weight 0.8; the harness's sum starts at (0.125, −0.25, 0.5) with colour index 0.375. Random rows replay the lane's
// seed: xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594, 0.875707, … from 0x9E3779B9.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

// The dc_ rows: with ColorOnly the point itself is kept (w · p) and the pattern read there; Gradient 2 makes the
// grey level ⌊0.299 R⌋ + ⌊0.587 G⌋ + ⌊0.114 B⌋ over 255 the index and z = grey · scale_z + offset_z (reset_z), else
// z + w z + that. dc_portal at (0.1, 0.2) is (16, 0, 0) (grey 4/255), at (−0.2, 0.15) (255, 255, 154) (242/255);
// without ColorOnly the point is (Ψ₁ − ½, Ψ₂ − ½). dc_menger (zoom 1.55, level 5) is white at (0.2, 0.3), black
// at (0.3, −0.7). dc_tesla with example162's time 10.732 and zoom 11 is grey 241 at (0.1, 0.2), 189 at (−0.2,
// 0.15) (168 with 7 levels and style 30); its defaults (time 0) are black. stun: r² = 0.58 > r_min, m = (r + |power
// r Ψ₁|)² where above r_max, else r², the point scaled by 1/m − 1, then (3w/π atan2(x, y), 3w/2π ln r², 3w z).
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"dc_portal",
       {1000.0, 0.0, 5.0, 15.0, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.1, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08000000000000002, 0.16000000000000003, -0.39215686274509803}},
      {"dc_portal",
       {1000.0, 0.0, 5.0, 15.0, 1.0, 2.0, 2.0, 0.0, 0.0},
       {-0.2, 0.15, 0.5},
       0.8,
       kHighSeed,
       {-0.16000000000000003, 0.12, 2.2980392156862743}},
      {"dc_portal", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3035731315612793, 0.03626041412353516, -0.5}},
      {"dc_portal",
       {1000.0, 3.25, 2.5, 7.0, 0.0, 0.0, 0.5, 0.25, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, 0.6499999999999999}},
      {"dc_menger",
       {1.55, 5.0, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.2, 0.3, 0.5},
       0.8,
       kHighSeed,
       {0.16000000000000003, 0.24, 0.0980392156862745}},
      {"dc_menger", {1.55, 5.0, 1.0, 2.0, 2.0, 0.0, 0.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.56, 0.4}},
      {"dc_menger", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.14672517776489258, 0.30056557655334476, -0.5}},
      {"dc_tesla",
       {20.0, 12.0, 10000.0, 10.732000000000001, 11.0, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.1, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08000000000000002, 0.16000000000000003, 0.07058823529411762}},
      {"dc_tesla",
       {20.0, 12.0, 10000.0, 10.732000000000001, 11.0, 1.0, 2.0, 2.0, 0.0, 0.0},
       {-0.2, 0.15, 0.5},
       0.8,
       kHighSeed,
       {-0.16000000000000003, 0.12, 1.8666666666666667}},
      {"dc_tesla",
       {7.0, 30.0, 10000.0, 10.732000000000001, 11.0, 1.0, 2.0, 2.0, 0.0, 0.0},
       {-0.2, 0.15, 0.5},
       0.8,
       kHighSeed,
       {-0.16000000000000003, 0.12, 1.7098039215686276}},
      {"dc_tesla",
       {20.0, 10.0, 10000.0, 0.0, 4.0, 0.0, 2.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, -0.5}},
      {"stun", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.3093145401819759, -0.7196170624071565, 1.2000000000000002}},
      {"stun", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.3093145401819759, -4.203439633302528, 1.2000000000000002}},
      // r_min and r_max are taken in either order: (r + |½ r Ψ₁|)² ≤ max 2, so m = r² (the point reflected).
      {"stun", {0.5, 2.0, 0.25}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {2.0906854598180247, -0.4546511624698465, 1.2}},
      // r² = 0.58 ≤ r_min 0.7: the point unscaled (no draw).
      {"stun", {1.0, 0.7, 2.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {2.0906854598180247, -0.20807045425926776, 1.2}},
      // (r + |2.5 r Ψ₁|)² ≤ r_max 3: m = r² (the point reflected, scaled by 1/r² − 1).
      {"stun", {2.5, 0.1, 3.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {2.0906854598180247, -0.4546511624698465, 1.2}},
  };
  return cases;
}

class Wild2VariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(Wild2VariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireWild2, Wild2VariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      {"dc_portal", {1000.0, 0.0, 5.0, 15.0, 1.0, 2.0, 0.5, 0.1, 1.0}, {0.1, 0.2, 0.5}, kHighSeed, 4.0 / 255.0},
      {"dc_portal", {1000.0, 0.0, 5.0, 15.0, 1.0, 2.0, 0.5, 0.1, 1.0}, {-0.2, 0.15, 0.5}, kLowSeed, 242.0 / 255.0},
      {"dc_menger", {1.55, 5.0, 1.0, 2.0, 0.0, 0.0, 1.0}, {0.2, 0.3, 0.5}, kHighSeed, 254.0 / 255.0},
      {"dc_menger", {1.55, 5.0, 1.0, 2.0, 0.0, 0.0, 1.0}, {0.3, -0.7, 0.5}, kHighSeed, 0.0},
      {"dc_tesla",
       {20.0, 12.0, 10000.0, 10.732000000000001, 11.0, 1.0, 2.0, 0.0, 0.0, 1.0},
       {0.1, 0.2, 0.5},
       kHighSeed,
       240.0 / 255.0},
      // Gradient 0 paints and leaves the index.
      {"dc_tesla", {}, {0.1, 0.2, 0.5}, kHighSeed, kStartColour},
  };
  return cases;
}

class Wild2VariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(Wild2VariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireWild2, Wild2VariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

TEST(FlameVariationWild2, OddPointsStayFiniteOrNaNWhole) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  // The dc_ variations place a random point of their square whatever the point; with ColorOnly they keep it.
  for (const char* name : {"dc_portal", "dc_menger", "dc_tesla"}) {
    const VariationInfo& info = variationOrThrow(name);
    for (const double v : {0.0, inf, -inf, nan, 1e300}) {
      const Outputs out = run(info, info.defaultParams(), {v, -v, v}, 0.8, kHighSeed, 3);
      EXPECT_TRUE(std::isfinite(out.x[0]) && std::isfinite(out.y[0]) && std::isfinite(out.z[0])) << name << " " << v;
      EXPECT_LE(std::abs(out.x[0] - kStartX), 0.4) << name;
    }
  }
  // stun at the origin: r² = 0 is not beyond r_min 0, so ln 0 sends y to −∞, as the plugin does.
  const VariationInfo& stun = variationOrThrow("stun");
  const Outputs origin = run(stun, stun.defaultParams(), {0.0, 0.0, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_EQ(origin.x[0] - kStartX, 0.0);
  EXPECT_EQ(origin.y[0], -inf);
  EXPECT_DOUBLE_EQ(origin.z[0] - kStartZ, 1.2);
  const Outputs far = run(stun, stun.defaultParams(), {1e300, nan, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_TRUE(std::isnan(far.x[0]) && std::isnan(far.y[0]));
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// Apophysis writes post_stun as a post_ term; JWildfire's dc_ variations wrote z_scale and z_offset before 2021,
// and dc_menger its level capitalised.
TEST(FlameVariationWild2, ImportsTheFilesNames) {
  const ImportedFlame flame =
      importXform(R"(post_stun="1" post_stun_power="0.5" post_stun_r_max="2" dc_menger="1.0" dc_menger_ColorOnly="0" )"
                  R"(dc_menger_Gradient="2" dc_menger_Level="5" dc_menger_reset_z="0" dc_menger_z_offset="0.25" )"
                  R"(dc_menger_z_scale="0.5" dc_menger_zoom="1.55" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 2u);
  for (const VariationTerm& term : terms) {
    if (term.name == "post_stun") {
      EXPECT_EQ(variationStage(term.name), VariationStage::Post);
      EXPECT_EQ(term.params, (std::vector<double>{0.5, 0.0, 2.0}));
    } else {
      EXPECT_EQ(term.name, "dc_menger");
      EXPECT_EQ(term.params, (std::vector<double>{1.55, 5.0, 0.0, 2.0, 0.5, 0.25, 0.0}));
    }
  }
}

}  // namespace
