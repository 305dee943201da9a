// The variations of core/flame/variations_jwildfire_glsl.cpp (glsl_apollonian, dc_crackle_wf, fract_mandelbrot_wf)
// and dc_perlin's color_seed, each at points whose expected values were worked out from JWildfire's Java classes
// (GLSLApollonianFunc with js.glsl's G.rot, G.app and mat3; DCCrackleWFFunc over CrackleFunc and VoronoiTools, with
// distort 0 so that the cell centres are the grid's corners; AbstractFractWFFunc with FractMandelbrotWFFunc's
// iterators) by a separate Python script in double precision, independently of the code under test. The point is
// (0.3, −0.7, 0.5) with weight 0.8, so a carried z is 0.4. Random draws are replayed from the lane's seed: xorshift32
// gives Ψ = 0.879466, 0.545326, … from 0x2545F491 and Ψ = 0.316594, 0.875707, … from 0x9E3779B9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

// fract_mandelbrot_wf's parameters in the catalogue's order, from its defaults.
struct FractParams {
  std::vector<double> values = {100.0, -2.35, 0.75, -1.2, 1.2,  0.0, 2.0, 1.0, 1.0, 3.0,
                                -5.0,  3.0,   7.0,  4.0,  0.55, 0.0, 0.0, 0.0, 0.0, 0.0};
  FractParams& set(const char* name, double value) {
    values.at(static_cast<std::size_t>(variationOrThrow("fract_mandelbrot_wf").paramIndex(name))) = value;
    return *this;
  }
};

const std::vector<double> kPower3 = FractParams()
                                        .set("power", 3.0)
                                        .set("max_iter", 50.0)
                                        .set("clip_iter_min", 0.0)
                                        .set("clip_iter_max", 0.0)
                                        .set("scale", 2.0)
                                        .set("offsetx", 0.1)
                                        .set("offsety", -0.2)
                                        .set("scalez", 3.0)
                                        .set("offsetz", 0.25)
                                        .values;
const std::vector<double> kPower4Log = FractParams()
                                           .set("power", 4.0)
                                           .set("xmin", -1.5)
                                           .set("xmax", 1.5)
                                           .set("ymin", -1.5)
                                           .set("ymax", 1.5)
                                           .set("z_logscale", 1.0)
                                           .set("scalez", 5.0)
                                           .set("max_clip_iter", 10.0)
                                           .values;
const std::vector<double> kPower7Fill = FractParams()
                                            .set("power", 7.0)
                                            .set("xmin", -1.2)
                                            .set("xmax", 1.2)
                                            .set("ymin", -1.2)
                                            .set("ymax", 1.2)
                                            .set("clip_iter_min", 1.0)
                                            .set("clip_iter_max", -1.0)
                                            .set("max_clip_iter", 20.0)
                                            .set("z_fill", 1.0)
                                            .values;
const std::vector<double> kColourOnly =
    FractParams().set("color_only", 1.0).set("clip_iter_min", 0.0).set("clip_iter_max", 0.0).values;
const std::vector<double> kNoClipTries = FractParams().set("max_clip_iter", 0.0).values;
const std::vector<double> kHalfFill = FractParams()
                                          .set("direct_color", 0.0)
                                          .set("z_fill", 0.5)
                                          .set("clip_iter_min", 2.0)
                                          .set("max_clip_iter", 8.0)
                                          .set("scalez", -2.0)
                                          .set("z_logscale", 1.0)
                                          .values;

