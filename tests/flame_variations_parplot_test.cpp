// parplot2d_wf (JWildfire's parametric surface of formulas: variations_parplot.cpp, parplot_formula.cpp):
// its formulas as muParser reads them after the Java rewrite, the surface at points whose (u, v) is
// known, its direct colour, the import of its text parameters and the warnings, threads, and a
// formula's NaN in the chaos game.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "core/chaos_game.h"
#include "core/flame/flame.h"
#include "core/flame/parplot_formula.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/random.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "variation_point_case.h"

namespace voxflame::test {
namespace {

using core::VariationInfo;
using core::VariationInput;

constexpr double kPi = std::numbers::pi;

// The catalogue's parameters with the ones named changed (the order: preset_id, umin, umax, vmin,
// vmax, direct_color, color_mode, blend_colormap, displ_amount, blend_displ_map, solid, param_a … f).
struct Surface {
  double umin = 0.0, umax = 2.0 * kPi, vmin = 0.0, vmax = 2.0 * kPi;
  double directColor = 1.0, colorMode = 3.0, solid = 1.0;
  std::array<double, 6> abcdef = {0, 0, 0, 0, 0, 0};
};
std::vector<double> params(const Surface& s) {
  std::vector<double> p = core::variationOrThrow("parplot2d_wf").defaultParams();
  EXPECT_EQ(p.size(), 17u);
  p[1] = s.umin;
  p[2] = s.umax;
  p[3] = s.vmin;
  p[4] = s.vmax;
  p[5] = s.directColor;
  p[6] = s.colorMode;
  p[10] = s.solid;
  std::copy(s.abcdef.begin(), s.abcdef.end(), p.begin() + 11);
  return p;
}

struct LaneResult {
  double x, y, z, colour;
};

// parplot2d_wf over `lanes` lanes at the points (px[i], py[i], 0.5), formulas `texts`, from the
// colour 0.375; the lanes' generators seeded from `seed` by SplitMix64 (never 0).
std::vector<LaneResult> runParplot(const std::vector<std::string>& texts, const std::vector<double>& p,
                                   const std::vector<double>& px, const std::vector<double>& py, double weight = 1.0,
                                   std::uint32_t seed = kHighSeed) {
  const VariationInfo& info = core::variationOrThrow("parplot2d_wf");
  const std::size_t lanes = px.size();
  std::vector<double> zs(lanes, 0.5), ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0), colour(lanes, 0.375);
  std::vector<std::uint32_t> random(lanes);
  core::SplitMix64 seeds(seed);
  for (std::uint32_t& state : random) state = static_cast<std::uint32_t>(seeds.next() >> 32) | 1u;
  VariationInput in;
  in.x = px.data();
  in.y = py.data();
  in.z = zs.data();
  in.tx = px.data();
  in.ty = py.data();
  in.tz = zs.data();
  in.random = random.data();
  in.count = lanes;
  in.weight = weight;
  in.params = p.data();
  in.affine = kAffine;
  in.colour = colour.data();
  in.texts = texts.empty() ? nullptr : texts.data();
  info.apply(in, ox.data(), oy.data(), oz.data());
  std::vector<LaneResult> out;
  for (std::size_t i = 0; i < lanes; ++i) out.push_back({ox[i], oy[i], oz[i], colour[i]});
  return out;
}

// One formula's value at (u, v) with param_a … param_f = 0.5, 1, 1.5, 2, 2.5, 3.
double valueOf(const std::string& formula, double u, double v) {
  core::ParplotEvaluator evaluator(formula, "0", "0");
  EXPECT_TRUE(evaluator.ok()) << formula << ": " << core::parplotFormulaError(formula).value_or("");
  const double abcdef[6] = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
  evaluator.setParams(abcdef);
  return evaluator(u, v)[0];
}

TEST(ParplotFormula, JwildfireFunctionsConstantsAndJavaSyntaxEvaluate) {
  struct Row {
    std::string formula;
    double u, v, expected;
  };
  const std::vector<Row> rows = {
      {"u*v + pi", 2.0, 3.0, 6.0 + kPi},
      {"param_a + param_b*10 + param_c*100 + param_d*1000 + param_e*1e4 + param_f*1e5", 0, 0, 327160.5},
      {"sqr(u) + fabs(v)", 3.0, -2.0, 11.0},
      {"atan2(v, u)", -1.0, 0.0, kPi},
      {"pow(u, 10) + sqrt(v)", 2.0, 9.0, 1027.0},
      {"cosh(u) - sinh(u) - exp(-u)", 0.7, 0.0, 0.0},
      {"log(M_E) + log10(100)", 0, 0, 3.0},
      // Java's % on doubles keeps the dividend's sign, and binds as * and / do.
      {"u % 3 * 2", 7.0, 0.0, 2.0},
      {"u % 2", -7.5, 0.0, -1.5},
      {"fmod(u, v)", 7.5, 2.0, 1.5},
      // Java's rounding: rint to the even neighbour, round half up, trunc and frac towards 0.
      {"rint(u)", 2.5, 0.0, 2.0},
      {"round(u)", -2.5, 0.0, -2.0},
      {"trunc(u) + frac(u)*100", -2.25, 0.0, -27.0},
      {"floor(u) + ceil(v)", -1.5, 1.2, 0.0},
      {"sign(u) + signum(v)", -3.0, 0.0, -1.0},
      {"min(u, v) + max(u, v)*10", 1.0, 2.0, 21.0},
      {"erf(0) + M_2PI - 2*M_PI + M_PI_2*2 - pi", 0, 0, 0.0},
      // What Java writes that muParser would not read: qualified names, literal suffixes, casts.
      {"Math.sin(u) + MathLib.M_PI + Math.PI", 0.5, 0.0, std::sin(0.5) + 2.0 * kPi},
      {"2.0f*3d + 1.5e1 + .5", 0, 0, 21.5},
      {"(double)u/2 + ( float )v", 3.0, 1.0, 2.5},
      {"u > 1 ? 10 : 20", 2.0, 0.0, 10.0},
      {"!(u > 1) ? 10 : 20", 2.0, 0.0, 20.0},
      {"u != v && u >= 1 || v == 3", 1.0, 2.0, 1.0},
      {"", 1.0, 1.0, 0.0},  // JWildfire's empty formula is 0
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(row.formula);
    EXPECT_EQ(core::parplotFormulaError(row.formula), std::nullopt);
    EXPECT_NEAR(valueOf(row.formula, row.u, row.v), row.expected, 1e-12 * std::max(1.0, std::abs(row.expected)));
  }
}

TEST(ParplotFormula, WhatDoesNotCompileIsReportedAndEvaluatesToNothing) {
  // A bare `e` is no name of JWildfire's either (its formulas see MathLib's M_E), nor are x and y.
  const std::vector<std::string> bad = {
      "sin(u",   "foo(u)", "u v",   "e", "x + y", "1, 2", "(int)u", "u +", "   ", "\"s\"", std::string(30000, '('),
      "sin(u))", "u ** 2", "u ^^ 2"};
  for (const std::string& formula : bad) {
    SCOPED_TRACE(formula.substr(0, 40));
    const auto error = core::parplotFormulaError(formula);
    ASSERT_TRUE(error.has_value());
    EXPECT_FALSE(error->empty());
    core::ParplotEvaluator evaluator("u", formula, "v");
    EXPECT_FALSE(evaluator.ok());
  }
  // The variation then adds nothing at all, and leaves the colour alone.
  const auto out = runParplot({"u", "sin(", "v"}, params({}), {0.2, 0.4}, {0.1, 0.3});
  for (const LaneResult& r : out) {
    EXPECT_EQ(r.x, 0.0);
    EXPECT_EQ(r.y, 0.0);
    EXPECT_EQ(r.z, 0.0);
    EXPECT_EQ(r.colour, 0.375);
  }
}

TEST(Parplot2dWf, ConstantFormulasAndCollapsedRangesGiveExactPoints) {
  // x = param_a, y = 2, z = u − u: one point whatever u and v are.
  Surface s;
  s.abcdef = {0.7, 0, 0, 0, 0, 0};
  for (const LaneResult& r : runParplot({"param_a", "2", "u-u"}, params(s), {0.1, 0.6, -3.0}, {0.2, 0.9, 7.0}, 0.8)) {
    EXPECT_DOUBLE_EQ(r.x, 0.56);
    EXPECT_DOUBLE_EQ(r.y, 1.6);
    EXPECT_EQ(r.z, 0.0);
  }
  // umin = umax and vmin = vmax: every draw gives (u, v) = (0.5, −0.25).
  Surface collapsed;
  collapsed.umin = collapsed.umax = 0.5;
  collapsed.vmin = collapsed.vmax = -0.25;
  collapsed.colorMode = 1.0;
  for (const LaneResult& r :
       runParplot({"u*v", "sin(u) + v", "pow(u, 2)"}, params(collapsed), {0.1, 0.6, 0.9}, {0.2, 0.4, 0.8}, 2.0)) {
    EXPECT_DOUBLE_EQ(r.x, -0.25);
    EXPECT_DOUBLE_EQ(r.y, 2.0 * (std::sin(0.5) - 0.25));
    EXPECT_DOUBLE_EQ(r.z, 0.5);
    EXPECT_EQ(r.colour, 0.0);  // (u − umin) / 0: JWildfire's NaN, the chaos game's 0
  }
}

TEST(Parplot2dWf, SolidDrawsUAndVWhereSolid0ReadsThemFromThePoint) {
  // solid 0: u = umin + x (umax − umin), v = vmin + y (vmax − vmin), bounds in either order.
  Surface s;
  s.solid = 0.0;
  s.umin = 3.0;
  s.umax = -1.0;  // swapped: [−1, 3]
  s.vmin = 10.0;
  s.vmax = 12.0;
  const auto out = runParplot({"u", "v", "u*v"}, params(s), {0.25, 1.5}, {0.5, -1.0});
  EXPECT_DOUBLE_EQ(out[0].x, 0.0);
  EXPECT_DOUBLE_EQ(out[0].y, 11.0);
  EXPECT_DOUBLE_EQ(out[1].x, 5.0);
  EXPECT_DOUBLE_EQ(out[1].y, 8.0);
  EXPECT_DOUBLE_EQ(out[1].z, 40.0);
  // solid 1: (u, v) uniform in the rectangle, whatever the point; lanes differ.
  Surface solid;
  solid.umin = -1.0;
  solid.umax = 3.0;
  solid.vmin = 10.0;
  solid.vmax = 12.0;
  const std::vector<double> zeros(4000, 0.0);
  const auto drawn = runParplot({"u", "v", "0"}, params(solid), zeros, zeros);
  double meanU = 0.0, meanV = 0.0;
  for (const LaneResult& r : drawn) {
    EXPECT_TRUE(r.x >= -1.0 && r.x < 3.0) << r.x;
    EXPECT_TRUE(r.y >= 10.0 && r.y < 12.0) << r.y;
    meanU += r.x / 4000.0;
    meanV += r.y / 4000.0;
  }
  EXPECT_NEAR(meanU, 1.0, 0.06);
  EXPECT_NEAR(meanV, 11.0, 0.03);
}

TEST(Parplot2dWf, DirectColourIsUVOrTheirProductClamped) {
  Surface s;
  s.solid = 0.0;  // (s, t) = the point's (x, y)
  const std::vector<double> px = {0.25, 0.8, 1.5, -0.2}, py = {0.5, 0.1, 0.5, 0.5};
  const auto colours = [&](double directColor, double mode) {
    Surface c = s;
    c.directColor = directColor;
    c.colorMode = mode;
    std::vector<double> got;
    for (const LaneResult& r : runParplot({"u", "v", "0"}, params(c), px, py)) got.push_back(r.colour);
    return got;
  };
  const auto expectColours = [](const std::vector<double>& got, const std::vector<double>& expected) {
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-15) << "lane " << i;
  };
  expectColours(colours(1, 1), {0.25, 0.8, 1.0, 0.0});         // u
  expectColours(colours(1, 2), {0.5, 0.1, 0.5, 0.5});          // v
  expectColours(colours(1, 3), {0.125, 0.08, 0.75, 0.0});      // u · v, clamped after
  expectColours(colours(1, 7), {0.125, 0.08, 0.75, 0.0});      // any other mode: u · v
  expectColours(colours(0, 2), {0.375, 0.375, 0.375, 0.375});  // direct_color 0: untouched
  expectColours(colours(1, 0), {0.375, 0.375, 0.375, 0.375});  // the colour map's: no image here
}

