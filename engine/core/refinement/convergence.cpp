#include "core/refinement/convergence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace voxflame::core {

namespace {

std::uint64_t totalHits(const std::vector<std::uint32_t>& hits) {
  return std::accumulate(hits.begin(), hits.end(), std::uint64_t{0});
}

}  // namespace

std::size_t convergenceSampleStride(std::size_t voxels) {
  return (voxels / kConvergenceSampleVoxels) | 1u;
}

double estimateNoise(const std::vector<std::uint32_t>& earlier, const std::vector<std::uint32_t>& later) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (earlier.size() != later.size()) return nan;
  const auto c1 = static_cast<double>(totalHits(earlier)), c2 = static_cast<double>(totalHits(later));
  if (c1 <= 0.0 || c2 <= c1) return nan;
  // Densities are normalised by the sample's own total rather than the accumulator's point count,
  // which a running batch may not have added yet: the two would disagree by up to a batch.
  double change = 0.0, signal = 0.0;
  for (std::size_t v = 0; v < later.size(); ++v) {
    if (later[v] == 0) continue;
    const double d1 = static_cast<double>(earlier[v]) / c1, d2 = static_cast<double>(later[v]) / c2;
    change += (d2 - d1) * (d2 - d1);
    signal += d2 * d2;
  }
  const double variance = change * c1 / (c2 - c1);  // of the later densities, summed over voxels
  // Σ d2² holds the noise too; what is left is the signal. When noise is half of it or more the
  // picture is mostly noise and the estimate is capped at 100%.
  return std::sqrt(variance / std::max(signal - variance, variance));
}

bool ConvergenceMeter::farEnough(std::uint64_t hits) const {
  // A quarter as many hits again as the reference: the change is then four times the remaining
  // variance's share, summed over the sample's hundred thousand voxels, not a small difference of
  // two nearly equal sums. Measurements half as far apart (×1.5) let the second one under a target
  // come when refinement was already near its cap, which then stopped it instead.
  return referenceHits_ >= kMinimumHits && hits >= referenceHits_ + std::max(kMinimumHits, referenceHits_ / 4);
}

double ConvergenceMeter::update(const DensitySample& sample) {
  const std::uint64_t hits = totalHits(sample.hits);
  const bool sameRun = haveReference_ && sample.generation == reference_.generation &&
                       sample.hits.size() == reference_.hits.size() && hits >= referenceHits_ &&
                       sample.points >= reference_.points;
  if (!sameRun) {
    reset();
  } else if (farEnough(hits)) {
    previous_ = measured_;
    measured_ = estimateNoise(reference_.hits, sample.hits);
    measuredPoints_ = sample.points;
    ++measurements_;
  }
  // The newer sample is the next reference unless it is too close to the old one to measure from:
  // a reference that moves a little each time would never be far enough behind.
  if (!sameRun || referenceHits_ < kMinimumHits || farEnough(hits)) {
    reference_ = sample;
    referenceHits_ = hits;
    haveReference_ = true;
  }
  noise_ = measured_;
  if (std::isfinite(measured_) && measuredPoints_ > 0 && sample.points > measuredPoints_)
    noise_ = measured_ * std::sqrt(static_cast<double>(measuredPoints_) / static_cast<double>(sample.points));
  return noise_;
}

void ConvergenceMeter::reset() {
  reference_ = DensitySample{};
  referenceHits_ = 0;
  haveReference_ = false;
  measured_ = std::numeric_limits<double>::quiet_NaN();
  previous_ = measured_;
  measurements_ = 0;
  measuredPoints_ = 0;
  noise_ = measured_;
}

}  // namespace voxflame::core
