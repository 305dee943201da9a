// The variations of core/flame/variations_jwildfire_corpus.cpp, each at points whose expected values were worked
// out by a separate Python transcription of the published formulas, independently of the code under test, in
// double precision: juliacomplex from the text of dark-beam's Apophysis plugin (as Fractal Architect ships it, the
// branch drawn as C's rand() draws it), hamid_js and dc_booleans from JWildfire's HamidFunc, DC_BooleansFunc and
// DC_BaseFunc (thargor6/JWildfire, src/org/jwildfire/create/tina/variation/), dc_booleans' offset from
// java.util.Random's published algorithm. The point is (0.3, −0.7, 0.5) with weight 0.8, as in
// flame_variations_more_test.cpp; a 2D variation's z is 0.8 · 0.5 = 0.4. Random variations are replayed from the
// lane's seed: xorshift32 gives Ψ = 0.879466, 0.545326, 0.394069 from 0x2545F491 and Ψ = 0.316594, 0.875707,
// 0.483300 from 0x9E3779B9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

constexpr glm::dvec3 kPoint{0.3, -0.7, 0.5};

// hamid_js' parameters: presetId, N, filled, then a … p.
std::vector<double> hamid(double preset, double lines, double filled, std::vector<double> shape = {}) {
  std::vector<double> params = {preset, lines, filled};
  shape.resize(16, 1.0);
  params.insert(params.end(), shape.begin(), shape.end());
  return params;
}