TEST(Parplot2dWf, ThreadsGiveWhatOneThreadGives) {
  // Four threads, each alternating between two surfaces (so each compiles both, and its cache
  // switches), give lane for lane what one thread gives.
  const std::vector<std::string> trefoil = {"2.0*sin(3.0*u)/(2.0+cos(v))",
                                            "2.0*(sin(u)+2.0*sin(2.0*u))/(2.0+cos(v+2.0*pi/3.0))",
                                            "(cos(u)-2.0*cos(2.0*u))*(2.0+cos(v))/4.0"};
  const std::vector<std::string> sphere = {"cos(u*param_a)*sin(v*param_b)", "sin(u*param_a)*sin(v*param_b)",
                                           "cos(v*param_b)"};
  Surface s;
  s.abcdef = {1.0, 0.5, 0, 0, 0, 0};
  const std::vector<double> p = params(s), px(257, 0.1), py(257, 0.2);
  const auto reference = [&](int k) { return runParplot(k % 2 ? sphere : trefoil, p, px, py, 1.0, 1000u + k); };
  std::vector<std::vector<LaneResult>> expected;
  for (int k = 0; k < 16; ++k) expected.push_back(reference(k));
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 20; ++round)
        for (int k = 0; k < 16; ++k) {
          const auto got = reference(k);
          for (std::size_t i = 0; i < got.size(); ++i)
            if (got[i].x != expected[k][i].x || got[i].y != expected[k][i].y || got[i].z != expected[k][i].z ||
                got[i].colour != expected[k][i].colour)
              ++mismatches[t];
        }
    });
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < 4; ++t) EXPECT_EQ(mismatches[t], 0) << "thread " << t;
}

