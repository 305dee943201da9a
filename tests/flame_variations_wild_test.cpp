// The variations of core/flame/variations_jwildfire_wild.cpp (JWildfire's mandelbrot, invsquircular, sph3D,
// colorscale_wf, bubble_wf, bwraps2, invpolar, threeply, spligon, lazysensen, disc3 and cpow3_wf), each at points
// whose expected values were worked out from JWildfire's Java classes by a separate Python script in double
// precision, independently of the code under test. The point is (0.3, −0.7, 0.5) with weight 0.8, as in
// flame_variations_more_test.cpp; random variations are replayed from the lane's seed: xorshift32 gives Ψ = 0.879466,
// 0.545326, 0.394069, 0.000355, … from 0x2545F491 and Ψ = 0.316594, 0.875707, 0.483300 from 0x9E3779B9. mandelbrot
// starts from an empty memory (a single evaluation keeps none); colorscale_wf reads the harness's colour index, 0.375.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;

const std::vector<double> kMandelbrotSkin = {50.0, -2.0, 1.0, -1.0, 1.0, 0.0, 0.3, 0.5, -0.25, -1.0, 1234.0, 0.6};

const std::vector<PointCase>& pointCases() {
  // Notes on the rows: mandelbrot's defaults find no start of the thin skin in ten tries from an empty memory, so
  // the point goes far ((u, u), u = 50000 − 100000 Ψ); with skin 0.3 the high seed keeps its eighth start, the low
  // seed its seventh; with invert the high seed's second start stays in the set, the low seed's ten do not.
  // invsquircular's weight enters its formula. sph3D scales z by its x parameter. colorscale_wf adds dz = 0.375 ·
  // scale_z · 0.8 + offset_z (times Ψ₁ with sides). bubble_wf's z is negative where Ψ₁ < ½ (the low seed). bwraps2's
  // rows: inside a bubble, twisted, outside one (the point, weighted), and a gain beyond 2 (the bubble recurves).
  // threeply draws orbit point k + 1 = 1 + ⌊2²⁰ Ψ₁⌋ (k = 922187 for the high seed, 331972 for the low). spligon's sides
  // 0.3 rounds to 0 and is taken as 1. lazysensen: the defaults keep the point (⌊0.3⌋ = 0 even, ⌊−0.7⌋ = −1 odd and
  // negative); ⌊0.5 · 2.5⌋ = 1 (odd) negates z; at (1.2, −2.6, 0.7) with scales (−2, 0.5, −1) only y's ⌊−1.3⌋ = −2
  // (even and negative) negates. cpow3_wf's defaults come out alike for both seeds (Ψ₁ < 1 truncates to n = 0, and
  // neither Ψ₂ jumps).
  static const std::vector<PointCase> cases = {
      {"mandelbrot", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {32925.87757110596, 32925.87757110596, 0.0}},
      {"mandelbrot", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-1192.4314498901367, -1192.4314498901367, 0.0}},
      {"mandelbrot",
       kMandelbrotSkin,
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.7633986013036175, 0.6115407744131381, 0.14238542318344116}},
      {"mandelbrot",
       kMandelbrotSkin,
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {-0.7312867377082588, 0.25032806109401273, 0.034667444229125974}},
      {"mandelbrot",
       {30.0, -2.0, 1.0, -1.0, 1.0, 1.0, 0.012, 0.0, 0.0, -1.0, 1234.0, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.29121875762939453, -0.16948976516723635, 0.00014204978942871095}},
      {"mandelbrot",
       {30.0, -2.0, 1.0, -1.0, 1.0, 1.0, 0.012, 0.0, 0.0, -1.0, 1234.0, 0.4},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {1973.0472564697266, 1973.0472564697266, 0.0023660659790039062}},
      {"invsquircular", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {1.065087891748364, -0.45646623932072744, 0.4}},
      {"invsquircular", {}, {0.2, 0.45, 0.5}, 1.0, kHighSeed, {0.45799282940201885, 0.20355236862311948, 0.5}},
      {"sph3D", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.35229357798165145, -0.8220183486238534, 0.5871559633027524}},
      {"sph3D",
       {1.3, -0.4, 2.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.3675344563552833, -0.8575803981623278, 0.6125574272588056}},
      {"colorscale_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.0, 0.0, 0.15000000000000002}},
      {"colorscale_wf",
       {0.5, -0.3, 1.2, 0.25, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.12, 0.16799999999999998, 0.5364745128154754}},
      {"colorscale_wf",
       {0.5, -0.3, 1.2, 0.25, 0.0, 1.0},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.12, 0.16799999999999998, 0.1931220519542694}},
      {"bubble_wf",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.20960698689956334, -0.48908296943231444, 0.5973799126637556}},
      {"bubble_wf",
       {},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {0.20960698689956334, -0.48908296943231444, -0.5973799126637556}},
      {"bwraps2", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.15757572635446104, -0.6424242736455389, 0.4}},
      {"bwraps2",
       {0.9, 0.4, 1.6, 0.8, -0.5},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.2515960800819889, -0.595885171233285, 0.4}},
      {"bwraps2", {1.0, 0.5, 2.0, 0.3, 0.2}, {0.05, -0.95, 0.5}, 0.8, kHighSeed, {0.04000000000000001, -0.76, 0.4}},
      {"bwraps2",
       {1.5, 0.2, 3.0, 1.1, -0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.0993882469850481, -0.8299263852775554, 0.4}},
      {"invpolar", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.19416407864998741, 0.1410684605501936, 0.4}},
      {"threeply", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.012565573692044384, -1.0389033403958021, 0.4}},
      {"threeply", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.9692000738996625, -0.4798747493278488, 0.4}},
      {"threeply", {1.3, 0.4, -2.2}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.2641844360632727, 0.2661827448288339, 0.4}},
      {"threeply", {1.3, 0.4, -2.2}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {-0.11502071412662979, 0.10132806207074074, 0.4}},
      {"spligon", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {-0.4528203230275509, -0.9600000000000002, 0.4}},
      {"spligon", {5.5, -0.7, 2.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.7943000074533222, -0.4803036905669603, 0.4}},
      {"spligon", {0.3, 0.6, 1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24000000000000013, -1.0399999999999998, 0.4}},
      {"lazysensen", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, 0.4}},
      {"lazysensen", {1.517, 3.0, 2.5}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.24, -0.5599999999999999, -0.4}},
      {"lazysensen", {-2.0, 0.5, -1.0}, {1.2, -2.6, 0.7}, 0.8, kHighSeed, {0.96, 2.08, 0.5599999999999999}},
      {"disc3", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.4745343649529728, -0.5103724043613876, 0.4}},
      {"disc3",
       {0.7, 1.2, 0.9, 1.1, 0.8, 1.3, 0.6, 1.4},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.5197357170081918, -0.562545867545305, 0.4}},
      {"cpow3_wf", {}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, {0.6990335228125295, 0.2225940971175898, 0.4}},
      {"cpow3_wf", {}, {0.3, -0.7, 0.5}, 0.8, kLowSeed, {0.6990335228125295, 0.2225940971175898, 0.4}},
      {"cpow3_wf",
       {1.3, 0.4, 3.0, 2.5, 0.0, 0.5, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {0.31642241879969246, -0.04695148338765332, 0.4}},
      {"cpow3_wf",
       {1.3, 0.4, 3.0, 2.5, 1.0, 0.5, 0.7},
       {0.3, -0.7, 0.5},
       0.8,
       kLowSeed,
       {9.430142650573266, 5.249780423482623, 0.4}},
  };
  return cases;
}

