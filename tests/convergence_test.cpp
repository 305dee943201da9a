// The convergence meter on counts whose noise is known: points dropped at random into voxels of
// known probabilities, so the true relative error of the densities can be computed and compared.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/refinement/convergence.h"

using namespace voxflame::core;

namespace {

// A lumpy density over `voxels` voxels, most of them empty, as a pattern in a grid is.
std::vector<double> lumpyProbabilities(std::size_t voxels) {
  std::vector<double> p(voxels, 0.0);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double total = 0.0;
  for (std::size_t v = 0; v < voxels; ++v) {
    if (v % 5 != 0) continue;  // four in five voxels stay empty
    p[v] = std::pow(uniform(random), 3.0) + 0.01;
    total += p[v];
  }
  for (double& value : p) value /= total;
  return p;
}

// ‖error‖ / ‖density‖ of counts of n points: what the meter estimates.
double trueNoise(const std::vector<double>& p, double n) {
  double variance = 0.0, signal = 0.0;
  for (double value : p) {
    variance += value * (1.0 - value) / n;
    signal += value * value;
  }
  return std::sqrt(variance / signal);
}

// Adds n points to the counts, each voxel's share drawn as a Poisson count (independent voxels).
void addPoints(std::vector<std::uint32_t>& hits, const std::vector<double>& p, double n, std::mt19937_64& random) {
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (p[v] <= 0.0) continue;
    std::poisson_distribution<std::uint32_t> count(p[v] * n);
    hits[v] += count(random);
  }
}

}  // namespace

TEST(Convergence, EstimatesTheTrueNoiseOfCountsAndFallsLikeOneOverRootN) {
  const std::vector<double> p = lumpyProbabilities(100'000);
  std::mt19937_64 random(11);
  DensitySample sample;
  sample.generation = 1;
  sample.hits.assign(p.size(), 0);
  ConvergenceMeter meter;
  double points = 0.0;
  std::vector<double> estimates, truths;
  for (double add : {2e5, 2e5, 4e5, 8e5, 1.6e6, 3.2e6, 6.4e6}) {
    addPoints(sample.hits, p, add, random);
    points += add;
    sample.points = static_cast<std::uint64_t>(points);
    const double noise = meter.update(sample);
    if (estimates.empty() && std::isnan(noise)) continue;  // the first sample is only a reference
    ASSERT_TRUE(std::isfinite(noise));
    estimates.push_back(noise);
    truths.push_back(trueNoise(p, points));
  }
  ASSERT_EQ(estimates.size(), 6u);
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    EXPECT_NEAR(estimates[i] / truths[i], 1.0, 0.1) << "at step " << i << ": " << estimates[i] << " vs " << truths[i];
    if (i > 0) {
      // Each step doubles the points: the noise falls by √2.
      EXPECT_NEAR(estimates[i - 1] / estimates[i], std::sqrt(2.0), 0.2) << "at step " << i;
    }
  }
}

TEST(Convergence, ANewGenerationOrGridStartsOver) {
  ConvergenceMeter meter;
  DensitySample sample;
  sample.generation = 1;
  sample.hits.assign(1000, 10);
  sample.points = 10'000;
  EXPECT_TRUE(std::isnan(meter.update(sample)));
  for (std::size_t v = 0; v < sample.hits.size(); ++v) sample.hits[v] += 10 + static_cast<std::uint32_t>(v % 3);
  sample.points = 21'000;
  EXPECT_TRUE(std::isfinite(meter.update(sample)));
  sample.generation = 2;
  EXPECT_TRUE(std::isnan(meter.update(sample))) << "another generation's counts are not comparable";
  EXPECT_TRUE(std::isnan(meter.noise()));
}

TEST(Convergence, NoiseIsCappedWhenThereIsMoreNoiseThanSignal) {
  // Two hits per voxel, one of them new: the noise is as large as the density.
  std::vector<std::uint32_t> earlier(10'000, 0), later(10'000, 0);
  for (std::size_t v = 0; v < earlier.size(); ++v) {
    earlier[v] = v % 2 ? 1 : 0;
    later[v] = earlier[v] + (v % 3 == 0 ? 1 : 0);
  }
  const double noise = estimateNoise(earlier, later);
  EXPECT_GT(noise, 0.5);
  EXPECT_LE(noise, 1.0);
}

TEST(Convergence, TheSampleStrideIsOddAndKeepsTheSampleSmall) {
  for (std::size_t voxels : {std::size_t{1000}, std::size_t{64} * 64 * 64, std::size_t{512} * 512 * 512}) {
    const std::size_t stride = convergenceSampleStride(voxels);
    EXPECT_EQ(stride % 2, 1u);
    EXPECT_LE(voxels / stride, 2 * kConvergenceSampleVoxels);
  }
}
