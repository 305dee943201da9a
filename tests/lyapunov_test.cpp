#include <gtest/gtest.h>

#include <atomic>

#include <cmath>
#include <limits>

#include "core/attractor.h"
#include "core/error.h"
#include "core/lyapunov.h"

using namespace voxflame::core;

namespace {

OrbitSpec specFor(const char* id, std::vector<double> params, Integrator integrator, double step, glm::dvec3 start) {
  return {&attractorOrThrow(id), std::move(params), integrator, step, start};
}

}  // namespace

// Published: 0.9056, 0, -14.5723 (Sprott, "Chaos and Time-Series Analysis", 2003, table of
// exponents); the sum must equal the trace of the Jacobian, -(sigma + 1 + beta).
TEST(Lyapunov, ClassicLorenzMatchesPublishedValues) {
  const NamedParams* classic = attractorOrThrow("lorenz").alternative("classic");
  ASSERT_NE(classic, nullptr);
  const OrbitAnalysis a =
      analyseOrbit(specFor("lorenz", classic->values, Integrator::RK4, 0.01, classic->start), {2'000, 200'000, 1e6});
  ASSERT_TRUE(a.bounded);
  EXPECT_NEAR(a.lyapunov[0], 0.9056, 0.04);
  EXPECT_NEAR(a.lyapunov[1], 0.0, 0.01);
  EXPECT_NEAR(a.lyapunov[2], -14.5723, 0.05);
  EXPECT_NEAR(a.lyapunov[0] + a.lyapunov[1] + a.lyapunov[2], -(10.0 + 1.0 + 8.0 / 3.0), 1e-3);
  EXPECT_NEAR(a.kaplanYorkeDimension, 2.062, 0.01);
  EXPECT_EQ(a.verdict, OrbitVerdict::Chaotic);
}

// Published: 0.0714, 0, -5.3943 (Sprott 2003).
TEST(Lyapunov, RosslerMatchesPublishedValues) {
  const OrbitAnalysis a =
      analyseOrbit(specFor("rossler", {0.2, 0.2, 5.7}, Integrator::RK4, 0.02, {1.0, 1.0, 0.0}), {5'000, 300'000, 1e6});
  ASSERT_TRUE(a.bounded);
  EXPECT_NEAR(a.lyapunov[0], 0.0714, 0.006);
  EXPECT_NEAR(a.lyapunov[1], 0.0, 0.005);
  EXPECT_NEAR(a.lyapunov[2], -5.3943, 0.02);
}

// Hénon (a = 1.4, b = 0.3): 0.41922 and -1.62319 per iteration (Sprott 2003); the z memory adds
// log|c| exactly, and the sum is log|det J| = log(b c) on every step.
TEST(Lyapunov, HenonMapMatchesPublishedValuesPerIteration) {
  const OrbitAnalysis a = analyseOrbit(specFor("henon_3d", {1.4, 0.3, 0.5}, Integrator::Euler, 1.0, {0.1, 0.1, 0.0}),
                                       {1'000, 200'000, 1e6});
  ASSERT_TRUE(a.bounded);
  EXPECT_NEAR(a.lyapunov[0], 0.41922, 0.005);
  EXPECT_NEAR(a.lyapunov[1], std::log(0.5), 1e-4);
  EXPECT_NEAR(a.lyapunov[2], -1.62319, 0.005);
  EXPECT_NEAR(a.lyapunov[0] + a.lyapunov[1] + a.lyapunov[2], std::log(0.3 * 0.5), 1e-9);
}

TEST(Lyapunov, PeriodicAndEscapingOrbitsAreRecognised) {
  // Rössler with c = 2.5 settles on a period-1 limit cycle.
  const OrbitAnalysis cycle =
      analyseOrbit(specFor("rossler", {0.2, 0.2, 2.5}, Integrator::RK4, 0.02, {1.0, 1.0, 0.0}), {5'000, 50'000, 1e6});
  EXPECT_TRUE(cycle.bounded);
  EXPECT_EQ(cycle.verdict, OrbitVerdict::Periodic);
  EXPECT_NEAR(cycle.lyapunov[0], 0.0, 0.005);
  const auto& b = attractorOrThrow("polynomial_b");
  const OrbitAnalysis escape =
      analyseOrbit({&b, b.alternative("seed")->values, Integrator::Euler, 1.0, {0.1, 0.1, 0.1}});
  EXPECT_FALSE(escape.bounded);
  EXPECT_EQ(escape.verdict, OrbitVerdict::Escapes);
}

TEST(Lyapunov, BadValuesAreRefusedWithAMessage) {
  const auto& info = attractorOrThrow("lorenz");
  OrbitSpec spec = defaultOrbitSpec(info);
  spec.params[1] = std::numeric_limits<double>::quiet_NaN();
  try {
    analyseOrbit(spec);
    FAIL() << "NaN accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'b'"), std::string::npos) << e.what();
  }
  spec = defaultOrbitSpec(info);
  spec.step = std::numeric_limits<double>::infinity();
  EXPECT_THROW(analyseOrbit(spec), Error);
  spec.step = 50.0;
  EXPECT_THROW(analyseOrbit(spec), Error);
  spec.step = -0.01;
  EXPECT_THROW(analyseOrbit(spec), Error);
  spec = defaultOrbitSpec(info);
  spec.params.pop_back();
  EXPECT_THROW(analyseOrbit(spec), Error);
  spec = defaultOrbitSpec(info);
  EXPECT_THROW(analyseOrbit(spec, {0, 0, 1e6}), Error);
}