const std::vector<PointCase>& pointCases() {
  // Notes on the rows: juliacomplex's (0.0005, 0.0002) power is below the plugin's 0.001 guard and taken as 1, and
  // with Im_p = 0 its spiral and exponential are skipped; hamid_js draws Ψ₁ for the figure, then Ψ₂ along a line, or
  // for a circle Ψ₂ > 0.05 and Ψ₃ for a filled one's radius and the next Ψ for the angle; dc_booleans' x and y are
  // w (Ψ₁ − ½, Ψ₂ − ½) (the point itself with ColorOnly), and with reset_z its z replaces the start 0.5 the rows add
  // to, so the expected change is L scale_z + offset_z − 0.5.
  static const std::vector<PointCase> cases = {
      {"juliacomplex", {}, kPoint, 0.8, kHighSeed, {-0.48200603340549253, 0.2709474846764086, 0.4}},
      {"juliacomplex", {-5.0, 4.0, 2.0, 3.0}, kPoint, 0.8, kHighSeed, {-0.5010070181695522, -0.5038827082504246, 0.4}},
      {"juliacomplex", {-5.0, 4.0, 2.0, 3.0}, kPoint, 0.8, kLowSeed, {-0.634040616046795, 0.32077766931619356, 0.4}},
      {"juliacomplex", {3.0, 0.0, 1.0, 1.0}, kPoint, 0.8, kHighSeed, {-0.577787143120772, -0.44709425832826744, 0.4}},
      {"juliacomplex",
       {0.0005, 0.0002, 1.0, 1.0},
       kPoint,
       0.8,
       kHighSeed,
       {0.60926174494537, -0.0003551705547608661, 0.4}},
      {"hamid_js", {}, kPoint, 0.8, kHighSeed, {0.38777555297575406, -0.2766995923146217, 0.4}},
      {"hamid_js", {}, kPoint, 0.8, kLowSeed, {-0.2738727125917961, 0.27392627908864114, 0.4}},
      {"hamid_js",
       hamid(1.0, 500.0, 1.0, {1.192, 1.212, 1.336}),
       kPoint,
       0.8,
       kHighSeed,
       {0.09843698771439727, -0.29151820136276746, 0.4}},
      {"hamid_js",
       hamid(4.0, 700.0, 1.0, {1.1, 0.9, 1.2, 0.8}),
       kPoint,
       0.8,
       kLowSeed,
       {0.21673218751528492, -0.06491257060702402, 0.4}},
      {"hamid_js",
       hamid(5.0, 1500.0, 0.0, {1.0, 1.2, 0.7, 1.3, 0.9, 1.1, 1.0, 0.8, 1.0, 1.5, 0.6}),
       kPoint,
       0.8,
       kHighSeed,
       {-0.31390302072979054, -0.16287619884442117, 0.4}},
      {"hamid_js", hamid(9.0, 2000.0, 1.0), kPoint, 0.8, kHighSeed, {0.3637395858764649, 0.39783572959899904, 0.4}},
      {"hamid_js", hamid(9.0, 2000.0, 1.0), kPoint, 0.8, kLowSeed, {0.29681335973739625, 0.09943442344665519, 0.4}},
      {"hamid_js", hamid(10.0, 2000.0, 1.0), kPoint, 0.8, kHighSeed, {-0.2723825592500243, 0.4608565686179848, 0.4}},
      {"hamid_js", hamid(10.0, 2000.0, 1.0), kPoint, 0.8, kLowSeed, {0.769881640603709, -0.21760930284385147, 0.4}},
      {"hamid_js",
       hamid(13.0, 3000.0, 0.0, {1.0, 1.1, 0.9, 1.2}),
       kPoint,
       0.8,
       kHighSeed,
       {0.32284564156865825, -0.7461984634269079, 0.4}},
      {"hamid_js", hamid(15.0, 1000.0, 1.0), kPoint, 0.8, kLowSeed, {0.8025431738329353, 0.1406627356295514, 0.4}},
      {"hamid_js", hamid(16.0, 2500.0, 1.0), kPoint, 0.8, kHighSeed, {0.3104034651611904, 0.5599424196964498, 0.4}},
      {"hamid_js",
       hamid(19.0, 1800.0, 1.0, {1.0, 1.2, 0.9, 1.1, 0.8, 1.0, 1.3, 1.0, 0.7, 1.0, 1.1, 1.0, 1.2}),
       kPoint,
       0.8,
       kLowSeed,
       {-0.5676676305329867, -0.7439959938123285, 0.4}},
      {"dc_booleans", {}, kPoint, 0.8, kHighSeed, {0.3035731315612793, 0.03626041412353516, -0.5}},
      {"dc_booleans",
       {3711.0, 1.0, 1000.0, 0.0, 0.0, 0.0, 0.0, 1.0},
       kPoint,
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, -0.5}},
      {"dc_booleans",
       {3711.0, 0.0, 250.0, 1.0, 2.0, 0.5, 0.1, 0.0},
       kPoint,
       0.8,
       kHighSeed,
       {0.24, -0.5599999999999999, 0.10784313725490197}},
      {"dc_booleans",
       {42.0, 2.0, 37.5, 0.0, 2.0, -1.5, 0.25, 1.0},
       kPoint,
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, -1.5558823529411765}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class FlameVariationCorpus : public testing::TestWithParam<PointCase> {};

TEST_P(FlameVariationCorpus, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, FlameVariationCorpus, testing::ValuesIn(pointCases()), caseLabel);

// juliacomplex picks its branch as C's rand() does, a whole multiple of 2π/Re_p: for Re_p = 3 (Im_p = 0) every
// point lands on one of the three cube roots' rays, never between them (a continuous draw would smear it round).
TEST(FlameVariationCorpusExtra, JuliacomplexLandsOnOneOfItsRoots) {
  const VariationInfo& info = variationOrThrow("juliacomplex");
  std::set<long> rays;
  for (std::uint32_t seed = 1; seed <= 200; ++seed) {
    const Outputs out = run(info, {3.0, 0.0, 1.0, 1.0}, kPoint, 1.0, seed * 0x9E3779B1u, 1);
    const double angle = std::atan2(out.y[0] - kStartY, out.x[0] - kStartX);
    // The root's own angle φ/3 plus k 2π/3, in units of a third of a turn.
    const double turns = (angle - std::atan2(-0.7, 0.3) / 3.0) / (2.0 * M_PI / 3.0);
    EXPECT_NEAR(turns, std::round(turns), 1e-9);
    rays.insert(std::lround(turns - 3.0 * std::floor(std::round(turns) / 3.0)));
  }
  EXPECT_EQ(rays.size(), 3u);
}

// dc_booleans' colour index is the luminance of its colour at the zoomed, offset point (Python values as above).
TEST(FlameVariationCorpusExtra, DcBooleansSetsTheColourIndexToTheLuminance) {
  const VariationInfo& info = variationOrThrow("dc_booleans");
  EXPECT_TRUE(info.directColour);
  EXPECT_DOUBLE_EQ(run(info, info.defaultParams(), kPoint, 0.8, kHighSeed, 3).colour[0], 0.13333333333333333);
  EXPECT_DOUBLE_EQ(run(info, {3711.0, 1.0, 1000.0, 0.0, 0.0, 0.0, 0.0, 1.0}, kPoint, 0.8, kLowSeed, 3).colour[0],
                   0.8156862745098039);
  EXPECT_DOUBLE_EQ(run(info, {3711.0, 0.0, 250.0, 1.0, 2.0, 0.5, 0.1, 0.0}, kPoint, 0.8, kHighSeed, 3).colour[0],
                   0.01568627450980392);
  EXPECT_DOUBLE_EQ(run(info, {42.0, 2.0, 37.5, 0.0, 2.0, -1.5, 0.25, 1.0}, kPoint, 0.8, kHighSeed, 3).colour[0],
                   0.47843137254901963);
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// JWildfire names hamid_js' N and filled "number_lines/circles" and "filled circles", and dc_booleans' type and z
// parameters "^/&/|", z_scale and z_offset in files before 2021: all are read. A Gradient other than 2 paints
// JWildfire's own colours, which are kept (VariationInfo::paintsRgb).
TEST(FlameVariationCorpusExtra, ReadsJwildfiresOddParameterNames) {
  const ImportedFlame hamidFlame =
      importXform(R"(hamid_js="2.0" hamid_js_presetId="1" hamid_js_number_lines/circles="500" )"
                  R"(hamid_js_filled circles="0" hamid_js_filled circles_enabled="false" hamid_js_a="1.192" )"
                  R"(hamid_js_p="0.5" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(hamidFlame.leftOut.empty()) << hamidFlame.leftOut.front();
  const VariationTerm& hamidTerm = hamidFlame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(hamidTerm.name, "hamid_js");
  std::vector<double> expected = hamid(1.0, 500.0, 0.0, {1.192});
  expected.back() = 0.5;
  EXPECT_EQ(hamidTerm.params, expected);

  const ImportedFlame booleans = importXform(
      R"(dc_booleans="1.0" dc_booleans_randomize="3711" dc_booleans_^/&/|="2" )"
      R"(dc_booleans_^/&/|_enabled="false" dc_booleans_zoom="500" dc_booleans_Gradient="2" )"
      R"(dc_booleans_z_scale="0.5" dc_booleans_z_offset="0.25" dc_booleans_reset_z="0" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(booleans.leftOut.empty()) << booleans.leftOut.front();
  EXPECT_EQ(booleans.genome.xforms.at(0).variations.at(0).params,
            (std::vector<double>{3711.0, 2.0, 500.0, 0.0, 2.0, 0.5, 0.25, 0.0}));

  const ImportedFlame trueColour = importXform(R"(dc_booleans="1.0" dc_booleans_Gradient="0" coefs="1 0 0 1 0 0")");
  EXPECT_TRUE(trueColour.leftOut.empty()) << trueColour.leftOut.front();
}

}  // namespace
