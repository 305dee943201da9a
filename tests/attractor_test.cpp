#include <gtest/gtest.h>

#include <cmath>

#include "core/attractor.h"
#include "core/error.h"

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
