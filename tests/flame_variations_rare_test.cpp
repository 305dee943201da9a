// JWildfire's polarplot3d_wf, isosfplot3d_wf, sunflower and dc_warping (variations_jwildfire_rare.cpp) and the import
// of the files that use them (and of dc_tesla's parameters from before 2020), each at points whose expected values were
// worked out from JWildfire's Java classes by a separate Python script in double precision, independently of the code
// under test. Weight 0.8; the harness's sum starts at (0.125, −0.25, 0.5) with colour index 0.375. Random rows replay
// the lane's seed: xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594, 0.875707, … from
// 0x9E3779B9.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/parplot_formula.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

constexpr double kPi = 3.141592653589793;

// polarplot3d_wf with its default formula r = sin(param_a u) + param_b: t and u from Ψ₁ and Ψ₂ in their
// ranges (swapped where min > max), w r (sin u cos t, sin u sin t, cos u), or cylindrical w (r cos t, r sin t, u).
// sunflower: seed k = 1 + ⌊nPoints Ψ₁⌋ at √(k/(nPoints + 1)) (cos θ, sin θ), θ = k angle (3 − √5) π/180, plus
// scale (1 − ρ) (or ρ, invert) times nBlur's polygon point from Ψ₂ (spread), Ψ₃ (sector, rand(32767) mod sides)
// and Ψ₄ (radius from the hole fill · edge to the edge); parameters clamped as JWildfire's setParameter does (the
// last row). dc_warping (ColorOnly keeps the point; else (Ψ₁ − ½, Ψ₂ − ½)) at seed 6239's shifts (x0, y0) =
// (−0.4479, 0.1258) and zoom 2.5 is (123, 57, 41) at (0.1, 0.2) (grey 73/255) and (67, 39, 32) at (−0.2, 0.15)
// (grey 45/255); isosfplot3d_wf with its default formula |x| + |y| + |z| − param_a: the first of Ψ-uniform
// points of the box (Ψ₁, Ψ₂, Ψ₃ for x, y, z, and so on) within thickness of 0 (the 8th with 0x2545F491, the
// 45th with 0x9E3779B9 by default); unshifted at Ψ's point (103, 44, 30) (grey 58/255). With reset_z, z is grey ·
// scale_z + offset_z (the sum's 0.5 replaced).
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"polarplot3d_wf",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-1.5865643095791997, 1.499924473526369, -0.31301318091616936}},
      {"polarplot3d_wf",
       {1.0, -kPi, kPi, -kPi, kPi, -2.0, 2.0, 1.0, 1.0, 2.0, 1.0, 0.1, 1.0, 5.0, 2.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.4254205859816591, -0.9566932363890097, 1.888509214443937}},
      {"polarplot3d_wf",
       {-1.0, 3.0, -3.0, -1.5, 1.5, 2.0, -2.0, 0.0, 1.0, 3.0, 1.0, 0.1, 1.0, 5.0, 2.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.1849544864615806, 0.21692970069344547, 2.083549943163138}},
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 0.0, 1.0, 4.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.1613798973816929, 0.3174172084523822, -0.16923990801005792}},
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 1.0, 1.0, 1.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.15438583148992424, 0.18107628994106514, 0.10878124237060548}},
      {"sunflower", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6879892660205762, 0.29794898633234024, 0.4}},
      {"sunflower",
       {1000.0, 10.0, 0.02, 180.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.3898346488151023, 0.2243469990811919, 0.4}},
      {"sunflower",
       {300.0, 5.0, 0.3, 137.5, 0.0, 0.4, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.7841629221365718, 0.08198392687971892, 0.4}},
      {"sunflower",
       {2000.0, 2.0, -1.0, 400.0, 0.0, 2.0, 3.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.22562627856919204, 0.3895768282333281, 0.4}},
      {"dc_warping",
       {6239.0, 2.5, -0.44785959212788384, 0.12577015000039604, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.1, 0.2, 0.5},
       0.8,
       kHighSeed,
       {0.08000000000000002, 0.16000000000000003, -0.2568627450980392}},
      {"dc_warping",
       {6239.0, 2.5, -0.44785959212788384, 0.12577015000039604, 1.0, 2.0, 2.0, 0.0, 0.0},
       {-0.2, 0.15, 0.5},
       0.8,
       kHighSeed,
       {-0.16000000000000003, 0.12, 0.7529411764705882}},
      {"dc_warping",
       {0.0, 1.0, 0.0, 0.0, 0.0, 2.0, 0.5, 0.25, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.14672517776489258, 0.30056557655334476, 0.7637254901960784}},
      {"dc_warping", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3035731315612793, 0.03626041412353516, -0.5}},
      {"isosfplot3d_wf",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.6304583072662354, 0.08319454193115235, -0.06712603569030762}},
      {"isosfplot3d_wf",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.04269132614135743, 0.4048972606658936, -0.38248972892761235}},
      {"isosfplot3d_wf",
       {-1.0, 1.0, -1.0, -1.0, 1.0, -1.5, 1.5, 0.3, 160.0, 1.0, 4.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.6071462631225586, 0.07252082824707032, -0.2542346477508545}},
      {"isosfplot3d_wf",
       {-1.0, -1.0, 1.0, -1.0, 1.0, -1.5, 1.5, 0.2, 160.0, 1.0, 6.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.13487062454223633, 0.19527721405029297, 0.18136882781982422}},
      // Three tries at a shell 10⁻⁴ thick find nothing: the point adds nothing (and is hidden).
      {"isosfplot3d_wf",
       {-1.0, -1.0, 1.0, -1.0, 1.0, -1.5, 1.5, 0.0001, 3.0, 1.0, 6.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.0, 0.0, 0.0}},
  };
  return cases;
}

class RareVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(RareVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireRare, RareVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// polarplot3d_wf's colour: u's place (mode 2), r's in [rmin, rmax] (3, clamped), t's times u's (4), t's (1).
// sunflower's is 1 − ρ (ρ inverted). dc_warping's grey level with Gradient 2; Gradient 0 leaves the index.
const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      {"polarplot3d_wf", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.545325517654419},
      {"polarplot3d_wf",
       {-1.0, 3.0, -3.0, -1.5, 1.5, 2.0, -2.0, 0.0, 1.0, 3.0, 1.0, 0.1, 1.0, 5.0, 2.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       1.0},
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 0.0, 1.0, 4.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       0.2772431591649749},
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 1.0, 1.0, 1.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.8794664144515991},
      // direct_color 0, and the colour map's mode 0, leave the index.
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 1.0, 0.0, 1.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       kStartColour},
      {"polarplot3d_wf",
       {-1.0, -3.0, 3.0, -1.5, 1.5, -2.0, 2.0, 1.0, 1.0, 0.0, 1.0, 0.1, 1.0, -1.5, 0.5, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       kStartColour},
      {"sunflower", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.06285352640366204},
      {"sunflower", {300.0, 5.0, 0.3, 137.5, 0.0, 0.4, 1.0}, {0.3, -0.7, 0.5}, kHighSeed, 0.9365235778986737},
      {"dc_warping",
       {6239.0, 2.5, -0.44785959212788384, 0.12577015000039604, 1.0, 2.0, 0.5, 0.1, 1.0},
       {0.1, 0.2, 0.5},
       kHighSeed,
       73.0 / 255.0},
      {"dc_warping", {}, {0.3, -0.7, 0.5}, kHighSeed, kStartColour},
      {"isosfplot3d_wf", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.05989159735060315},
      {"isosfplot3d_wf",
       {-1.0, 1.0, -1.0, -1.0, 1.0, -1.5, 1.5, 0.3, 160.0, 1.0, 4.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.545325517654419},
      {"isosfplot3d_wf",
       {-1.0, -1.0, 1.0, -1.0, 1.0, -1.5, 1.5, 0.2, 160.0, 1.0, 6.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       0.2585891061674275},
      // octagon-b's color_mode 1 reads a colour map (none here), and a point found nowhere keeps its index.
      {"isosfplot3d_wf",
       {-1.0, -1.0, 1.0, -1.0, 1.0, -1.5, 1.5, 0.2, 160.0, 1.0, 1.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       kStartColour},
      {"isosfplot3d_wf",
       {-1.0, -1.0, 1.0, -1.0, 1.0, -1.5, 1.5, 0.0001, 3.0, 1.0, 6.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       kStartColour},
  };
  return cases;
}

class RareVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(RareVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireRare, RareVariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

TEST(FlameVariationRare, OddPointsStayFiniteOrNaNWhole) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const double v : {0.0, inf, -inf, nan, 1e300}) {
    // polarplot3d_wf and sunflower draw from their parameters alone (sunflower carries w z); dc_warping places a
    // random point of its square and sets z (reset_z).
    for (const char* name : {"polarplot3d_wf", "sunflower", "dc_warping", "isosfplot3d_wf"}) {
      const VariationInfo& info = variationOrThrow(name);
      const Outputs out = run(info, info.defaultParams(), {v, -v, 0.5}, 0.8, kHighSeed, 3);
      EXPECT_TRUE(std::isfinite(out.x[0]) && std::isfinite(out.y[0]) && std::isfinite(out.z[0])) << name << " " << v;
      EXPECT_TRUE(std::isfinite(out.colour[0])) << name << " " << v;
    }
    // dc_warping reading the point (ColorOnly): the point passes whole, the colour stays an index.
    const VariationInfo& warping = variationOrThrow("dc_warping");
    const Outputs kept = run(warping, {0.0, 1.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0}, {v, v, 0.5}, 0.8, kHighSeed, 3);
    EXPECT_TRUE(std::isfinite(kept.colour[0]) && kept.colour[0] >= 0.0 && kept.colour[0] <= 1.0) << v;
    EXPECT_EQ(kept.z[0], 0.0) << v;
  }
  // Odd parameters: polarplot3d_wf's collapsed or infinite ranges and sunflower's NaN counts neither trap nor
  // leave a colour outside [0, 1].
  const VariationInfo& polar = variationOrThrow("polarplot3d_wf");
  for (const double v : {0.0, inf, nan, 1e300}) {
    std::vector<double> params = polar.defaultParams();
    params[1] = params[2] = v;  // tmin = tmax
    params[9] = 1.0;            // the colour from t
    const Outputs out = run(polar, params, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 3);
    EXPECT_TRUE(out.colour[0] >= 0.0 && out.colour[0] <= 1.0) << v;
  }
  // isosfplot3d_wf with odd bounds, thickness and tries: no trap, no NaN, a colour index in [0, 1].
  const VariationInfo& isosf = variationOrThrow("isosfplot3d_wf");
  for (const double v : {0.0, inf, nan, 1e300, -1e300}) {
    const Outputs out =
        run(isosf, {-1.0, v, 1.0, -1.0, v, -1.5, 1.5, v, v, 1.0, 9.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
            {0.3, -0.7, 0.5}, 0.8, kHighSeed, 3);
    // (Infinite bounds and thickness find a point at infinity at once, as JWildfire does.)
    EXPECT_FALSE(std::isnan(out.x[0]) || std::isnan(out.y[0]) || std::isnan(out.z[0])) << v;
    EXPECT_TRUE(out.colour[0] >= 0.0 && out.colour[0] <= 1.0) << v;
  }
  const VariationInfo& sunflower = variationOrThrow("sunflower");
  const Outputs odd = run(sunflower, {nan, nan, 0.02, 180.0, 0.0, 0.0, nan}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 3);
  EXPECT_TRUE(std::isfinite(odd.x[0]) && std::isfinite(odd.y[0]));
}

// polarplot3d_wf's formula reads t and u; it is evaluated as parplot's surface of u and v.
TEST(FlameVariationRare, PolarplotFormulasRenameTheirVariables) {
  EXPECT_EQ(polarplotSurfaceFormulas("(sin(param_a*t) + cos(param_b*u)) + param_c")[0],
            "(sin(param_a*u) + cos(param_b*v)) + param_c");
  // Only the whole names t and u: not tan, Math's members, literals' suffixes or exponents.
  EXPECT_EQ(polarplotSurfaceFormulas("tan(t_1+u2) * Math.u + 2.5e-3f*t")[0], "tan(t_1+u2) * Math.u + 2.5e-3f*u");
  EXPECT_EQ(polarplotSurfaceFormulas("u")[1], "0");
  // v is no variable of polarplot3d_wf's: it stays unknown, and the formula does not compile.
  EXPECT_TRUE(parplotFormulaError(polarplotSurfaceFormulas("v + t")[0]).has_value());
  EXPECT_FALSE(parplotFormulaError(polarplotSurfaceFormulas("sin(param_a*u) + param_b")[0]).has_value());
  // isosfplot3d_wf's x, y, z become u, v and the evaluator's third variable; u and v name nothing there.
  EXPECT_EQ(isosfplotSurfaceFormulas("fabs(x) + fabs(y) + sqrt(fabs(z)) - 1")[0],
            "fabs(u) + fabs(v) + sqrt(fabs(isosf_z)) - 1");
  EXPECT_TRUE(parplotFormulaError(isosfplotSurfaceFormulas("x + u")[0]).has_value());
  ParplotEvaluator& octagon =
      parplotEvaluator(isosfplotSurfaceFormulas("fabs(x) + fabs(y) + sqrt(fabs(z)) - 1")[0], "0", "0");
  ASSERT_TRUE(octagon.ok());
  octagon.setThird(0.25);
  EXPECT_DOUBLE_EQ(octagon(0.5, -0.25)[0], 0.25);
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// JWildfire writes polarplot3d_wf's and isosfplot3d_wf's formula as the hex of its bytes, beside image names;
// sunflower's fill as "F. filling" (no XML name); dc_warping before 2020 only its seed, whose shifts (x0, y0) it took
// from java.util.Random(6239); dc_tesla before 2020 its unused thicknes and shift.
TEST(FlameVariationRare, ImportsTheFilesNames) {
  const ImportedFlame polar = importXform(
      R"(polarplot3d_wf="0.75" polarplot3d_wf_preset_id="1" polarplot3d_wf_cylindrical="1" polarplot3d_wf_tmin="-3" )"
      R"(polarplot3d_wf_param_a="5.0" polarplot3d_wf_formula="73696E28706172616D5F612A7529202B20706172616D5F62" )"
      R"(polarplot3d_wf_colormap_filename="" polarplot3d_wf_displ_map_filename="" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(polar.leftOut.empty()) << polar.leftOut.front();
  const VariationTerm& plot = polar.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(plot.name, "polarplot3d_wf");
  EXPECT_EQ(plot.texts, (std::vector<std::string>{"sin(param_a*u) + param_b"}));
  EXPECT_EQ(plot.params.at(1), -3.0);
  EXPECT_EQ(plot.params.at(7), 1.0);
  // A formula muParser cannot read is named; the variation then adds nothing.
  const ImportedFlame broken = importXform(R"(polarplot3d_wf="1" polarplot3d_wf_formula="762B74" coefs="1 0 0 1 0 0")");
  EXPECT_FALSE(broken.leftOut.empty());

  const std::string flower =
      "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" sunflower=\"1.0\" "
      "sunflower_nPoints=\"1000\" sunflower_shape=\"10\" sunflower_F. filling=\"0.25\" sunflower_invert=\"1\" "
      "coefs=\"1 0 0 1 0 0\"/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  const ImportedFlame sunflower = readFlameXml(flower, "t.flame").flame;
  ASSERT_TRUE(sunflower.leftOut.empty()) << sunflower.leftOut.front();
  EXPECT_EQ(sunflower.genome.xforms.at(0).variations.at(0).params,
            (std::vector<double>{1000.0, 10.0, 0.02, 180.0, 0.0, 0.25, 1.0}));

  const ImportedFlame warping =
      importXform(R"(dc_warping="1" dc_warping_randomize="6239" dc_warping_zoom="2.5" dc_warping_Gradient="2" )"
                  R"(dc_warping_z_scale="0.5" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(warping.leftOut.empty()) << warping.leftOut.front();
  EXPECT_EQ(warping.genome.xforms.at(0).variations.at(0).params,
            (std::vector<double>{6239.0, 2.5, -0.44785959212788384, 0.12577015000039604, 0.0, 2.0, 0.5, 0.0, 1.0}));
  // Since 2020 JWildfire writes x0, which shifts both ways.
  const ImportedFlame shifted =
      importXform(R"(dc_warping="1" dc_warping_randomize="6239" dc_warping_x0="0.3" coefs="1 0 0 1 0 0")");
  const std::vector<double>& params = shifted.genome.xforms.at(0).variations.at(0).params;
  EXPECT_EQ(params.at(2), 0.3);
  EXPECT_EQ(params.at(3), 0.3);

  // octagon-b's isosfplot3d_wf: its formula, box and colour map's mode.
  const ImportedFlame octagon = importXform(
      R"(isosfplot3d_wf="1.0" isosfplot3d_wf_preset_id="-1" isosfplot3d_wf_xmin="-1.0" isosfplot3d_wf_zmax="1.5" )"
      R"(isosfplot3d_wf_thickness="0.05" isosfplot3d_wf_max_iter="160" isosfplot3d_wf_color_mode="1" )"
      R"(isosfplot3d_wf_formula="66616273287829202B2066616273287929202B20737172742866616273287A2929202D2031" )"
      R"(isosfplot3d_wf_colormap_filename="" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(octagon.leftOut.empty()) << octagon.leftOut.front();
  const VariationTerm& iso = octagon.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(iso.texts, (std::vector<std::string>{"fabs(x) + fabs(y) + sqrt(fabs(z)) - 1"}));
  EXPECT_EQ(iso.params.at(10), 1.0);

  const ImportedFlame tesla = importXform(
      R"(dc_tesla="1.0" dc_tesla_levels="20" dc_tesla_thicknes="1000.0" dc_tesla_style="12.0" dc_tesla_shift="1.5" )"
      R"(dc_tesla_seed="10000" dc_tesla_time="10.732" dc_tesla_zoom="11.0" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(tesla.leftOut.empty()) << tesla.leftOut.front();
  ASSERT_EQ(tesla.genome.xforms.at(0).variations.size(), 1u);
  EXPECT_EQ(tesla.genome.xforms.at(0).variations.at(0).params.at(1), 12.0);
}

}  // namespace