class WildVariationAtPoint : public testing::TestWithParam<PointCase> {};

TEST_P(WildVariationAtPoint, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}

INSTANTIATE_TEST_SUITE_P(JwildfireWild, WildVariationAtPoint, testing::ValuesIn(pointCases()), caseLabel);

const PointCaseTableRegistration registered(&pointCases);

// One lane run `calls` times with memory kept from call to call (as the chaos game keeps it), weight 0.8, from
// the point (0.3, −0.7, 0.5): each call's result.
struct Call {
  double x, y, z;
};
std::vector<Call> runWithMemory(const std::string& name, const std::vector<double>& params, std::uint32_t seed,
                                int calls, std::vector<double>& memory) {
  const VariationInfo& info = variationOrThrow(name);
  memory.assign(info.laneState, 0.0);
  double x = 0.3, y = -0.7, z = 0.5, colour = 0.375;
  std::uint32_t random = seed;
  std::vector<Call> results;
  for (int k = 0; k < calls; ++k) {
    double ox = 0.0, oy = 0.0, oz = 0.0;
    VariationInput in;
    in.x = in.tx = &x;
    in.y = in.ty = &y;
    in.z = in.tz = &z;
    in.random = &random;
    in.count = 1;
    in.weight = 0.8;
    in.params = params.data();
    in.affine = kAffine;
    in.colour = &colour;
    in.state = memory.data();
    info.apply(in, &ox, &oy, &oz);
    results.push_back({ox, oy, oz});
  }
  return results;
}