// The hex of a text's bytes, as JWildfire writes a resource.
std::string hexOf(const std::string& text) {
  std::string out;
  char two[3];
  for (const char c : text) {
    std::snprintf(two, sizeof two, "%02X", static_cast<unsigned char>(c));
    out += two;
  }
  return out;
}

// A JWildfire flame of one parplot2d_wf transform, with `extra` attributes on it.
std::string parplotFlame(const std::string& x, const std::string& y, const std::string& z, const std::string& extra) {
  return "<flames><flame name=\"plot\" version=\"JWildfire V7.50\"><xform weight=\"1\" color=\"0\" "
         "parplot2d_wf=\"0.5\" parplot2d_wf_preset_id=\"-1\" parplot2d_wf_umin=\"-3.0\" parplot2d_wf_umax=\"3.0\" "
         "parplot2d_wf_vmin=\"-1.5\" parplot2d_wf_vmax=\"2.5\" parplot2d_wf_direct_color=\"1\" "
         "parplot2d_wf_color_mode=\"2\" parplot2d_wf_blend_colormap=\"1\" parplot2d_wf_displ_amount=\"0.1\" "
         "parplot2d_wf_blend_displ_map=\"1\" parplot2d_wf_solid=\"1\" parplot2d_wf_param_a=\"0.25\" "
         "parplot2d_wf_param_f=\"-2.0\" parplot2d_wf_fx_priority=\"0\" parplot2d_wf_colormap_filename=\"\" "
         "parplot2d_wf_displ_map_filename=\"\"" +
         (x.empty() ? "" : " parplot2d_wf_xformula=\"" + hexOf(x) + "\"") +
         (y.empty() ? "" : " parplot2d_wf_yformula=\"" + hexOf(y) + "\"") +
         (z.empty() ? "" : " parplot2d_wf_zformula=\"" + hexOf(z) + "\"") + " " + extra +
         " coefs=\"1 0 0 1 0 0\"/></flame></flames>";
}

