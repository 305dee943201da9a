#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <glm/common.hpp>

#include "core/attractor.h"
#include "core/error.h"
#include "core/lyapunov.h"

using namespace voxflame::core;

TEST(Attractor, Lorenz84FollowsTheSeedEquations) {
  const AttractorInfo& info = attractorOrThrow("lorenz84");
  EXPECT_EQ(info.kind, AttractorKind::Flow);
  const std::vector<double> p = info.defaultParams();
  const double a = p[0], b = p[1], f = p[2], g = p[3], h = info.defaultStep;
  double x = 0.3, y = -0.2, z = 0.7;
  const double ex = x + h * (-a * x - y * y - z * z + a * f);
  const double ey = y + h * (-y + x * y - b * x * z + g);
  const double ez = z + h * (-z + b * x * y + x * z);
  info.advance(Integrator::Euler)(p.data(), h, &x, &y, &z, 1);
  EXPECT_DOUBLE_EQ(x, ex);
  EXPECT_DOUBLE_EQ(y, ey);
  EXPECT_DOUBLE_EQ(z, ez);
}

TEST(Attractor, Lorenz84StaysBoundedForAMillionSteps) {
  const AttractorInfo& info = attractorOrThrow("lorenz84");
  const std::vector<double> p = info.defaultParams();
  for (Integrator integrator : {Integrator::Euler, Integrator::RK4}) {
    double x = info.start.x, y = info.start.y, z = info.start.z;
    const AdvanceFn advance = info.advance(integrator);
    double maxAbs = 0.0;
    for (int i = 0; i < 1'000'000; ++i) {
      advance(p.data(), info.defaultStep, &x, &y, &z, 1);
      maxAbs = std::max({maxAbs, std::abs(x), std::abs(y), std::abs(z)});
    }
    EXPECT_TRUE(std::isfinite(maxAbs));
    EXPECT_LT(maxAbs, 100.0);
    EXPECT_GT(maxAbs, 0.5);  // not collapsed to the origin
  }
}

TEST(Attractor, UnknownIdListsTheKnownOnes) {
  EXPECT_EQ(findAttractor("no-such"), nullptr);
  try {
    attractorOrThrow("no-such");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lorenz84"), std::string::npos);
  }
}

// --- the catalogue ------------------------------------------------------------------------------

TEST(Catalogue, HasTheSeedsSixAndAtLeastTwentyFourMoreWithCitations) {
  const auto& catalogue = attractorCatalogue();
  for (const char* id : {"lorenz", "lorenz84", "pickover", "polynomial_a", "polynomial_b", "polynomial_c"})
    EXPECT_NE(findAttractor(id), nullptr) << id;
  EXPECT_NE(findAttractor("sprott_quadratic"), nullptr);
  EXPECT_GE(catalogue.size(), 6u + 24u + 1u);
  std::set<std::string> ids;
  for (const auto& info : catalogue) {
    EXPECT_TRUE(ids.insert(info.id).second) << "duplicate id " << info.id;
    EXPECT_FALSE(info.name.empty()) << info.id;
    EXPECT_FALSE(info.citation.empty()) << info.id;
    EXPECT_FALSE(info.equations.empty()) << info.id;
    ASSERT_NE(info.advanceEuler, nullptr) << info.id;
    ASSERT_NE(info.advanceRk4, nullptr) << info.id;
    ASSERT_NE(info.jacobianEuler, nullptr) << info.id;
    ASSERT_NE(info.jacobianRk4, nullptr) << info.id;
    for (const auto& p : info.params) {
      EXPECT_LE(p.sliderMin, p.defaultValue) << info.id << "." << p.name;
      EXPECT_GE(p.sliderMax, p.defaultValue) << info.id << "." << p.name;
    }
    if (info.kind == AttractorKind::Map) {
      EXPECT_EQ(info.advanceEuler, info.advanceRk4) << info.id;
    }
  }
}