// mandelbrot's walk: a start it keeps is the next call's seed, the next start drawn within (skin + 0.001)/2 of it
// (the Python script's three calls, one stream of draws).
TEST(FlameVariationWild, MandelbrotWalksAlongTheSkinFromItsLastStart) {
  std::vector<double> memory;
  const std::vector<Call> calls = runWithMemory("mandelbrot", kMandelbrotSkin, kHighSeed, 3, memory);
  const std::vector<Call> expected = {{-0.7633986013036175, 0.6115407744131381, 0.14238542318344116},
                                      {-0.06173973263136563, 0.34469610206122336, 0.14238542318344116},
                                      {0.8087839296616409, 0.5385607432168159, 0.14238542318344116}};
  for (std::size_t k = 0; k < calls.size(); ++k) {
    EXPECT_NEAR(calls[k].x, expected[k].x, 1e-12) << "call " << k;
    EXPECT_NEAR(calls[k].y, expected[k].y, 1e-12) << "call " << k;
    EXPECT_NEAR(calls[k].z, expected[k].z, 1e-12) << "call " << k;
  }
  ASSERT_EQ(memory.size(), 3u);
  EXPECT_NEAR(memory[0], -0.16102412670850755, 1e-12);
  EXPECT_NEAR(memory[1], 1.1135321633815765, 1e-12);
}

// With invert the kept starts are in the set (their orbits stay within 2 for iter steps), without it outside.
TEST(FlameVariationWild, MandelbrotKeepsStartsInsideTheSetWithInvertAndOnTheSkinWithout) {
  const VariationInfo& info = variationOrThrow("mandelbrot");
  const auto escapes = [](double cx, double cy, int iter) {
    double x = cx, y = cy;
    for (int k = 0; k < iter; ++k) {
      if (x * x + y * y >= 4.0) return true;
      const double next = x * x - y * y + cx;
      y = 2.0 * x * y + cy;
      x = next;
    }
    return x * x + y * y >= 4.0;
  };
  for (const double invert : {0.0, 1.0}) {
    const std::vector<double> params = {60.0, -2.0, 1.0, -1.2, 1.2, invert, 0.2, 0.0, 0.0, -1.0, 1.0, 0.0};
    int kept = 0;
    for (std::uint32_t seed = 1; seed <= 200; ++seed) {
      const Outputs out = run(info, params, {0.0, 0.0, 0.0}, 1.0, seed * 2654435761u, 1);
      const double cx = out.x[0] - kStartX, cy = out.y[0] - kStartY;
      if (std::abs(cx) > 10.0) continue;  // no start in ten tries: sent far away
      ++kept;
      EXPECT_EQ(escapes(cx, cy, 60), invert == 0.0) << "start (" << cx << ", " << cy << ")";
    }
    EXPECT_GT(kept, 100) << "invert " << invert;
  }
}

