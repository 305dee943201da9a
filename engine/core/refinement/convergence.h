// How far a refining volume still is from its limit: an estimate of the noise left in the voxel
// densities, from how much they change between two samples of the same generation.
//
// A voxel's hit count is a Monte Carlo sum: its relative error falls like 1/sqrt(hits). Between
// a sample of C1 hits and a later one of C2 hits (counted over the same voxels), the normalised
// densities d = hits / C differ by noise alone, and for counts that grow by independent
// increments E[(d2 - d1)²] = Var(d2) · (C2 - C1) / C1 per voxel. So the change between samples,
// scaled by C1 / (C2 - C1), estimates the variance still in the newer one, whatever the pattern.
//
// The unit: the RMS error of the voxel densities relative to their RMS value, ‖error‖ / ‖density‖
// over the sampled voxels (a fraction; 0.01 is 1%). For a uniformly filled volume it is the
// relative error of one voxel, 1/sqrt(hits per voxel); the weighting by density makes the dense
// voxels, which the picture shows, count most. It is scale-free (no dependence on the point count's
// units, the grid's size or how much of it is empty), so one target means the same on any grid;
// a finer grid simply needs more points to reach it. Colour is left out: a voxel's colour is the
// mean over the same hits, whose error is smaller than the density's whenever the colours within
// a voxel vary by less than their mean.
//
// Only a fixed subsample of voxels is read (kConvergenceSampleVoxels), so a measurement costs
// the same few milliseconds at 512³ as at 64³ and can run while the workers refine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace voxflame::core {

// About how many voxels a sample reads (spread evenly over the grid).
inline constexpr std::size_t kConvergenceSampleVoxels = std::size_t{1} << 17;

// Hit counts of a fixed subsample of a grid's voxels (Accumulator::sampleDensity fills it).
struct DensitySample {
  std::uint64_t generation = 0;
  std::uint64_t points = 0;         // the accumulator's point count when sampled
  std::vector<std::uint32_t> hits;  // per sampled voxel
};

// Every `stride`-th voxel of a grid of `voxels`, where the stride keeps a sample near
// kConvergenceSampleVoxels and is odd, so the sampled voxels do not line up with a grid axis.
std::size_t convergenceSampleStride(std::size_t voxels);

class ConvergenceMeter {
 public:
  // Takes a new sample and returns the estimate for it (NaN while there is none yet). A sample of
  // another generation, grid or an earlier moment starts over; one that has not added a quarter as many
  // hits again since the reference sample (and at least kMinimumHits) keeps the last estimate, scaled by
  // 1/sqrt(points).
  double update(const DensitySample& sample);
  // The latest estimate, scaled to the latest sample's point count; NaN when there is none.
  double noise() const { return noise_; }
  // The last two measurements themselves (not scaled on to later point counts), newest first;
  // NaN until taken. A picture has stopped changing when both are at or under a target: one
  // measurement alone can fall under it by chance, or while an orbit dwells in one part of a flow
  // between two samples, and the estimate between measurements is only an extrapolation.
  double lastMeasurement() const { return measured_; }
  double previousMeasurement() const { return previous_; }
  bool twoMeasurementsWithin(double target) const { return measured_ <= target && previous_ <= target; }
  // Measurements taken since the last reset.
  int measurements() const { return measurements_; }
  void reset();

  // At least this many hits in a sample, and this many added since the reference, for a measure.
  static constexpr std::uint64_t kMinimumHits = 2000;

 private:
  bool farEnough(std::uint64_t hits) const;  // from the reference, for a measurement
  DensitySample reference_;
  std::uint64_t referenceHits_ = 0;
  bool haveReference_ = false;
  double measured_ = std::numeric_limits<double>::quiet_NaN();  // at measuredPoints_
  double previous_ = std::numeric_limits<double>::quiet_NaN();  // the measurement before it
  int measurements_ = 0;
  std::uint64_t measuredPoints_ = 0;
  double noise_ = std::numeric_limits<double>::quiet_NaN();
};

// The relative noise of `later` estimated from its change since `earlier` (the unit above); NaN
// when `later` did not add hits to `earlier`'s. Exposed for tests.
double estimateNoise(const std::vector<std::uint32_t>& earlier, const std::vector<std::uint32_t>& later);

}  // namespace voxflame::core