TEST(Parplot2dWf, AFlameImportsItsFormulasAndParametersWhole) {
  const core::ImportedFlame flame =
      core::readFlameXml(parplotFlame("u+(1.0/10.0)*sin(10.0*v)", "param_a*v", "sin(pi*v)/(2.0*pi*v)", ""),
                         "plot.flame")
          .flame;
  EXPECT_TRUE(flame.leftOut.empty()) << ::testing::PrintToString(flame.leftOut);
  for (const std::string& warning : flame.warnings)  // (the palette this test's flame leaves out is)
    EXPECT_EQ(warning.find("parplot2d_wf"), std::string::npos) << warning;
  const core::VariationTerm& term = flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "parplot2d_wf");
  EXPECT_EQ(term.texts, (std::vector<std::string>{"u+(1.0/10.0)*sin(10.0*v)", "param_a*v", "sin(pi*v)/(2.0*pi*v)"}));
  const VariationInfo& info = core::variationOrThrow("parplot2d_wf");
  EXPECT_DOUBLE_EQ(term.params.at(info.paramIndex("umin")), -3.0);
  EXPECT_DOUBLE_EQ(term.params.at(info.paramIndex("vmax")), 2.5);
  EXPECT_DOUBLE_EQ(term.params.at(info.paramIndex("color_mode")), 2.0);
  EXPECT_DOUBLE_EQ(term.params.at(info.paramIndex("param_a")), 0.25);
  EXPECT_DOUBLE_EQ(term.params.at(info.paramIndex("param_f")), -2.0);
  // The scene keeps the formulas.
  const core::Scene scene = core::sceneFromImportedFlame(flame, core::defaultScene());
  const core::Scene back = core::sceneFromJson(core::sceneToJson(scene), "plot.json");
  EXPECT_EQ(back.layers.at(0).flame.xforms.at(0).variations.at(0).texts, term.texts);
}