// With max_points > 0 the fresh starts are max_points fixed ones (skin 1 draws a fresh start every try, and cx =
// cy = 0 gives the start itself): at most 100 of them, whatever the lane's seed.
TEST(FlameVariationWild, MandelbrotMaxPointsDrawsFromAFixedSetOfStarts) {
  const VariationInfo& info = variationOrThrow("mandelbrot");
  const auto starts = [&](double seed, double maxPoints) {
    std::set<std::pair<double, double>> seen;
    const std::vector<double> params = {40.0, -2.0, 1.0, -1.2, 1.2, 0.0, 1.0, 0.0, 0.0, maxPoints, seed, 0.0};
    for (std::uint32_t lane = 1; lane <= 2000; ++lane) {
      const Outputs out = run(info, params, {0.0, 0.0, 0.0}, 1.0, lane * 2654435761u, 1);
      if (std::abs(out.x[0]) < 10.0) seen.insert({out.x[0], out.y[0]});
    }
    return seen;
  };
  const auto fixed = starts(1234.0, 7.0);  // JWildfire takes fewer than 100 as 100
  EXPECT_LE(fixed.size(), 100u);
  EXPECT_GT(fixed.size(), 20u);
  EXPECT_EQ(starts(1234.0, 100.0), fixed);
  EXPECT_NE(starts(99.0, 100.0), fixed);         // another seed, other starts
  EXPECT_GT(starts(1234.0, -1.0).size(), 500u);  // none kept: every start drawn afresh
}

// threeply's table is the orbit from (0, 0): (0, a), (a, a), then the map proper (the Python script's points); an
// orbit that overflows starts over from (0, 0), so later points are finite again.
TEST(FlameVariationWild, ThreeplyDrawsFromItsOrbit) {
  const VariationInfo& info = variationOrThrow("threeply");
  ASSERT_NE(info.table, nullptr);
  EXPECT_EQ(info.replaces, VariationInfo::Replaces::XY);
  const std::vector<double> params = {-55.0, -1.0, -42.0};
  const std::vector<double> table = info.table(params.data(), nullptr);
  ASSERT_EQ(table.size(), std::size_t{2} << 20);
  const std::vector<double> first = {
      0.0, -55.0, -55.0, -55.0, -45.076172984942524, 0.0, 16.63415101846426, -9.923827015057476};
  for (std::size_t k = 0; k < first.size(); ++k) EXPECT_NEAR(table[k], first[k], 1e-12) << k;
  // a = 1.7e308 overflows y′ = a − x at its fifth point (one in five points after that, the Python script found).
  const std::vector<double> wild = {1.7e308, 0.0, 0.0};
  const std::vector<double> restarted = info.table(wild.data(), nullptr);
  EXPECT_TRUE(std::isinf(restarted[9]));
  EXPECT_EQ(restarted[10], 0.0);  // from (0, 0) again: (0, a)
  EXPECT_EQ(restarted[11], 1.7e308);
  std::size_t finite = 0;
  for (const double v : restarted) finite += std::isfinite(v) ? 1 : 0;
  EXPECT_GT(finite, restarted.size() * 3 / 4);
}

// colorscale_wf's reset_z makes z of the sum dz (0.375 · 1.2 · 0.8 + 0.25 = 0.61) where the others add to it.
TEST(FlameVariationWild, ColorscaleResetZReplacesTheSumsZ) {
  const VariationInfo& info = variationOrThrow("colorscale_wf");
  EXPECT_TRUE(info.directColour);
  EXPECT_TRUE(info.readsSum);
  const Outputs reset = run(info, {0.5, -0.3, 1.2, 0.25, 1.0, 1.0}, {0.3, -0.7, 0.5}, 0.8, kHighSeed, 5);
  EXPECT_NEAR(reset.x[0] - kStartX, 0.12, 1e-12);
  EXPECT_NEAR(reset.z[0], 0.61, 1e-12);
  EXPECT_EQ(reset.colour[0], kStartColour);  // read, not written
}