TEST(Catalogue, SeedMapsFollowTheirEquations) {
  const double x = 0.3, y = -0.2, z = 0.7;
  const auto step = [&](const char* id) {
    const AttractorInfo& info = attractorOrThrow(id);
    EXPECT_EQ(info.kind, AttractorKind::Map) << id;
    std::array<double, 3> s{x, y, z};
    const auto p = info.defaultParams();
    info.advance(Integrator::Euler)(p.data(), 1.0, &s[0], &s[1], &s[2], 1);
    return std::pair(s, p);
  };
  {
    const auto [s, p] = step("pickover");
    EXPECT_DOUBLE_EQ(s[0], std::sin(p[0] * y) - z * std::cos(p[1] * x));
    EXPECT_DOUBLE_EQ(s[1], z * std::sin(p[2] * x) - std::cos(p[3] * y));
    EXPECT_DOUBLE_EQ(s[2], std::sin(x));
    EXPECT_DOUBLE_EQ(p[0], -0.759494);
  }
  {
    const auto [s, p] = step("polynomial_a");
    EXPECT_DOUBLE_EQ(s[0], p[0] + y - z * y);
    EXPECT_DOUBLE_EQ(s[1], p[1] + z - x * z);
    EXPECT_DOUBLE_EQ(s[2], p[2] + x - y * x);
    EXPECT_EQ(p, (std::vector<double>{1.586, 1.124, 0.281}));
  }
  {
    const auto [s, p] = step("polynomial_b");
    EXPECT_DOUBLE_EQ(s[0], p[0] + y - z * (p[1] + y));
    EXPECT_DOUBLE_EQ(s[1], p[2] + z - x * (p[3] + z));
    EXPECT_DOUBLE_EQ(s[2], p[4] + x - y * (p[5] + x));
  }
  {
    const auto [s, p] = step("polynomial_c");
    ASSERT_EQ(p.size(), 18u);
    EXPECT_DOUBLE_EQ(s[0], p[0] + x * (p[1] + p[2] * x + p[3] * y) + y * (p[4] + p[5] * y));
    EXPECT_DOUBLE_EQ(s[1], p[6] + y * (p[7] + p[8] * y + p[9] * z) + z * (p[10] + p[11] * z));
    EXPECT_DOUBLE_EQ(s[2], p[12] + z * (p[13] + p[14] * z + p[15] * x) + x * (p[16] + p[17] * x));
  }
}

TEST(Catalogue, SeedLorenzIsAnEulerStepWithTheSeedsDefaults) {
  const AttractorInfo& info = attractorOrThrow("lorenz");
  EXPECT_EQ(info.defaultParams(), (std::vector<double>{28.0, 46.92, 4.0}));
  EXPECT_EQ(info.defaultStep, 0.01);
  EXPECT_EQ(info.defaultIntegrator, Integrator::Euler);
  const auto p = info.defaultParams();
  double x = 0.3, y = -0.2, z = 0.7;
  const double h = 0.01;
  const double ex = x + p[0] * h * (y - x), ey = y + h * (p[1] * x - y - z * x), ez = z + h * (x * y - p[2] * z);
  info.advance(Integrator::Euler)(p.data(), h, &x, &y, &z, 1);
  EXPECT_DOUBLE_EQ(x, ex);
  EXPECT_DOUBLE_EQ(y, ey);
  EXPECT_DOUBLE_EQ(z, ez);
}