TEST(ChaosSearch, IsDeterministicPerSeedAndFindsChaoticVolumeFillingSets) {
  const auto& info = attractorOrThrow("polynomial_b");
  OrbitSpec base{&info, info.alternative("seed")->values, Integrator::Euler, 1.0, {0.1, 0.1, 0.1}};
  SearchOptions options;
  options.seed = 3;
  options.count = 3;
  options.strength = 0.3;
  const auto first = searchChaos(base, options);
  const auto again = searchChaos(base, options);
  ASSERT_EQ(first.size(), 3u);
  ASSERT_EQ(again.size(), first.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].params, again[i].params);
    EXPECT_EQ(first[i].analysis.verdict, OrbitVerdict::Chaotic);
    EXPECT_GT(first[i].analysis.lyapunov[0], chaosThreshold(info));
    EXPECT_GE(first[i].analysis.smallestExtent(), options.minExtentRatio * first[i].analysis.largestExtent());
    // The result re-analysed from scratch is chaotic too (nothing depends on hidden state).
    OrbitSpec check = base;
    check.params = first[i].params;
    check.start = first[i].start;
    EXPECT_EQ(analyseOrbit(check, options.confirm).verdict, OrbitVerdict::Chaotic);
    // Nearby: each parameter moved by at most strength x its slider range.
    for (std::size_t k = 0; k < info.params.size(); ++k)
      EXPECT_LE(std::abs(first[i].params[k] - base.params[k]),
                options.strength * (info.params[k].sliderMax - info.params[k].sliderMin) + 1e-12);
  }
  options.seed = 4;
  const auto other = searchChaos(base, options);
  ASSERT_FALSE(other.empty());
  EXPECT_NE(other[0].params, first[0].params);
  options.strength = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(searchChaos(base, options), Error);
}

// A caller holds the search to its own check of each set that passed the analysis (the explorer:
// does its live view run it bounded?) and, when its orbits cannot start elsewhere, to the base's
// start, so the analysis it reports is of the orbit it runs.
TEST(ChaosSearch, KeepsOnlyWhatTheCallerAcceptsFromTheBasesStart) {
  const auto& info = attractorOrThrow("polynomial_b");
  const OrbitSpec base{&info, info.alternative("seed")->values, Integrator::Euler, 1.0, {0.1, 0.1, 0.1}};
  SearchOptions options;
  options.seed = 3;
  options.count = 2;
  options.strength = 0.3;
  options.jitterStart = false;
  int asked = 0;
  std::vector<std::vector<double>> refused;
  options.accept = [&](const std::vector<double>& params) {
    const bool accepted = ++asked % 2 == 0;  // every other one
    if (!accepted) refused.push_back(params);
    return accepted;
  };
  const auto found = searchChaos(base, options);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(asked, 4) << "asked only of sets that passed the analysis, until enough were kept";
  for (const SearchResult& result : found) {
    EXPECT_EQ(std::count(refused.begin(), refused.end(), result.params), 0) << "a refused set is never returned";
    EXPECT_EQ(result.start, base.start);
    OrbitSpec check = base;
    check.params = result.params;
    EXPECT_EQ(analyseOrbit(check, options.confirm).verdict, OrbitVerdict::Chaotic) << "from the base's own start";
  }
  options.accept = [](const std::vector<double>&) { return false; };
  options.maxCandidates = 60;
  EXPECT_TRUE(searchChaos(base, options).empty());
}

// Nothing chaotic near a periodic Thomas (b well above the onset of chaos at 0.208): the search
// widens its strength by itself, reporting its tries and the strength, before giving up.
TEST(ChaosSearch, WidensItsStrengthUntilItFindsChaos) {
  const auto& info = attractorOrThrow("thomas");
  OrbitSpec base = defaultOrbitSpec(info);
  base.params = {0.32};
  ASSERT_NE(analyseOrbit(base).verdict, OrbitVerdict::Chaotic);
  SearchOptions options;
  options.seed = 5;
  options.count = 1;
  options.strength = 0.05;
  options.maxCandidates = 40;
  std::atomic<int> tried{0};
  std::atomic<double> strength{0.0};
  options.tried = &tried;
  options.strengthNow = &strength;
  EXPECT_TRUE(searchChaos(base, options).empty()) << "a twentieth of the range holds no chaos";
  EXPECT_EQ(tried.load(), 40);
  tried = 0;
  options.widenTo = 0.8;
  const auto found = searchChaos(base, options);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_LT(found[0].params[0], 0.22);
  EXPECT_GT(tried.load(), 40) << "it went on past the first strength";
  EXPECT_GT(strength.load(), 0.1);
  EXPECT_LE(strength.load(), 0.8);
}