TEST(Parplot2dWf, ABadFormulaAMissingOneAndAnImageAreReported) {
  const auto has = [](const std::vector<std::string>& list, const std::string& what) {
    return std::find(list.begin(), list.end(), what) != list.end();
  };
  // A formula muParser cannot read: named with the variation and muParser's message.
  const core::ImportedFlame bad = core::readFlameXml(parplotFlame("u", "sin(u", "v", ""), "bad.flame").flame;
  EXPECT_TRUE(has(bad.leftOut, "yformula of parplot2d_wf")) << ::testing::PrintToString(bad.leftOut);
  const auto said = std::find_if(bad.warnings.begin(), bad.warnings.end(), [](const std::string& warning) {
    return warning.find("parplot2d_wf") != std::string::npos;
  });
  ASSERT_NE(said, bad.warnings.end()) << ::testing::PrintToString(bad.warnings);
  EXPECT_NE(said->find("yformula \"sin(u\""), std::string::npos) << *said;
  EXPECT_NE(said->find("muParser: Missing parenthesis"), std::string::npos) << *said;
  // A formula left out of the file: the default stands in, and the import says so.
  const core::ImportedFlame missing = core::readFlameXml(parplotFlame("u", "v", "", ""), "missing.flame").flame;
  EXPECT_TRUE(has(missing.leftOut, "zformula of parplot2d_wf")) << ::testing::PrintToString(missing.leftOut);
  // A named colour map is an image that does not travel with the flame.
  const core::ImportedFlame image =
      core::readFlameXml(parplotFlame("u", "v", "0", "parplot2d_wf_colormap_filename=\"" + hexOf("map.png") + "\""),
                         "image.flame")
          .flame;
  EXPECT_TRUE(has(image.leftOut, "image parplot2d_wf_colormap_filename")) << ::testing::PrintToString(image.leftOut);
}