const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      // glsl_apollonian: w (i/width − ½, j/10⁶ − ½), pixel (⌊Ψ₁ width⌋, ⌊Ψ₂ 10⁶⌋); JWildfire's grid height stays 10⁶
      // whatever Density Pixels says. Pixels (879466, 545325), (879, 545325), (79, 875706), (683, 545325).
      {"glsl_apollonian", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.3035728, 0.03625999999999996, 0.4}},
      {"glsl_apollonian",
       {1000.0, 10000.0, 7.5, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3032, 0.03625999999999996, 0.4}},
      {"glsl_apollonian", {250.0, 10000.0, 1234.5, 1.0}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.1472, 0.3005648, 0.4}},
      {"glsl_apollonian",
       {777.0, 10000.0, 0.0, 0.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.30321750321750324, 0.03625999999999996, 0.4}},
      // dc_crackle_wf: crackle's pull of a point of the blurred disc towards its cell's centre.
      {"dc_crackle_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0015517661988218771, 0.588496476654058, 0.4}},
      {"dc_crackle_wf", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.039300953956544954, 0.5636022599431243, 0.4}},
      {"dc_crackle_wf",
       {0.35, 0.6, 0.0, 0.8, 0.0, 1.7, -0.2},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.0020336038030393934, 0.5412801498451392, 0.4}},
      {"dc_crackle_wf",
       {2.5, -0.4, 0.0, 1.3, 0.0, -0.9, 0.95},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.024706470004889954, 0.6644525008156101, 0.4}},
      // Weight 0 colours by the point and moves nothing.
      {"dc_crackle_wf", {}, {0.3, -0.7, 0.5}, 0.0, kHighSeed, {0.0, 0.0, 0.0}},
      // fract_mandelbrot_wf: w scale (c + offset), z = w scale (scalez/10 · n/max_iter + offsetz), c the first start
      // whose escape count n passes the clips: n = 16, 4, 51, 8, 4, 7 (color_only: c the point, not added), 0 (no
      // tries: c = 0), 4.
      {"fract_mandelbrot_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {2.964306831359864, 0.34809997558593725, 0.0512}},
      {"fract_mandelbrot_wf", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-2.6193922042846682, 2.8854295349121095, 0.0128}},
      {"fract_mandelbrot_wf",
       kPower3,
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.7621534156799319, -0.1459500122070314, 0.8896000000000002}},
      {"fract_mandelbrot_wf",
       kPower4Log,
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {1.076435241699219, -2.1305688858032226, 0.05347800877911957}},
      {"fract_mandelbrot_wf",
       kPower7Fill,
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {4.674302062988281, 0.34809997558593725, 0.01279886360168457}},
      {"fract_mandelbrot_wf", kColourOnly, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.0, 0.0, 0.022400000000000003}},
      {"fract_mandelbrot_wf", kNoClipTries, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {1.7600000000000002, 0.0, 0.0}},
      {"fract_mandelbrot_wf",
       kHalfFill,
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-2.6193922042846682, 2.8854295349121095, -0.010885451896845135}},
      // buddhabrot_mode without memory (a single call): the first point after the 7 skipped of the orbit of the
      // first start that escapes after more than 7 tests (16).
      {"fract_mandelbrot_wf",
       FractParams().set("buddhabrot_mode", 1.0).values,
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {3.0721958095187434, -0.2588297702163182, 0.0}},
  };
  return cases;
}

class GlslVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(GlslVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireGlsl, GlslVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// The colour index a row's variation leaves in every one of 37 lanes (the harness's colour was 0.375), from the same
// script.
struct ColourCase {
  std::string name;
  std::vector<double> params;  // empty: the defaults
  double weight;
  std::uint32_t seed;
  double colour;
};

const std::vector<ColourCase>& colourCases() {
  static const std::vector<ColourCase> cases = {
      // glsl_apollonian: Gradient 0 (an RGB colour) leaves the index; Gradient 1 makes it r·g, unclamped.
      {"glsl_apollonian", {}, 0.8, kHighSeed, 0.375},
      {"glsl_apollonian", {1000000.0, 10000.0, 0.0, 1.0}, 0.8, kLowSeed, 0.014521843454126469},
      {"glsl_apollonian", {1000.0, 10000.0, 7.5, 1.0}, 0.8, kHighSeed, 0.3777431313350718},
      {"glsl_apollonian", {250.0, 10000.0, 1234.5, 1.0}, 0.8, kLowSeed, 1.0818293370408598},
      // dc_crackle_wf: L color_scale + color_offset clamped into [0, 1]; with weight 0 L is the point's (0.8).
      {"dc_crackle_wf", {}, 0.8, kHighSeed, 0.3718229654974774},
      {"dc_crackle_wf", {}, 0.8, kLowSeed, 0.18313296161361103},
      {"dc_crackle_wf", {0.35, 0.6, 0.0, 0.8, 0.0, 1.7, -0.2}, 0.8, kHighSeed, 0.07371976373879002},
      {"dc_crackle_wf", {2.5, -0.4, 0.0, 1.3, 0.0, -0.9, 0.95}, 0.8, kLowSeed, 0.09814426763820006},
      {"dc_crackle_wf", {}, 0.0, kHighSeed, 0.4},
      {"dc_crackle_wf", {0.35, 0.2, 0.0, 1.0, 0.0, 1.0, 0.0}, 0.0, kHighSeed, 0.5714285714285713},
      {"dc_crackle_wf", {1.0, 0.2, 0.0, 1.0, 0.0, 5.0, 0.0}, 0.8, kHighSeed, 1.0},
      {"dc_crackle_wf", {1.0, 0.2, 0.0, 1.0, 0.0, 0.5, -3.0}, 0.8, kHighSeed, 0.0},
      // fract_mandelbrot_wf: the index plus n/max_iter (less 1 above 1); direct_color 0 leaves it.
      {"fract_mandelbrot_wf", {}, 0.8, kHighSeed, 0.535},
      {"fract_mandelbrot_wf", {}, 0.8, kLowSeed, 0.415},
      {"fract_mandelbrot_wf", kPower3, 0.8, kHighSeed, 0.395},
      {"fract_mandelbrot_wf", kColourOnly, 0.8, kLowSeed, 0.445},
      {"fract_mandelbrot_wf", kHalfFill, 0.8, kLowSeed, 0.375},
      {"fract_mandelbrot_wf", FractParams().set("buddhabrot_mode", 1.0).values, 0.8, kHighSeed, 0.875},
  };
  return cases;
}

class GlslVariationSetsColour : public testing::TestWithParam<ColourCase> {};

TEST_P(GlslVariationSetsColour, ToTheHandComputedValue) {
  const ColourCase& c = GetParam();
  const VariationInfo& info = variationOrThrow(c.name);
  EXPECT_TRUE(info.directColour);
  const Outputs out =
      run(info, c.params.empty() ? info.defaultParams() : c.params, {0.3, -0.7, 0.5}, c.weight, c.seed, 37);
  for (std::size_t lane = 0; lane < out.colour.size(); ++lane)
    EXPECT_NEAR(out.colour[lane], c.colour, 1e-12) << "lane " << lane;
}

std::string colourCaseLabel(const testing::TestParamInfo<ColourCase>& info) {
  return info.param.name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(JwildfireGlsl, GlslVariationSetsColour, testing::ValuesIn(colourCases()), colourCaseLabel);

// A start that never escapes within the clips (every start near the origin is inside the set) is dropped as JWildfire
// hides it: NaN, the chaos game's escape; the colour stays.
TEST(FlameVariationJwildfireGlsl, MandelbrotDropsThePointWhenEveryStartIsClipped) {
  const VariationInfo& info = variationOrThrow("fract_mandelbrot_wf");
  const std::vector<double> inside =
      FractParams().set("xmin", -0.1).set("xmax", 0.1).set("ymin", -0.1).set("ymax", 0.1).values;
  const Outputs out = run(info, inside, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  for (std::size_t lane = 0; lane < 5; ++lane) {
    EXPECT_TRUE(std::isnan(out.x[lane]));
    EXPECT_TRUE(std::isnan(out.y[lane]));
    EXPECT_TRUE(std::isnan(out.z[lane]));
    EXPECT_EQ(out.colour[lane], kStartColour);
  }
}

// In buddhabrot_mode a lane walks its orbit one point a call, keeping it in its memory, and draws a new one when the
// orbit's length is reached: the script's six calls of one lane, each from colour 0.375.
TEST(FlameVariationJwildfireGlsl, MandelbrotBuddhabrotWalksEachLanesOrbitAcrossCalls) {
  const VariationInfo& info = variationOrThrow("fract_mandelbrot_wf");
  ASSERT_EQ(info.laneState, 9u);
  struct Call {
    double x, y, colour;
  };
  const auto walk = [&](const std::vector<double>& params, std::uint32_t seed, const std::vector<Call>& calls) {
    std::vector<double> memory(2 * info.laneState, 0.0);
    std::uint32_t random[2] = {seed, seed};
    for (const Call& call : calls) {
      double x[2] = {0.3, -5.0}, y[2] = {-0.7, 4.0}, z[2] = {0.5, 0.5};
      double ox[2] = {}, oy[2] = {}, oz[2] = {}, colour[2] = {0.375, 0.375};
      VariationInput in;
      in.x = in.tx = x;
      in.y = in.ty = y;
      in.z = in.tz = z;
      in.random = random;
      in.count = 2;
      in.weight = 0.8;
      in.params = params.data();
      in.affine = kAffine;
      in.colour = colour;
      in.state = memory.data();
      info.apply(in, ox, oy, oz);
      for (int lane = 0; lane < 2; ++lane) {  // the orbit does not depend on the point
        EXPECT_NEAR(ox[lane], call.x, 1e-9 * std::max(1.0, std::abs(call.x)));
        EXPECT_NEAR(oy[lane], call.y, 1e-9 * std::max(1.0, std::abs(call.y)));
        EXPECT_EQ(oz[lane], 0.0);
        EXPECT_NEAR(colour[lane], call.colour, 1e-12);
      }
    }
  };
  walk(FractParams().set("buddhabrot_mode", 1.0).values, kHighSeed,
       {{3.0721958095187434, -0.2588297702163182, 0.875},
        {3.481452141537463, 0.1358278881755923, 0.9375},
        {3.8846031627341375, 0.4942382311986775, 1.0},
        {4.298577821960334, 1.0043875438039598, 1.0},
        {4.662926525109964, 1.9416724401821535, 1.0},
        {4.419585126742393, 3.8709327441357892, 1.0}});
  // An orbit of length 4 (after 3 skipped) ends after one call; the next call draws a new one, of length 9.
  walk(FractParams()
           .set("buddhabrot_mode", 1.0)
           .set("max_iter", 40.0)
           .set("buddhabrot_min_iter", 3.0)
           .set("power", 3.0)
           .values,
       kLowSeed,
       {{2411.3389846404334, -15493.716393770223, 1.0},
        {2.563777118173949, 3.188668536275878, 0.8194444444444444},
        {-0.8904477577391869, 1.1869310015886307, 0.9305555555555556},
        {0.7287922150863319, 6.029011341034341, 1.0},
        {12.32748722707168, -15.773410758423545, 1.0},
        {-653.5759502337468, -129.05346459802496, 1.0}});
}

// dc_perlin's color_seed (pyr3's) turns the colour index round the palette: with the same draws the index moves by
// the seed, mod 1; its default 0 keeps the colour as before.
TEST(FlameVariationJwildfireGlsl, PerlinColorSeedTurnsTheColourIndex) {
  const VariationInfo& info = variationOrThrow("dc_perlin");
  const int seedIndex = info.paramIndex("color_seed");
  ASSERT_EQ(seedIndex, static_cast<int>(info.params.size()) - 1);
  EXPECT_EQ(info.params.back().defaultValue, 0.0);
  std::vector<double> params = info.defaultParams();
  const Outputs plain = run(info, params, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  for (const double seed : {0.1, 0.65, 3.25}) {
    params[static_cast<std::size_t>(seedIndex)] = seed;
    const Outputs turned = run(info, params, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
    const double expected = plain.colour[0] + seed - std::floor(plain.colour[0] + seed);
    EXPECT_NEAR(turned.colour[0], expected, 1e-12) << seed;
    EXPECT_EQ(turned.x[0], plain.x[0]);
    EXPECT_EQ(turned.y[0], plain.y[0]);
  }
  params[static_cast<std::size_t>(seedIndex)] = std::nan("");
  EXPECT_EQ(run(info, params, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5).colour[0], plain.colour[0]);
}

// A NaN, infinite or huge parameter, one at a time, never leaves a NaN colour index (dc_perlin: its color_seed).
TEST(FlameVariationJwildfireGlsl, OddParametersNeverLeaveANanColour) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const char* name : {"glsl_apollonian", "dc_crackle_wf", "fract_mandelbrot_wf", "dc_perlin"}) {
    const VariationInfo& info = variationOrThrow(name);
    for (std::size_t k = std::string(name) == "dc_perlin" ? info.params.size() - 1 : 0; k < info.params.size(); ++k)
      for (const double odd : {std::nan(""), inf, -inf, 1e300, -1e300, 0.0}) {
        std::vector<double> params = info.defaultParams();
        params[k] = odd;
        const Outputs out = run(info, params, {0.3, -0.7, 0.5}, 0.8, kLowSeed, 3);
        for (std::size_t lane = 0; lane < 3; ++lane)
          EXPECT_FALSE(std::isnan(out.colour[lane])) << name << " " << info.params[k].name << " = " << odd;
      }
  }
}

ImportedFlame importXform(const std::string& attributes) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + attributes +
                           R"( coefs="1 0 0 1 0 0"/><color index="0" rgb="255 255 255"/></flame></flames>)";
  return readFlameXml(text, "t.flame").flame;
}

// glsl_apollonian's Gradient 0 paints the pattern's colour at the pixel as JWildfire's dbl2int bytes (⌊256 c⌋ held
// within 0 … 255), from the same transcription: (1.0957, 0.3048, 0.7743) → (255, 78, 198) at pixel (879466, 545325)
// of the default grid; (1.0240, 0.8990, 0.0256) → (255, 230, 6) on a 1000-wide grid at time 7.5. The index is left.
TEST(FlameVariationJwildfireGlsl, ApollonianGradientZeroPaintsThePatternsColour) {
  const VariationInfo& info = variationOrThrow("glsl_apollonian");
  EXPECT_TRUE(info.paintsRgb);
  const struct {
    std::vector<double> params;
    std::uint32_t seed;
    std::uint32_t painted;
  } cases[] = {{{1000000.0, 10000.0, 0.0, 0.0}, kHighSeed, paintedRgb(255, 78, 198)},
               {{1000.0, 10000.0, 7.5, 0.0}, kLowSeed, paintedRgb(255, 230, 6)}};
  for (const auto& c : cases) {
    constexpr std::size_t kLanes = 37;
    std::vector<double> xs(kLanes, 0.3), ys(kLanes, -0.7), zs(kLanes, 0.5), ox(kLanes), oy(kLanes), oz(kLanes),
        colour(kLanes, 0.375);
    std::vector<std::uint32_t> random(kLanes, c.seed), rgb(kLanes, 0u);
    VariationInput in;
    in.x = in.tx = xs.data();
    in.y = in.ty = ys.data();
    in.z = in.tz = zs.data();
    in.random = random.data();
    in.count = kLanes;
    in.weight = 0.8;
    in.params = c.params.data();
    in.affine = kAffine;
    in.colour = colour.data();
    in.rgb = rgb.data();
    info.apply(in, ox.data(), oy.data(), oz.data());
    for (std::size_t lane = 0; lane < kLanes; ++lane) {
      EXPECT_EQ(rgb[lane], c.painted) << "lane " << lane;
      EXPECT_EQ(colour[lane], 0.375);
    }
  }
}

// JWildfire writes glsl_apollonian's "Density Pixels" with its space; the import reads it, and both Gradients (0 an
// RGB colour, 1 the index) are whole.
TEST(FlameVariationJwildfireGlsl, ImportsJwildfiresParameterNames) {
  const ImportedFlame rgb =
      importXform(R"(glsl_apollonian="0.7" glsl_apollonian_Density Pixels="2500" glsl_apollonian_seed="42" )"
                  R"(glsl_apollonian_time="3.5" glsl_apollonian_Gradient="0")");
  EXPECT_TRUE(rgb.leftOut.empty()) << rgb.leftOut.front();
  const auto& apollonian = rgb.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(apollonian.name, "glsl_apollonian");
  EXPECT_EQ(apollonian.params, (std::vector<double>{2500.0, 42.0, 3.5, 0.0}));
  const ImportedFlame index = importXform(R"(glsl_apollonian="0.7" glsl_apollonian_Gradient="1")");
  EXPECT_TRUE(index.leftOut.empty()) << index.leftOut.front();

  const ImportedFlame painterly = importXform(
      R"(dc_crackle_wf="0.02" dc_crackle_wf_cellsize="0.7" dc_crackle_wf_power="0.3" dc_crackle_wf_distort="0.1" )"
      R"(dc_crackle_wf_scale="1.1" dc_crackle_wf_z="0.2" dc_crackle_wf_color_scale="0.6" dc_crackle_wf_color_offset="0.1" )"
      R"(fract_mandelbrot_wf="0.005" fract_mandelbrot_wf_max_iter="120" fract_mandelbrot_wf_power="3" )"
      R"(fract_mandelbrot_wf_clip_iter_max="-4" fract_mandelbrot_wf_z_logscale="1" fract_mandelbrot_wf_color_only="1" )"
      R"(dc_perlin="1.0" dc_perlin_scale="1.5" dc_perlin_octaves="4" dc_perlin_color_seed="0.1")");
  // pyr3's dc_perlin (the only writer of color_seed) is read as Fractorium's, and said to differ.
  EXPECT_EQ(painterly.leftOut, (std::vector<std::string>{"pyr3's dc_perlin"}));
  const auto& terms = painterly.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 3u);
  EXPECT_EQ(terms.at(0).name, "dc_crackle_wf");
  EXPECT_EQ(terms.at(0).params, (std::vector<double>{0.7, 0.3, 0.1, 1.1, 0.2, 0.6, 0.1}));
  EXPECT_EQ(terms.at(1).name, "fract_mandelbrot_wf");
  EXPECT_EQ(terms.at(1).params, FractParams()
                                    .set("max_iter", 120.0)
                                    .set("power", 3.0)
                                    .set("clip_iter_max", -4.0)
                                    .set("z_logscale", 1.0)
                                    .set("color_only", 1.0)
                                    .values);
  EXPECT_EQ(terms.at(2).name, "dc_perlin");
  EXPECT_EQ(terms.at(2).params.back(), 0.1);
}

}  // namespace
