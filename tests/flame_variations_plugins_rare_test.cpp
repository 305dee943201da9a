// JWildfire's symmetry groups sym_bg2, sym_ng11 and sym_ng15 and its glsl_circlesblue, glsl_grid3D and glsl_mandala,
// flam3's original secant and the Apophysis plugins julian2dc and shape (variations_plugins_rare.cpp), each at points
// whose expected values were worked out from JWildfire's Java classes, flam3's old formula, julian2dc's C and (for
// shape) the superformula by a separate Python script in double precision, independently of the code under test. Weight
// 0.8; the harness's sum starts at (0.125, −0.25, 0.5) with colour index 0.375. Random rows replay the lane's seed:
// xorshift32 gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594, 0.875707, … from 0x9E3779B9.
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

// The symmetry rows pick map ⌊count Ψ₁⌋: sym_bg2 its second map with the high seed and its first with the low one,
// sym_ng11 map 7 and map 2, sym_ng15 map 10 and map 3 (of twelve: 0–5 moved by −step/2, 6–11 by +step/2). The
// parameters marked "file" are those of the published flames that use them. secant: (w x, 1/cos(w r)), y not
// weighted. julian2dc picks root ⌊|power| Ψ₁⌋ and sets the colour index (the colour table below).
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"sym_bg2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, 1.36, 0.4}},
      {"sym_bg2", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.5599999999999999, -0.5599999999999999, 0.4}},
      // file
      {"sym_bg2", {-1.0, -0.832}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.16000000000000003, 1.0272000000000001, 0.4}},
      {"sym_bg2", {-1.0, -0.832}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.16000000000000003, -0.22719999999999999, 0.4}},
      {"sym_ng11", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.36000000000000004, -0.040000000000000036, 0.4}},
      {"sym_ng11", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.040000000000000036, 0.36000000000000004, 0.4}},
      {"sym_ng11",
       {-0.4, 0.1, 0.2, 1.5, 1.25},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.6000000000000001, 0.2200000000000001, 0.4}},
      {"sym_ng11",
       {-0.4, 0.1, 0.2, 1.5, 1.25},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.2000000000000001, 0.42000000000000004, 0.4}},
      {"sym_ng15", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.07216, 0.60496, 0.4}},
      {"sym_ng15", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.07216, 0.60496, 0.4}},
      // file
      {"sym_ng15", {0.625, 1.6, 1.024}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.229206068449588, 0.8851594590428619, 0.4}},
      {"sym_ng15",
       {0.625, 1.6, 1.024},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.229206068449588, 0.06595945904286182, 0.4}},
      {"secant", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, 1.2194071216358846, 0.4}},
      // cos(w r) < 0: y negative (secant2 would add 1).
      {"secant", {}, {2.0, 0.5, 0.5}, 0.8, kHighSeed, {1.6, -12.760718720804427, 0.4}},
      {"julian2dc", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.5828419506072336, 0.3843237429403043, 0.4}},
      {"julian2dc", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.5828419506072338, -0.38432374294030425, 0.4}},
      // file
      {"julian2dc",
       {2.0, 1.0, 0.346, 0.8, 0.0, 0.3, 1.4, 0.2, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.6771290581476097, 0.4205992883825045, 0.4}},
      // power −3: root 2 with the high seed, root 0 with the low one.
      {"julian2dc",
       {-3.0, 0.5, 1.25, 1.0, 0.2, -0.1, 0.9, 0.05, -0.1},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.6805566955396543, 0.47916923643487364, 0.4}},
      {"julian2dc",
       {-3.0, 0.5, 1.25, 1.0, 0.2, -0.1, 0.9, 0.05, -0.1},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.7552510792344197, 0.34979476883549543, 0.4}},
      // shape: w (Ψ₁ − holes) R(φ) (x, y)/r, R the superformula's radius at φ.
      {"shape", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.032708234772874364, 0.07631921447004018, 0.4}},
      {"shape", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.18545054672121658, 0.43271794234950534, 0.4}},
      // file
      {"shape",
       {4.0, 1.5, 0.7, 2.0, 1.0, 1.0, -0.6},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.37874928545528386, -0.8837483327289956, 0.4}},
      {"shape",
       {4.0, 1.5, 0.7, 2.0, 1.0, 1.0, -0.6},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.234651588108916, -0.5475203722541373, 0.4}},
      {"shape",
       {5.0, 2.0, 1.5, 0.5, 0.8, 1.3, 0.25},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.20598041599301053, -0.48062097065035786, 0.4}},
      {"shape",
       {5.0, 2.0, 1.5, 0.5, 0.8, 1.3, 0.25},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.02179141292133405, -0.05084663014977945, 0.4}},
      // glsl_circlesblue: w (i/width − ½, j/10⁶ − ½), pixel (⌊Ψ₁ width⌋, ⌊Ψ₂ 10⁶⌋), whatever the point.
      {"glsl_circlesblue", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3035728, 0.03625999999999996, 0.4}},
      {"glsl_circlesblue",
       {1000.0, 10000.0, 197.572, 0.3, 60.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.1472, 0.3005648, 0.4}},
      {"glsl_grid3D", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.14672559999999998, 0.3005648, 0.4}},
      {"glsl_grid3D", {1000.0, 10000.0, 37.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3032, 0.03625999999999996, 0.4}},
      {"glsl_mandala", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3035728, 0.03625999999999996, 0.4}},
      {"glsl_mandala",
       {1000.0, 0.3, 0.2, 3.0, 5.0, 0.0, 20.0, 1.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.1472, 0.3005648, 0.4}},
      {"glsl_acrilic", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.14672559999999998, 0.3005648, 0.4}},
      {"glsl_acrilic",
       {1000.0, 10000.0, 37.25, 5.0, 30.0, 7.0, 4.0, 60.0, 20.0, 90.0, 0.5, 2.5, 4.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3032, 0.03625999999999996, 0.4}},
  };
  return cases;
}

class PluginsRareVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(PluginsRareVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(PluginsRare, PluginsRareVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// julian2dc's colour index: |ρ col + α/2π (1 − col)| mod 1, ρ and α the result's radius (weighted) and angle.
const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      {"julian2dc", {}, {0.3, -0.7, 0.5}, kHighSeed, 0.40722026460228916},
      {"julian2dc", {}, {0.3, -0.7, 0.5}, kLowSeed, 0.09277973539771085},
      {"julian2dc", {2.0, 1.0, 0.346, 0.8, 0.0, 0.3, 1.4, 0.2, 0.0}, {0.3, -0.7, 0.5}, kHighSeed, 0.5449505809211291},
      {"julian2dc", {2.0, 1.0, 0.346, 0.8, 0.0, 0.3, 1.4, 0.2, 0.0}, {0.3, -0.7, 0.5}, kLowSeed, 0.21795058092112915},
      {"julian2dc",
       {-3.0, 0.5, 1.25, 1.0, 0.2, -0.1, 0.9, 0.05, -0.1},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.18981186611116652},
      {"julian2dc",
       {-3.0, 0.5, 1.25, 1.0, 0.2, -0.1, 0.9, 0.05, -0.1},
       {0.3, -0.7, 0.5},
       kLowSeed,
       0.023145199444499998},
      // glsl_circlesblue with Gradient 1: sin(r/(r + g + b)) of the bubbles' colour at the pixel; where no bubble
      // covers it (0/0) the index is left.
      {"glsl_circlesblue",
       {1000.0, 10000.0, 197.572, 0.3, 60.0, 1.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.11404146779597489},
      {"glsl_circlesblue", {1000.0, 10000.0, 197.572, 0.3, 60.0, 1.0}, {0.3, -0.7, 0.5}, kLowSeed, 0.11643048558773295},
      {"glsl_circlesblue", {1000000.0, 10000.0, 1.0, 0.04, 40.0, 1.0}, {0.3, -0.7, 0.5}, kHighSeed, kStartColour},
      // glsl_mandala with Gradient 1: r·g of the kaleidoscope's colour (unclamped, as JWildfire leaves it).
      {"glsl_mandala",
       {1000.0, 0.3, 0.2, 3.0, 5.0, 0.0, 20.0, 1.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.1292880450066749},
      {"glsl_mandala",
       {1000.0, 0.3, 0.2, 3.0, 5.0, 0.0, 20.0, 1.0, 0.0, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       -0.07310722756676542},
      // glsl_acrilic with Gradient 1: sin(r/(r + g + b)) of the pour's colour.
      {"glsl_acrilic",
       {1000.0, 10000.0, 37.25, 5.0, 30.0, 7.0, 4.0, 60.0, 20.0, 90.0, 0.5, 2.5, 4.0, 1.0},
       {0.3, -0.7, 0.5},
       kHighSeed,
       0.9244712110079876},
      {"glsl_acrilic",
       {1000.0, 10000.0, 37.25, 5.0, 30.0, 7.0, 4.0, 60.0, 20.0, 90.0, 0.5, 2.5, 4.0, 1.0},
       {0.3, -0.7, 0.5},
       kLowSeed,
       0.5089859965351877},
  };
  return cases;
}

class PluginsRareVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(PluginsRareVariationSetsColour, ToTheHandComputedValue) {
  expectSetsTheHandComputedColour(GetParam());
}

INSTANTIATE_TEST_SUITE_P(PluginsRare, PluginsRareVariationSetsColour, testing::ValuesIn(colourCases()),
                         colourCaseLabel);

TEST(FlameVariationPluginsRare, OddPointsStayFiniteOrNaNWhole) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  // The symmetry maps are rigid motions: a finite point stays finite, a non-finite one is not made finite.
  for (const char* name : {"sym_bg2", "sym_ng11", "sym_ng15"}) {
    const VariationInfo& info = variationOrThrow(name);
    for (const double v : {0.0, 1e300, -1e300}) {
      const Outputs out = run(info, info.defaultParams(), {v, -v, v}, 0.8, kHighSeed, 3);
      EXPECT_TRUE(std::isfinite(out.x[0]) && std::isfinite(out.y[0]) && std::isfinite(out.z[0])) << name << " " << v;
    }
    for (const double v : {inf, -inf, nan}) {
      const Outputs out = run(info, info.defaultParams(), {v, 0.25, 0.5}, 0.8, kHighSeed, 3);
      EXPECT_FALSE(std::isfinite(out.x[0]) && std::isfinite(out.y[0])) << name << " " << v;
    }
  }
  // secant at the origin: (0, 1); far away cos is some number in [−1, 1], so y is finite or ±∞.
  const VariationInfo& secant = variationOrThrow("secant");
  const Outputs origin = run(secant, {}, {0.0, 0.0, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_EQ(origin.x[0] - kStartX, 0.0);
  EXPECT_DOUBLE_EQ(origin.y[0] - kStartY, 1.0);
  const Outputs far = run(secant, {}, {inf, nan, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_FALSE(std::isfinite(far.x[0]));
  // julian2dc at the image of the origin (q = 0) with a positive exponent: the origin, colour from the angle alone.
  const VariationInfo& julian2dc = variationOrThrow("julian2dc");
  const Outputs zero = run(julian2dc, julian2dc.defaultParams(), {0.0, 0.0, 0.5}, 0.8, kLowSeed, 1);
  EXPECT_EQ(zero.x[0] - kStartX, 0.0);
  EXPECT_EQ(zero.y[0] - kStartY, 0.0);
  EXPECT_TRUE(std::isfinite(zero.colour[0]) && zero.colour[0] >= 0.0 && zero.colour[0] < 1.0);
  // A negative dist sends q = 0 to infinity: the point is not finite, and neither is made up.
  const Outputs pole =
      run(julian2dc, {2.0, -1.0, 0.5, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 0.5}, 0.8, kLowSeed, 1);
  EXPECT_FALSE(std::isfinite(pole.x[0]) && std::isfinite(pole.y[0]));
  const Outputs huge = run(julian2dc, julian2dc.defaultParams(), {1e300, -1e300, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_FALSE(std::isnan(huge.x[0]) != std::isnan(huge.y[0]));
  // shape places a point within its curve whatever the point's distance: at the origin there is no direction, so
  // the point stays at the origin; a huge one stays within the curve (its r² overflows: at the origin too).
  const VariationInfo& shape = variationOrThrow("shape");
  const std::vector<double> file = {4.0, 1.5, 0.7, 2.0, 1.0, 1.0, -0.6};
  const Outputs centre = run(shape, file, {0.0, 0.0, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_EQ(centre.x[0] - kStartX, 0.0);
  EXPECT_EQ(centre.y[0] - kStartY, 0.0);
  const Outputs farOut = run(shape, file, {1e300, -1e300, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_LT(std::hypot(farOut.x[0] - kStartX, farOut.y[0] - kStartY), 0.8 * 1.6 + 1e-9);
  const Outputs notFinite = run(shape, file, {inf, nan, 0.5}, 0.8, kHighSeed, 1);
  EXPECT_FALSE(std::isfinite(notFinite.x[0]) && std::isfinite(notFinite.y[0]));
}

// A painting variation over 37 lanes: each lane paints `painted` and leaves the colour index.
void expectPaints(const std::string& name, const std::vector<double>& params, std::uint32_t seed,
                  std::uint32_t painted) {
  const VariationInfo& info = variationOrThrow(name);
  EXPECT_TRUE(info.paintsRgb);
  constexpr std::size_t kLanes = 37;
  std::vector<double> xs(kLanes, 0.3), ys(kLanes, -0.7), zs(kLanes, 0.5), ox(kLanes), oy(kLanes), oz(kLanes),
      colour(kLanes, 0.375);
  std::vector<std::uint32_t> random(kLanes, seed), rgb(kLanes, 0u);
  VariationInput in;
  in.x = in.tx = xs.data();
  in.y = in.ty = ys.data();
  in.z = in.tz = zs.data();
  in.random = random.data();
  in.count = kLanes;
  in.weight = 0.8;
  in.params = params.data();
  in.affine = kAffine;
  in.colour = colour.data();
  in.rgb = rgb.data();
  info.apply(in, ox.data(), oy.data(), oz.data());
  for (std::size_t lane = 0; lane < kLanes; ++lane) {
    EXPECT_EQ(rgb[lane], painted) << name << " lane " << lane;
    EXPECT_EQ(colour[lane], 0.375);
  }
}

// glsl_circlesblue's Gradient 0 paints the bubbles' colour at the pixel as JWildfire's dbl2int bytes (⌊256 c⌋ held
// within 0 … 255), from the same transcription: (0.0121, 0.0381, 0.0623) → (3, 9, 15) at pixel (879466, 545325) with
// the published flame's parameters; (0.2931, 1.0259, 1.2455) → (75, 255, 255) and (0.0438, 0.1585, 0.1728) → (11,
// 40, 44) on a 1000-wide grid at time 197.572; no bubble at all at pixel (316593, 875706) at time 1: black.
TEST(FlameVariationPluginsRare, CirclesblueGradientZeroPaintsTheBubblesColour) {
  expectPaints("glsl_circlesblue", {1000000.0, 10000.0, 1.0, 0.252, 100.0, 0.0}, kHighSeed, paintedRgb(3, 9, 15));
  expectPaints("glsl_circlesblue", {1000000.0, 10000.0, 1.0, 0.252, 100.0, 0.0}, kLowSeed, paintedRgb(0, 0, 0));
  expectPaints("glsl_circlesblue", {1000.0, 10000.0, 197.572, 0.3, 60.0, 0.0}, kHighSeed, paintedRgb(75, 255, 255));
  expectPaints("glsl_circlesblue", {1000.0, 10000.0, 197.572, 0.3, 60.0, 0.0}, kLowSeed, paintedRgb(11, 40, 44));
}

// glsl_grid3D paints the grey of its march through the pixel, from the same transcription: 0.1708 → 43 at pixel
// (879466, 545325) and 0.3842 → 98 at (316593, 875706) at the default time 200; 0.2236 → 57 and 0.2182 → 55 at the
// published flame's time 410.032; 0.3220 → 82 and 0.2042 → 52 on a 1000-wide grid at time 37.5.
TEST(FlameVariationPluginsRare, Grid3dPaintsItsMarchsGrey) {
  const std::vector<double> defaults = variationOrThrow("glsl_grid3D").defaultParams();
  expectPaints("glsl_grid3D", defaults, kHighSeed, paintedRgb(43, 43, 43));
  expectPaints("glsl_grid3D", defaults, kLowSeed, paintedRgb(98, 98, 98));
  expectPaints("glsl_grid3D", {1000000.0, 10000.0, 410.032}, kHighSeed, paintedRgb(57, 57, 57));
  expectPaints("glsl_grid3D", {1000000.0, 10000.0, 410.032}, kLowSeed, paintedRgb(55, 55, 55));
  expectPaints("glsl_grid3D", {1000.0, 10000.0, 37.5}, kHighSeed, paintedRgb(82, 82, 82));
  expectPaints("glsl_grid3D", {1000.0, 10000.0, 37.5}, kLowSeed, paintedRgb(52, 52, 52));
}

// glsl_mandala's Gradient 0 paints the kaleidoscope's colour, from the same transcription (JWildfire's G.atan2
// included): (0.1349, 0.5296, 0.5431) → (34, 135, 139) and (0.2933, 0.2214, 0.5799) → (75, 56, 148) with the
// defaults; (0.3835, 0.3997, 0.6349) → (98, 102, 162) and (0.6014, 0.7475, 0.8046) → (153, 191, 205) with the
// published flame's parameters; on a 1000-wide grid with five sides, no multiply fold, 21 folds and iR inverted
// (0.7949, 0.1626, 0.8717) → (203, 41, 223) and (−0.1221, 0.5985, 0.1768) → (0, 153, 45).
TEST(FlameVariationPluginsRare, MandalaGradientZeroPaintsTheKaleidoscopesColour) {
  const std::vector<double> defaults = variationOrThrow("glsl_mandala").defaultParams();
  const std::vector<double> file = {1000000.0, 0.877, -0.241245675, 1.56, 6.0, 1.5, 64.0, 0.0, 0.0, 1.0, 0.0};
  const std::vector<double> other = {1000.0, 0.3, 0.2, 3.0, 5.0, 0.0, 20.0, 1.0, 0.0, 0.0, 0.0};
  expectPaints("glsl_mandala", defaults, kHighSeed, paintedRgb(34, 135, 139));
  expectPaints("glsl_mandala", defaults, kLowSeed, paintedRgb(75, 56, 148));
  expectPaints("glsl_mandala", file, kHighSeed, paintedRgb(98, 102, 162));
  expectPaints("glsl_mandala", file, kLowSeed, paintedRgb(153, 191, 205));
  expectPaints("glsl_mandala", other, kHighSeed, paintedRgb(203, 41, 223));
  expectPaints("glsl_mandala", other, kLowSeed, paintedRgb(0, 153, 45));
}

// glsl_acrilic's Gradient 0 paints the pour's colour, from the same transcription: (0.9959, −0.1386, 0.3926) → (254,
// 0, 100) and (0.3952, −0.2707, 0.7401) → (101, 0, 189) with the defaults; (0.9700, −0.2837, 0.9877) → (248, 0, 252)
// and (0.9915, −0.1530, −0.6976) → (253, 0, 0) with the published flame's parameters; (0.9279, 0.7191, −0.8604) →
// (237, 184, 0) and (0.9989, 0.9499, −0.0783) → (255, 243, 0) on a 1000-wide grid with other parameters.
TEST(FlameVariationPluginsRare, AcrilicGradientZeroPaintsThePoursColour) {
  const std::vector<double> defaults = variationOrThrow("glsl_acrilic").defaultParams();
  const std::vector<double> file = {1000000.0, 10000.0, 152.44, 8.0, 10.0, 12.0, 18.0,
                                    12.0,      75.0,    75.0,   1.0, 1.5,  1.3,  0.0};
  const std::vector<double> other = {1000.0, 10000.0, 37.25, 5.0, 30.0, 7.0, 4.0, 60.0, 20.0, 90.0, 0.5, 2.5, 4.0, 0.0};
  expectPaints("glsl_acrilic", defaults, kHighSeed, paintedRgb(254, 0, 100));
  expectPaints("glsl_acrilic", defaults, kLowSeed, paintedRgb(101, 0, 189));
  expectPaints("glsl_acrilic", file, kHighSeed, paintedRgb(248, 0, 252));
  expectPaints("glsl_acrilic", file, kLowSeed, paintedRgb(253, 0, 0));
  expectPaints("glsl_acrilic", other, kHighSeed, paintedRgb(237, 184, 0));
  expectPaints("glsl_acrilic", other, kLowSeed, paintedRgb(255, 243, 0));
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// The files' own spellings: JWildfire writes each parameter after the variation's name (and an fx_priority that
// does not change the map), Apophysis writes julian2dc's, flam3 wrote secant without parameters.
// JWildfire writes glsl_circlesblue's "Density Pixels" with its space and its other parameters capitalised.
TEST(FlameVariationPluginsRare, ImportsCirclesbluesParameters) {
  const ImportedFlame flame =
      importXform(R"(glsl_circlesblue="1.0" glsl_circlesblue_fx_priority="0" glsl_circlesblue_Density Pixels="1000" )"
                  R"(glsl_circlesblue_Seed="10000" glsl_circlesblue_time="2.5" glsl_circlesblue_Radiusy="0.252" )"
                  R"(glsl_circlesblue_Bubles="100" glsl_circlesblue_Gradient="1" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].name, "glsl_circlesblue");
  EXPECT_EQ(terms[0].params, (std::vector<double>{1000.0, 10000.0, 2.5, 0.252, 100.0, 1.0}));
}

// glsl_acrilic's colour factors are written "Red Fac.", "Green Fac." and "Blue Fac.", spaces and dots included.
TEST(FlameVariationPluginsRare, ImportsAcrilicsParameters) {
  const ImportedFlame flame = importXform(
      R"(glsl_acrilic="1.0" glsl_acrilic_Density Pixels="1000" glsl_acrilic_Seed="10000" glsl_acrilic_time="152.44" )"
      R"(glsl_acrilic_Steps="8" glsl_acrilic_p1="10.0" glsl_acrilic_p2="12.0" glsl_acrilic_p3="18.0" )"
      R"(glsl_acrilic_p4="12.0" glsl_acrilic_p5="75.0" glsl_acrilic_p6="75.0" glsl_acrilic_Red Fac.="1.0" )"
      R"(glsl_acrilic_Green Fac.="1.5" glsl_acrilic_Blue Fac.="1.3" glsl_acrilic_Gradient="0" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].params, (std::vector<double>{1000.0, 10000.0, 152.44, 8.0, 10.0, 12.0, 18.0, 12.0, 75.0, 75.0, 1.0,
                                                  1.5, 1.3, 0.0}));
}

TEST(FlameVariationPluginsRare, ImportsTheFilesNames) {
  const ImportedFlame flame = importXform(
      R"(sym_ng15="1.0" sym_ng15_fx_priority="0" sym_ng15_radius="0.625" sym_ng15_stepx="1.6" sym_ng15_stepy="1.024" )"
      R"(julian2dc="0.5" julian2dc_power="2" julian2dc_dist="1" julian2dc_col="0.346" julian2dc_a="0.8" )"
      R"(julian2dc_b="0" julian2dc_c="0.3" julian2dc_d="1.4" julian2dc_e="0.2" julian2dc_f="0" secant="0.25" )"
      R"(coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 3u);
  for (const VariationTerm& term : terms) {
    if (term.name == "sym_ng15") {
      EXPECT_EQ(term.params, (std::vector<double>{0.625, 1.6, 1.024}));
    } else if (term.name == "julian2dc") {
      EXPECT_EQ(term.params, (std::vector<double>{2.0, 1.0, 0.346, 0.8, 0.0, 0.3, 1.4, 0.2, 0.0}));
    } else {
      EXPECT_EQ(term.name, "secant");
      EXPECT_TRUE(term.params.empty());
    }
  }
}

}  // namespace