// The seed's polynomial_b defaults escape; that finding is kept honest by this test, and the
// seed's set stays available as the alternative "seed".
TEST(Catalogue, SeedPolynomialBSetEscapesFromEveryStartTried) {
  const AttractorInfo& info = attractorOrThrow("polynomial_b");
  const NamedParams* seed = info.alternative("seed");
  ASSERT_NE(seed, nullptr);
  EXPECT_EQ(seed->values, (std::vector<double>{-0.237, 0.453, 0.486, 0.616, 0.141, 0.483}));
  int escaped = 0, tried = 0;
  for (double sx = -1.0; sx <= 1.0; sx += 0.5)
    for (double sy = -1.0; sy <= 1.0; sy += 0.5)
      for (double sz = -1.0; sz <= 1.0; sz += 0.5) {
        ++tried;
        double x = sx, y = sy, z = sz;
        for (int i = 0; i < 10'000 && std::abs(x) + std::abs(y) + std::abs(z) < 1e6; ++i)
          info.advanceEuler(seed->values.data(), 1.0, &x, &y, &z, 1);
        if (!(std::abs(x) + std::abs(y) + std::abs(z) < 1e6)) ++escaped;
      }
  EXPECT_EQ(escaped, tried);
}

TEST(Catalogue, PolynomialAEscapesFromTheSeedStartButNotFromItsOwn) {
  const AttractorInfo& info = attractorOrThrow("polynomial_a");
  const auto p = info.defaultParams();
  const auto runs = [&](glm::dvec3 s) {
    double x = s.x, y = s.y, z = s.z;
    for (int i = 0; i < 100'000; ++i) {
      info.advanceEuler(p.data(), 1.0, &x, &y, &z, 1);
      if (!(std::abs(x) + std::abs(y) + std::abs(z) < 1e6)) return false;
    }
    return true;
  };
  EXPECT_FALSE(runs({0.1, 0.1, 0.1}));
  EXPECT_TRUE(runs(info.start));
}

TEST(Catalogue, SprottLetterCodeRoundTripsAndRefusesBadCodes) {
  const std::string code = "TXGJBUAELWVBHYVTGSPAVSHEPGMIGR";
  const auto params = sprottCodeToParams(code);
  ASSERT_EQ(params.size(), 30u);
  EXPECT_NEAR(params[0], 0.7, 1e-12);   // T
  EXPECT_NEAR(params[6], -1.2, 1e-12);  // A
  EXPECT_NEAR(params[26], 0.0, 1e-12);  // M
  EXPECT_EQ(paramsToSprottCode(params), code);
  EXPECT_EQ(sprottCodeToParams("I" + code), params);
  EXPECT_EQ(attractorOrThrow("sprott_quadratic").defaultParams(), params);
  EXPECT_THROW(sprottCodeToParams("ABC"), Error);
  EXPECT_THROW(sprottCodeToParams(std::string(30, 'Z')), Error);
}

// The dual-number Jacobian of every step agrees with central finite differences.
TEST(Catalogue, StepJacobiansMatchFiniteDifferences) {
  for (const auto& info : attractorCatalogue()) {
    for (Integrator integrator : {Integrator::Euler, Integrator::RK4}) {
      const auto p = info.defaultParams();
      const double h = info.defaultStep;
      const glm::dvec3 point = info.start + glm::dvec3(0.13, -0.07, 0.05);
      double state[3] = {point.x, point.y, point.z}, jacobian[9];
      info.stepJacobian(integrator)(p.data(), h, state, jacobian);
      for (int column = 0; column < 3; ++column) {
        const double eps = 1e-6;
        double plus[3] = {point.x, point.y, point.z}, minus[3] = {point.x, point.y, point.z};
        plus[column] += eps;
        minus[column] -= eps;
        info.advance(integrator)(p.data(), h, &plus[0], &plus[1], &plus[2], 1);
        info.advance(integrator)(p.data(), h, &minus[0], &minus[1], &minus[2], 1);
        for (int row = 0; row < 3; ++row) {
          const double numeric = (plus[row] - minus[row]) / (2.0 * eps);
          EXPECT_NEAR(jacobian[3 * row + column], numeric, 1e-5 * (1.0 + std::abs(numeric)))
              << info.id << " " << toString(integrator) << " d" << row << "/d" << column;
        }
      }
      double x = point.x, y = point.y, z = point.z;
      info.advance(integrator)(p.data(), h, &x, &y, &z, 1);
      EXPECT_DOUBLE_EQ(state[0], x) << info.id;
      EXPECT_DOUBLE_EQ(state[2], z) << info.id;
    }
  }
}

// Every entry, with its defaults, integrator, step and start, stays bounded for a million steps
// and is chaotic: one test per entry so CTest spreads them over the cores.
class EveryAttractor : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAttractor, DefaultsAreBoundedForAMillionStepsAndChaotic) {
  const AttractorInfo& info = attractorOrThrow(GetParam());
  const auto p = info.defaultParams();
  const AdvanceFn advance = info.advance(info.defaultIntegrator);
  double x = info.start.x, y = info.start.y, z = info.start.z;
  double maxAbs = 0.0;
  glm::dvec3 low(1e300), high(-1e300);
  for (int i = 0; i < 1'000'000; ++i) {
    advance(p.data(), info.defaultStep, &x, &y, &z, 1);
    maxAbs = std::max({maxAbs, std::abs(x), std::abs(y), std::abs(z)});
    if (!(maxAbs < 1e6)) break;
    if (i >= 10'000) {
      low = glm::min(low, glm::dvec3(x, y, z));
      high = glm::max(high, glm::dvec3(x, y, z));
    }
  }
  ASSERT_LT(maxAbs, 1e6) << "escapes";
  const glm::dvec3 extent = high - low;
  EXPECT_GT(std::min({extent.x, extent.y, extent.z}), 1e-3 * std::max({extent.x, extent.y, extent.z}))
      << "collapsed onto a plane, line or point";

  const OrbitAnalysis analysis = analyseOrbit(defaultOrbitSpec(info), {5'000, 100'000, 1e6});
  ASSERT_TRUE(analysis.bounded);
  EXPECT_EQ(analysis.verdict, OrbitVerdict::Chaotic) << "largest exponent " << analysis.lyapunov[0];
  EXPECT_GT(analysis.lyapunov[0], chaosThreshold(info));
}

std::vector<std::string> catalogueIds() {
  std::vector<std::string> ids;
  for (const auto& info : attractorCatalogue()) ids.push_back(info.id);
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryAttractor, ::testing::ValuesIn(catalogueIds()),
                         [](const ::testing::TestParamInfo<std::string>& test) { return test.param; });