TEST(Parplot2dWf, NaNAndInfinityOfAFormulaNeverReachTheDrawnPoints) {
  // x = √u over u in [−1, 1] is NaN for half the draws, y = 1/v infinite where v = 0 (never drawn
  // exactly) and huge near it: the chaos game drops such points (NaN out) and starts them afresh.
  const core::ImportedFlame flame =
      core::readFlameXml(parplotFlame("sqrt(u)", "1/(v-0.5)", "log(u)", ""), "nan.flame").flame;
  core::PatternLayer layer;
  layer.kind = core::PatternKind::Flame;
  layer.attractor.clear();
  layer.flame = flame.genome;
  layer.color.mode = core::ColorMode::Index;
  const core::ChaosGame game(layer, "test");
  constexpr std::size_t kLanes = 512;
  core::ChaosLanes lanes;
  lanes.resize(kLanes);
  core::SplitMix64 rng(7);
  for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
  std::vector<double> x(kLanes), y(kLanes), z(kLanes), colour(kLanes);
  std::size_t drawn = 0, dropped = 0;
  for (int step = 0; step < 50; ++step) {
    game.step(lanes, x.data(), y.data(), z.data(), colour.data(), kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) {
      if (std::isnan(x[i]) || std::isnan(y[i]) || std::isnan(z[i])) {
        ++dropped;
        game.seedLane(lanes, i, rng);
        continue;
      }
      ++drawn;
      EXPECT_TRUE(std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(z[i]) && std::isfinite(colour[i]))
          << x[i] << ", " << y[i] << ", " << z[i] << ", " << colour[i];
      EXPECT_TRUE(colour[i] >= 0.0 && colour[i] <= 1.0) << colour[i];
    }
  }
  // About half the points are dropped (√u of a negative u), and the rest are drawn.
  EXPECT_GT(dropped, kLanes * 50 / 3);
  EXPECT_GT(drawn, kLanes * 50 / 3);
}

// The catalogue's own check rows: the default surface (a torus, radii 1 and 0.4, over [0, 2π]²)
// with solid 0, so that (u, v) = 2π (x, y): at (¼, ½) u = π/2, v = π, the point (0, 0.6, 0); at (⅛, ¾)
// u = π/4, v = 3π/2, the point (√½, √½, −0.4); times the weight 0.8.
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = [] {
    Surface s;
    s.solid = 0.0;
    const std::vector<double> p = params(s);
    const double h = 0.8 * std::sqrt(0.5);
    return std::vector<PointCase>{
        {"parplot2d_wf", p, {0.25, 0.5, 0.3}, 0.8, kHighSeed, {0.0, 0.48, 0.0}},
        {"parplot2d_wf", p, {0.125, 0.75, -0.6}, 0.8, kLowSeed, {h, h, -0.32}},
    };
  }();
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class FlameVariationParplot : public testing::TestWithParam<PointCase> {};
TEST_P(FlameVariationParplot, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Cases, FlameVariationParplot, testing::ValuesIn(pointCases()), caseLabel);

}  // namespace
}  // namespace voxflame::test