// Odd points: what JWildfire keeps finite stays finite here; invsquircular drops what it cannot map (NaN in all
// three, the chaos game's escape, where JWildfire resets the point); a huge iter is held at 10000 steps.
TEST(FlameVariationWild, OddPointsStayFiniteOrDropWhole) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const char* name : {"sph3D", "bubble_wf", "bwraps2", "invpolar", "spligon", "lazysensen", "disc3",
                           "colorscale_wf", "mandelbrot", "threeply"}) {
    const VariationInfo& info = variationOrThrow(name);
    const Outputs origin = run(info, info.defaultParams(), {0.0, 0.0, 0.0}, 0.8, kHighSeed, 3);
    EXPECT_TRUE(std::isfinite(origin.x[0]) && std::isfinite(origin.y[0]) && std::isfinite(origin.z[0])) << name;
  }
  const VariationInfo& sph = variationOrThrow("sph3D");
  const Outputs zero = run(sph, sph.defaultParams(), {0.0, 0.0, 0.0}, 0.8, kHighSeed, 1);
  EXPECT_EQ(zero.x[0] - kStartX, 0.0);
  const VariationInfo& inv = variationOrThrow("invsquircular");
  for (const double v : {0.0, inf, -inf, nan, 1e300}) {
    const Outputs out = run(inv, {}, {v, 0.3, 0.5}, 0.8, kHighSeed, 1);
    EXPECT_TRUE(std::isnan(out.x[0]) && std::isnan(out.y[0]) && std::isnan(out.z[0])) << v;
  }
  // Beyond Java's int range ⌊v s⌋ is held at its ends (odd above, even below), so both far halves are negated.
  const VariationInfo& lazy = variationOrThrow("lazysensen");
  const Outputs far = run(lazy, {1.0, 1.0, 1.0}, {1e300, -1e300, nan}, 1.0, kHighSeed, 1);
  EXPECT_EQ(far.x[0] - kStartX, -1e300);
  EXPECT_EQ(far.y[0] - kStartY, 1e300);
  EXPECT_TRUE(std::isnan(far.z[0]));
  const VariationInfo& mandel = variationOrThrow("mandelbrot");
  const Outputs capped = run(mandel, {1e300, -2.0, 1.0, -1.2, 1.2, 1.0, 0.012, 0.0, 0.0, -1.0, 1.0, 0.0},
                             {0.0, 0.0, 0.0}, 1.0, kHighSeed, 1);
  EXPECT_TRUE(std::isfinite(capped.x[0]));
}

ImportedFlame importXform(const std::string& xform) {
  const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                           "/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
  return readFlameXml(text, "t.flame").flame;
}

// Files write them as JWildfire does: mandelbrot with all its parameters, bwraps2 as pre_bwraps2.
TEST(FlameVariationWild, ImportsJwildfiresNames) {
  const ImportedFlame flame = importXform(
      R"(mandelbrot="0.019" mandelbrot_iter="100" mandelbrot_xmin="-1.6" mandelbrot_xmax="1.6" mandelbrot_ymin="-1.2" )"
      R"(mandelbrot_ymax="1.2" mandelbrot_invert="0" mandelbrot_skin="0.012" mandelbrot_cx="0.0" mandelbrot_cy="0.0" )"
      R"(mandelbrot_max_points="-1" mandelbrot_seed="77" mandelbrot_rnd_z_range="0.25" pre_bwraps2="0.004" )"
      R"(pre_bwraps2_fx_priority="0" pre_bwraps2_cellsize="1.0" pre_bwraps2_space="0.0" pre_bwraps2_gain="2.0" )"
      R"(pre_bwraps2_inner_twist="0.0" pre_bwraps2_outer_twist="0.5" coefs="1 0 0 1 0 0")");
  ASSERT_TRUE(flame.leftOut.empty()) << flame.leftOut.front();
  const auto& terms = flame.genome.xforms.at(0).variations;
  ASSERT_EQ(terms.size(), 2u);
  const auto mandelbrot =
      std::find_if(terms.begin(), terms.end(), [](const VariationTerm& t) { return t.name == "mandelbrot"; });
  const auto bwraps =
      std::find_if(terms.begin(), terms.end(), [](const VariationTerm& t) { return t.name == "pre_bwraps2"; });
  ASSERT_NE(mandelbrot, terms.end());
  ASSERT_NE(bwraps, terms.end());
  EXPECT_EQ(mandelbrot->params,
            (std::vector<double>{100.0, -1.6, 1.6, -1.2, 1.2, 0.0, 0.012, 0.0, 0.0, -1.0, 77.0, 0.25}));
  EXPECT_EQ(variationStage(bwraps->name), VariationStage::Pre);
  EXPECT_EQ(bwraps->params, (std::vector<double>{1.0, 0.0, 2.0, 0.0, 0.5}));
}

}  // namespace
