// The Accumulator owns progressive refinement: worker threads iterate many independent orbits of
// every pattern layer, drop transients and points outside the inside mask, reseed orbits that
// diverge (never splatting them), and add density and colour into one shared voxel grid.
//
// Every change of pattern bumps a *generation*: the grid is cleared and work of the older
// generation is thrown away. Readers (the UI, the exporter) take versioned snapshots; the
// accumulator never touches GL. Threads are std::jthreads owned here and joined in the destructor.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <thread>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>

#include "inside_mask.h"
#include "scene.h"

namespace voxflame::core {

// Maps attractor coordinates into grid voxel coordinates: uniform scale about a centre.
struct FitTransform {
  glm::dvec3 attractorCenter{0.0};
  double scale = 1.0;          // voxels per attractor unit
  glm::dvec3 gridCenter{0.0};  // in voxel units
  glm::dvec3 apply(glm::dvec3 p) const { return (p - attractorCenter) * scale + gridCenter; }
};

// What one layer needs to run, prepared once per generation from a short probe orbit.
struct PreparedLayer {
  PatternLayer layer;
  const AttractorInfo* info = nullptr;
  FitTransform fit;
  std::vector<glm::dvec3> seeds;     // points known to lie on the attractor
  double escapeRadius = 1e6;         // beyond this an orbit counts as escaped
  double speedReference = 1.0;       // speed mapped to the gradient's end
  std::vector<glm::u8vec3> palette;  // 256 gradient entries, linear RGB
  bool bounded = false;              // the probe orbit stayed finite and bounded
};

// Samples the layer's attractor and fits it into the mask's grid. Deterministic for a seed.
PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, std::uint64_t seed);

// A copy of the grid for rendering: raw density (hits) and average colour per voxel.
struct VolumeSnapshot {
  GridGeometry geometry;
  std::vector<float> density;
  std::vector<std::uint8_t> rgba;  // average linear colour, alpha unused (255)
  float maxDensity = 0.0f;
  std::uint64_t version = 0;
  std::uint64_t points = 0;
};

struct AccumulatorStats {
  std::uint64_t generation = 0;
  std::uint64_t iterations = 0;  // orbit steps taken, transients included
  std::uint64_t points = 0;      // points splatted inside the mask
  std::uint64_t outside = 0;     // points dropped for lying outside the mask
  std::uint64_t escapes = 0;     // orbits that diverged and were reseeded
  double pointsPerSecond = 0.0;  // iterations per second over the current generation
  double insideFraction() const {
    const auto total = points + outside;
    return total ? static_cast<double>(points) / static_cast<double>(total) : 0.0;
  }
  bool done = false;    // the target number of points was reached
  std::string problem;  // why nothing accumulates (an escaping attractor), else empty
};

class Accumulator {
 public:
  // threads == 0 means one per hardware thread.
  Accumulator(std::shared_ptr<const InsideMask> mask, int threads = 0);
  ~Accumulator();
  Accumulator(const Accumulator&) = delete;
  Accumulator& operator=(const Accumulator&) = delete;

  // Starts a new generation with these layers: the grid is cleared and refinement restarts.
  // Blocks only for the probe of each layer (milliseconds) and the end of a running batch.
  void setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed);
  // Stop once this many points are inside (0 = refine forever).
  void setTargetPoints(std::uint64_t target);
  // Waits until the target is reached or the pattern cannot accumulate; false on timeout.
  bool waitUntilDone(double timeoutSeconds);

  AccumulatorStats stats() const;
  std::uint64_t version() const { return version_.load(std::memory_order_acquire); }
  std::uint64_t generation() const { return generation_.load(std::memory_order_acquire); }
  int threadCount() const { return static_cast<int>(threads_.size()); }
  const InsideMask& mask() const { return *mask_; }
  const std::vector<PreparedLayer>& preparedLayers() const { return layers_; }  // main-thread use

  // Copies the grid; safe to call while the workers run.
  void snapshot(VolumeSnapshot& out) const;

 private:
  void workerLoop(std::stop_token stop, int threadIndex);
  void runBatch(int threadIndex, std::uint64_t generation, std::vector<struct OrbitBatch>& batches);

  std::shared_ptr<const InsideMask> mask_;
  std::vector<std::uint32_t> density_;   // hits per voxel, updated with atomic_ref
  std::vector<std::uint32_t> colorSum_;  // 3 per voxel: sums of 8-bit linear colour

  mutable std::shared_mutex gridMutex_;  // shared: a batch writing; exclusive: a generation change
  std::vector<PreparedLayer> layers_;    // guarded by gridMutex_
  std::uint64_t seed_ = 1;

  std::atomic<std::uint64_t> generation_{0};
  std::atomic<std::uint64_t> version_{0};
  std::atomic<std::uint64_t> iterations_{0};
  std::atomic<std::uint64_t> points_{0};
  std::atomic<std::uint64_t> outside_{0};
  std::atomic<std::uint64_t> escapes_{0};
  std::atomic<std::uint64_t> targetPoints_{0};
  std::atomic<bool> active_{false};  // a pattern is set and can accumulate
  std::atomic<double> generationStart_{0.0};
  std::string problem_;  // guarded by gridMutex_

  std::mutex wakeMutex_;
  std::condition_variable_any wake_;  // workers sleep here when idle
  std::condition_variable doneSignal_;

  std::vector<std::jthread> threads_;
};

}  // namespace voxflame::core
