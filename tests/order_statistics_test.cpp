// core::percentiles must give exactly what std::nth_element gives, whatever the distribution: the
// attractor's fit (and so every image) depends on these values bit for bit.
#include "core/order_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using voxflame::core::percentiles;

namespace {

double byNthElement(std::vector<double> values, double fraction) {
  const auto index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
  return values[index];
}

constexpr std::array kFractions{0.0, 0.01, 0.05, 0.5, 0.95, 0.99, 1.0};

void expectExact(const std::vector<double>& values, const char* what) {
  const std::array<double, kFractions.size()> got = percentiles(values, kFractions);
  for (std::size_t f = 0; f < kFractions.size(); ++f)
    EXPECT_EQ(got[f], byNthElement(values, kFractions[f])) << what << ", fraction " << kFractions[f];
}

}  // namespace

TEST(Percentiles, MatchNthElementOnManyDistributions) {
  std::mt19937_64 random(7);
  for (const std::size_t n : {1u, 2u, 7u, 1000u, 8191u, 8192u, 100'000u, 128'000u}) {
    std::vector<double> uniform(n), heavy(n), ties(n), sorted(n), reversed(n), signs(n);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::cauchy_distribution<double> cauchy(0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      uniform[i] = unit(random);
      heavy[i] = cauchy(random);
      ties[i] = std::floor(4.0 * unit(random));  // a handful of distinct values, each many times
      sorted[i] = static_cast<double>(i);
      reversed[i] = -static_cast<double>(i);
      signs[i] = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? -0.0 : 1e-300 * unit(random));
    }
    expectExact(uniform, "uniform");
    expectExact(heavy, "Cauchy");
    expectExact(ties, "ties");
    expectExact(sorted, "sorted");
    expectExact(reversed, "reversed");
    expectExact(signs, "zeros of both signs and denormals");
  }
}

// A subsample that brackets the wrong ranks (a periodic input whose stride hits one value) still
// answers exactly, through the fallback.
TEST(Percentiles, AStrideAliasedSubsampleFallsBackToTheExactAnswer) {
  const std::size_t n = 102'400;  // the subsample takes every 100th value
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = i % 100 == 0 ? 1e9 : static_cast<double>(i % 97);
  expectExact(values, "aliased");
}
