// The Accumulator owns progressive refinement: worker threads iterate many independent orbits of
// every pattern layer, drop transients and points outside the inside mask, reseed orbits that
// diverge (never splatting them), and add density and colour into one shared voxel grid.
//
// Speed comes from three things: orbits advance as structure-of-arrays batches that the compiler
// vectorises; a second vectorised pass turns each new point into a voxel index and a palette
// colour without branches; and points are not added to the grid one at a time with atomics but
// collected per thread, sorted by grid slab and added with plain stores under that slab's mutex
// (one lock per slab per few thousand points; the adds overlap their cache misses). The inside
// mask lives in each voxel's hit count as a flag, so the exact test costs no extra memory access.
// Colour sums live in colour cells (one per voxel up to 256³, one per 2×2×2 voxels above): a splat
// adds one to its voxel's hits and its colour to its cell.
//
// Every change of pattern bumps a *generation*: the grid is cleared and work of the older
// generation is thrown away. Readers (the UI, the exporter) take versioned snapshots; the
// accumulator never touches GL. Threads are std::jthreads owned here and joined in the destructor.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "chaos_game.h"
#include "convergence.h"
#include "core_budget.h"
#include "inside_mask.h"
#include "progress_signal.h"
#include "scene.h"

namespace voxflame::core {

// Maps attractor coordinates into grid voxel coordinates: scale about a centre (uniform, times a
// per-axis factor for a stretch fit), then the user's rotation, then a move to the grid centre
// (plus the user's offset).
struct FitTransform {
  glm::dvec3 attractorCenter{0.0};
  double scale = 1.0;          // voxels per attractor unit
  glm::dvec3 axisScale{1.0};   // per attractor axis, times scale (1 unless the fit stretches)
  glm::dvec3 gridCenter{0.0};  // in voxel units
  glm::dmat3 rotation{1.0};
  glm::dvec3 apply(glm::dvec3 p) const { return rotation * ((p - attractorCenter) * axisScale * scale) + gridCenter; }
};

// The automatic part of the fit (before the user transform): robust bounds of a probe sample,
// so a 1% parameter change moves it by well under 2%. Exposed for tests and the UI's lock button.
struct AutomaticFit {
  glm::dvec3 center{0.0};
  double scale = 1.0;
  glm::dvec3 axisScale{1.0};  // a stretch fit's shape (geometric mean 1); 1 for contain and cover
};

// What one layer needs to run, prepared once per generation from a short probe orbit.
struct PreparedLayer {
  PatternLayer layer;
  const AttractorInfo* info = nullptr;    // attractor layers
  std::shared_ptr<const ChaosGame> game;  // flame and quaternion Julia layers (shared by copies)
  AutomaticFit automaticFit;
  FitTransform fit;                      // automatic fit (or the locked one) and the user transform
  std::vector<glm::dvec3> seeds;         // points known to lie on the attractor (attractor layers)
  double escapeRadius = 1e6;             // beyond this an orbit counts as escaped
  double speedReference = 1.0;           // speed mapped to the gradient's end
  double distanceReference = 1.0;        // distance from the centre mapped to the gradient's end
  double curvatureReference = 1.0;       // sine of the turning angle mapped to the gradient's end
  double axisLow = 0.0, axisHigh = 1.0;  // extent of the attractor along the colour axis
  glm::dvec3 center{0.0};                // robust centre of the attractor
  std::vector<glm::u8vec3> palette;      // 256 gradient entries, linear RGB
  bool bounded = false;                  // the probe orbit stayed finite and bounded
  bool emptyView = false;                // a chaos game stays finite but (almost) nothing of it is drawn
};

// The box of the voxels inside the mask, in voxel units; the whole grid when the mask is empty.
// What the automatic fit sizes the attractor's robust box against and centres it in.
struct InsideBox {
  glm::dvec3 low{0.0}, high{0.0};
};
// One pass over the mask (a tenth of a second at 512³): an Accumulator finds it once for its
// grid instead of once per pattern.
InsideBox insideBox(const InsideMask& mask);

// The automatic fit of robust bounds (low, median and high percentiles) into the mask's inside box,
// the way `mode` asks (scene.h's FitMode).
AutomaticFit automaticFit(const glm::dvec3& low, const glm::dvec3& median, const glm::dvec3& high,
                          const InsideBox& inside, FitMode mode = FitMode::Contain);

// Each layer followed by its copies (LayerTransform::copies) as layers of their own: turned by the
// copy's angles, the layer's weight shared among them, no copies left. What the Accumulator runs.
std::vector<PatternLayer> expandCopies(const std::vector<PatternLayer>& layers);

// prepareLayer for each layer and its copies (one probe for all copies of a layer), in
// expandCopies's order.
// `inside` is insideBox(mask), when the caller has it already.
// `deepSeeds`: attractor layers draw their orbits' starts from a pool of seeds spread over a long
// run of the probe (tens of milliseconds), not only its first samples: what many short orbits (a
// still's chunks) need to cover the attractor.
std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         const InsideBox& inside, std::uint64_t seed, bool deepSeeds = false);
std::vector<PreparedLayer> prepareLayers(const std::vector<PatternLayer>& layers, const InsideMask& mask,
                                         std::uint64_t seed);

// Samples the layer's attractor and fits it into the mask's grid. Deterministic for a seed.
// Throws core::Error on parameters that are not finite numbers, absurd steps or transforms.
PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, const InsideBox& inside,
                           std::uint64_t seed, bool deepSeeds = false);
PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, std::uint64_t seed);

// Whether an Accumulator runs `layer` (in a scene of `seed`) or counts it as escaping (or
// collapsing, or showing almost nothing): the probe setPattern makes, so the answer is the live
// view's, whose KeepLastBounded keeps the last pattern instead. The mask only places a bounded
// pattern, so a small box stands in for the mesh's. A search asks this of a candidate before it
// hands it back. An invalid layer does not run: false.
bool runsBounded(const PatternLayer& layer, std::uint64_t seed);

// A copy of the grid for rendering: raw density (hits) and average colour per voxel.
struct VolumeSnapshot {
  GridGeometry geometry;
  std::vector<float> density;
  std::vector<std::uint8_t> rgba;  // average linear colour, alpha unused (255)
  float maxDensity = 0.0f;
  std::uint64_t version = 0;
  std::uint64_t generation = 0;  // the pattern generation the grid held when copied
  std::uint64_t points = 0;
  std::uint64_t insideVoxels = 0;  // voxels inside the mask (0: unknown, the occupied ones stand in)
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
  bool done = false;    // the target number of points was reached, or nothing can accumulate
  std::string problem;  // why nothing accumulates (an escaping attractor), else empty
  // With a problem: the grid still holds the last bounded pattern (WhenEscaping::KeepLastBounded),
  // and every other figure here is that pattern's.
  bool showingLastBounded = false;
};

// One batch of points that landed inside the mask, in grid voxel coordinates (continuous: voxel
// (i, j, k) spans [i, i+1) × [j, j+1) × [k, k+1)), with their palette colour.
struct AcceptedPoints {
  const float* x = nullptr;
  const float* y = nullptr;
  const float* z = nullptr;
  const std::uint32_t* rgb = nullptr;  // linear RGB8 packed r | g << 8 | b << 16
  std::size_t count = 0;
  // The seed stream they came from (Accumulator::setChunk): every call holds one stream's points
  // in the order it made them, so a sink can draw its own random numbers per stream and stay
  // independent of the threads.
  std::uint64_t stream = 0;
};

// Receives every accepted point instead of the grid (a points-to-image renderer projects them).
class PointSink {
 public:
  virtual ~PointSink() = default;
  // Called by worker thread `thread` (0 ≤ thread < Accumulator::threadCount()); calls with the same
  // thread index never overlap, calls with different ones run concurrently.
  virtual void consume(int thread, const AcceptedPoints& points) = 0;
};

// How a point is added to the grid. Jittered: the voxel coordinate is moved by an independent
// uniform offset in [-0.5, 0.5) per axis before flooring, so the expected deposit is the trilinear
// tent around the point (measured from voxel centres) and thin sheets do not alias against the
// lattice. Nearest: the voxel that contains the point (the old deposit, kept for benchmarks).
enum class Deposit { Jittered, Nearest };

// A grid's colour is kept at a coarser resolution than its density above this many voxels: one
// colour cell per 2×2×2 voxels. Colour varies slowly next to density (the palette follows speed,
// position or a transform's index, all smooth along the pattern), so the picture keeps every
// detail of the density while the grid needs a third of the memory (6 instead of 20 bytes a voxel).
inline constexpr std::size_t kFullColourVoxels = std::size_t{1} << 24;  // 256³

// How colour cells divide the voxels of a grid: each spans 2^colourShift voxels along every axis.
struct ColourLayout {
  int shift = 0;       // 0: a colour cell per voxel; 1: per 2×2×2 voxels
  glm::ivec3 size{0};  // colour cells along each axis
  static ColourLayout of(const GridGeometry& grid);
  std::size_t cellCount() const { return static_cast<std::size_t>(size.x) * size.y * size.z; }
};

// The accumulator's own memory for a grid, in bytes (hit counts, colour sums and slab bookkeeping):
// what the explorer's grid slider and the memory check count.
std::size_t accumulatorBytes(const GridGeometry& grid);

namespace detail {
// A colour cell's sums of the palette colours of the points that landed in it, and how many they
// were. Colour stops being added at kColourCountLimit points (the sums then stay below 2^32, and
// the mean colour, long converged, stays put) while the voxels' hit counts go on. Where a colour
// cell is one voxel, `count` is that voxel's hit count itself (flag included), so a splat touches
// a single 16-byte slot; the points its colour holds are then min(hits, kColourCountLimit).
struct ColourCell {
  std::uint32_t red = 0, green = 0, blue = 0, count = 0;
};
inline constexpr std::uint32_t kColourCountLimit = std::uint32_t{1} << 24;
// Hit counts carry a voxel's outside-the-mask flag in their top bit (never counted).
inline constexpr std::uint32_t kOutsideBit = 0x80000000u;
// The points whose colours a cell's sums hold (either layout).
inline std::uint32_t colourPoints(const ColourCell& cell) {
  return std::min(cell.count & ~kOutsideBit, kColourCountLimit);
}

// Memory for the grid on 2 MiB pages where the OS offers them: splats land at random across
// hundreds of megabytes, and with 4 KiB pages nearly every one would also miss the TLB.
void* allocateHugePages(std::size_t bytes);  // zero-filled
struct FreeHugePages {
  void operator()(void* p) const;
};
template <class T>
class HugePageArray {
 public:
  void allocate(std::size_t count) {
    data_.reset(static_cast<T*>(allocateHugePages(count * sizeof(T))));
    count_ = count;
  }
  T* data() const { return data_.get(); }
  std::size_t size() const { return count_; }
  T& operator[](std::size_t i) const { return data_.get()[i]; }

 private:
  std::unique_ptr<T[], FreeHugePages> data_;
  std::size_t count_ = 0;
};

}  // namespace detail

// One slab of the grid as readSlabs shows it: whole z slices of voxels and the colour cells over them.
struct GridSlabView {
  int firstZ = 0, endZ = 0;                     // voxel slices [firstZ, endZ)
  const std::uint32_t* hits = nullptr;          // from voxel (0, 0, firstZ) on; the top bit flags outside voxels
  int hitsStride = 1;                           // in uint32s: 4 where the hits live in the colour cells
  int firstColourZ = 0, endColourZ = 0;         // colour cell slices [firstColourZ, endColourZ)
  const detail::ColourCell* colours = nullptr;  // from colour cell (0, 0, firstColourZ) on
  bool empty = false;  // nothing of the current generation has landed here: treat every hit count as 0
  const std::uint8_t* rowInside = nullptr;  // per row of voxels from (0, 0, firstZ) on: does any lie inside
};

// What readSlabs read: the grid and its state when it began.
struct GridReading {
  GridGeometry geometry;
  ColourLayout colour;
  std::uint64_t version = 0;
  std::uint64_t generation = 0;
  std::uint64_t points = 0;
  std::uint64_t insideVoxels = 0;
  std::uint64_t gridId = 0;  // which accumulator (and so which mask) was read: unique in the process
};

class Accumulator {
 public:
  // threads == 0 means one per hardware thread. `cores`: a budget shared with other accumulators
  // (null: none, the workers run whenever they have work).
  Accumulator(std::shared_ptr<const InsideMask> mask, int threads = 0, std::shared_ptr<CoreBudget> cores = nullptr);
  ~Accumulator();
  Accumulator(const Accumulator&) = delete;
  Accumulator& operator=(const Accumulator&) = delete;

  // What setPattern does with a pattern none of whose layers stays bounded.
  enum class WhenEscaping {
    Clear,            // a new, empty generation that says why it stays empty (a still must not go on)
    KeepLastBounded,  // the grid keeps the last bounded pattern's points, and the workers stop:
                      // what the explorer shows while a drag passes through an escape
  };
  // Starts a new generation with these layers: the grid is cleared and refinement restarts.
  // Blocks only for the probe of each layer (milliseconds) and the end of a running batch.
  void setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed,
                  WhenEscaping whenEscaping = WhenEscaping::Clear);
  // How points are added to the grid (default Jittered). Takes effect at the next setPattern.
  void setDeposit(Deposit deposit);
  // How colour index layers (ColorMode::Index) look up their gradient, as flam3 does (the scene's
  // flat.palette_mode): Step takes entry ⌊256 c⌋; Linear blends it with the next entry by the
  // fraction of 256 c, here by taking the next entry with that probability, which sums to the
  // blend in every voxel and pixel. Default Step. Takes effect at the next setPattern.
  void setPaletteMode(PaletteMode mode);
  // When a sink is set, accepted points go to it instead of the grid (they still count as points
  // towards the target and in stats). Set it before setPattern; nullptr restores grid deposits.
  // The sink must outlive the pattern's generation. Positions are exact (never jittered) and the
  // inside test is the voxel's mask flag. The same seed gives the same set of points whatever the
  // number of threads (their order and batching may differ).
  void setPointSink(PointSink* sink);
  // Stop once this many points are inside (0 = refine forever).
  void setTargetPoints(std::uint64_t target);
  // Restarts every orbit in the seed streams of chunk `chunk` (streams chunk·kStreams onwards;
  // chunk 0 is where setPattern starts), with the stream counts back at zero so the target counts
  // the chunk's own points. `clearGrid`: the grid starts empty too (a new generation); otherwise
  // the chunk adds to what is there and the statistics go on counting. A still's points split into
  // chunks (chunk_sums.h) so it can be resumed or spread over a farm. Call when the workers are
  // idle (the previous chunk reached its target) or held, then set the chunk's target.
  void setChunk(std::uint64_t chunk, bool clearGrid);
  // Prepare the next patterns with a deep seed pool (prepareLayers): set before setPattern when
  // the points will be split into chunks.
  void setDeepSeeds(bool deep) { deepSeeds_.store(deep); }
  static constexpr int streamsPerChunk() { return kStreams; }
  // While held the workers start no batch (and sleep), whatever the target; the grid keeps what
  // it has, and a new pattern set meanwhile waits, cleared, until the hold ends.
  void setHeld(bool held);
  // Waits until the target is reached or the pattern cannot accumulate; false on timeout.
  bool waitUntilDone(double timeoutSeconds);
  // Waits until every worker sleeps for want of work (after waitUntilDone: the batches under way
  // when the target was reached have landed), so stats and the grid stay as they are; false on
  // timeout. For tests and tools that read the grid at rest.
  bool waitUntilIdle(double timeoutSeconds);

  AccumulatorStats stats() const;
  std::uint64_t version() const { return version_.load(std::memory_order_acquire); }
  // Notified after every batch that lands (version() moved) and every change of pattern, hold or
  // target: what a reader following the grid waits on instead of a timer. Silent while the
  // workers rest.
  ProgressSignal& progress() const { return progress_; }
  // The budget its workers share (null: none); a reader that works as hard as a worker (a pack)
  // holds a core of it too.
  CoreBudget* coreBudget() const { return cores_.get(); }
  // Its workers take a freed core of the budget before the other accumulator's (the proxy's, so
  // an edit shows within two frames while the large grid refines).
  void setCoresFirst(bool first) { coresFirst_.store(first, std::memory_order_relaxed); }
  bool coresFirst() const { return coresFirst_.load(std::memory_order_relaxed); }
  std::uint64_t generation() const { return generation_.load(std::memory_order_acquire); }
  int threadCount() const { return static_cast<int>(threads_.size()); }
  const InsideMask& mask() const { return *mask_; }
  const std::vector<PreparedLayer>& preparedLayers() const { return layers_; }  // main-thread use

  // Copies the grid; safe to call while the workers run.
  void snapshot(VolumeSnapshot& out) const;
  // Shows the grid to `visit` slab by slab in z order, each under its own lock (workers wait for
  // that slab only), with nothing copied: what packing for the renderer reads, so no full-size
  // snapshot exists in between. Safe to call while the workers run.
  // `reading` is filled in before the first slab is visited.
  template <class Visit>
  void readSlabs(GridReading& reading, Visit&& visit) const {
    using VisitType = std::remove_reference_t<Visit>;
    readSlabsImpl(
        reading, [](const GridSlabView& slab, void* context) { (*static_cast<VisitType*>(context))(slab); },
        const_cast<void*>(static_cast<const void*>(&visit)));
  }
  const ColourLayout& colourLayout() const { return colour_; }
  std::uint64_t insideVoxels() const { return insideVoxels_; }  // voxels inside the mask
  // The hit counts of every convergenceSampleStride()-th voxel, for a ConvergenceMeter: a few
  // milliseconds at any grid size, safe to call while the workers run.
  void sampleDensity(DensitySample& out) const;

 private:
  friend struct SplatBuffer;
  void workerLoop(std::stop_token stop, int threadIndex);
  void runBatch(int threadIndex, int stream, std::uint64_t generation, std::vector<struct OrbitBatch>& batches,
                struct SplatBuffer& splats);
  // Hands a thread's collected points to the sink; returns how many there were.
  std::uint64_t flushPoints(int threadIndex, std::uint64_t streamId, struct SplatBuffer& splats);
  bool streamDone(int stream, std::uint64_t target) const;
  bool allStreamsDone(std::uint64_t target) const;
  // Adds a thread's collected splats to the grid; returns how many landed inside the mask.
  std::uint64_t flushSplats(struct SplatBuffer& splats);
  template <bool kHitsInCells>
  std::uint64_t addSplats(const struct Splat* sorted, const std::size_t* slabEnd);
  void readSlabsImpl(GridReading& reading, void (*visit)(const GridSlabView&, void*), void* context) const;
  std::size_t slabOfColourSlice(int colourZ) const { return static_cast<std::size_t>(colourZ >> slabShift_); }
  int slabFirstZ(std::size_t slab) const;  // the first voxel slice of a slab
  int slabEndZ(std::size_t slab) const;
  void clearCells();  // every slab, for the current generation
  void clearSlab(std::size_t slab);
  void makeSlabCurrent(
      std::size_t slab);  // clears a slab left by an older generation (zero sums, outside flags from the mask)
  void waitForPatternChange() const;  // readers step aside while setPattern waits for the grid

  std::shared_ptr<const InsideMask> mask_;
  std::shared_ptr<CoreBudget> cores_;  // set before the workers start
  std::atomic<bool> coresFirst_{false};

  // The grid, guarded per slab by slabMutexes_. A slab is a run of whole colour slices (and the
  // voxel slices under them), so a colour cell and all its voxels share one slab and one lock.
  detail::HugePageArray<std::uint32_t> hits_;          // per voxel, where colour cells span 2³ voxels
  detail::HugePageArray<detail::ColourCell> colours_;  // per colour cell (with the hits, where one a voxel)
  std::uint32_t* hitsData() const;                     // hit counts, hitsStride() uint32s apart
  int hitsStride() const { return colour_.shift == 0 ? 4 : 1; }
  ColourLayout colour_;
  std::uint64_t insideVoxels_ = 0;
  InsideBox insideBox_;                  // of mask_, for every pattern's fit
  std::vector<std::uint8_t> rowInside_;  // per row of voxels (j, k): does any lie inside the mask
  std::uint64_t gridId_ = 0;
  std::vector<std::uint64_t> brickBits_;  // per 4×4×4 brick: does any voxel lie inside the mask
  int slabShift_ = 0;                     // colour slice >> slabShift_ = its slab
  std::unique_ptr<std::mutex[]> slabMutexes_;
  std::unique_ptr<std::uint64_t[]> slabGeneration_;  // per slab, under its mutex: the generation its cells hold
  std::size_t slabCount_ = 0;

  std::atomic<int> patternWriters_{0};   // setPattern calls waiting for gridMutex_
  mutable std::shared_mutex gridMutex_;  // shared: a batch writing; exclusive: a generation change
  std::vector<PreparedLayer> layers_;    // guarded by gridMutex_
  std::uint64_t seed_ = 1;
  std::uint64_t chunk_ = 0;                   // guarded by gridMutex_ (setChunk)
  std::atomic<std::uint64_t> orbitEpoch_{0};  // bumped by setChunk: orbits restart in the chunk's streams
  std::atomic<bool> deepSeeds_{false};        // setDeepSeeds
  // What setDeposit / setPointSink asked for, and what the current generation uses (copied by
  // setPattern under gridMutex_, so a running batch never sees them change).
  std::atomic<Deposit> requestedDeposit_{Deposit::Jittered};
  std::atomic<PaletteMode> requestedPaletteMode_{PaletteMode::Step};
  PaletteMode paletteMode_ = PaletteMode::Step;  // guarded by gridMutex_
  std::atomic<PointSink*> requestedSink_{nullptr};
  Deposit deposit_ = Deposit::Jittered;  // guarded by gridMutex_
  PointSink* sink_ = nullptr;            // guarded by gridMutex_

  std::atomic<std::uint64_t> generation_{0};
  std::atomic<std::uint64_t> version_{0};
  std::atomic<std::uint64_t> iterations_{0};
  std::atomic<std::uint64_t> points_{0};
  std::atomic<std::uint64_t> outside_{0};
  std::atomic<std::uint64_t> escapes_{0};
  std::atomic<std::uint64_t> targetPoints_{0};
  std::atomic<bool> active_{false};  // a pattern is set and can accumulate
  std::atomic<bool> held_{false};    // setHeld
  std::atomic<double> generationStart_{0.0};
  // Guarded by its own mutex, not gridMutex_: stats() is read every UI frame and must not wait
  // while a generation change clears a large grid.
  mutable std::mutex problemMutex_;
  std::string problem_;              // guarded by problemMutex_
  bool showingLastBounded_ = false;  // guarded by problemMutex_

  void notifyWorkChanged();  // wakes idle workers and waitUntilDone, under wakeMutex_, and progress_
  mutable ProgressSignal progress_;
  std::mutex wakeMutex_;
  // Workers sleep here when idle, each on its own condition. A change of work wakes the first, and
  // each passes the wake-up on to the next once it holds a core of the budget (or finds it has no
  // work): all woken at once, they would queue together for the cores as runnable threads.
  std::unique_ptr<std::condition_variable_any[]> workerWake_;
  std::unique_ptr<std::atomic<bool>[]> wakeAsked_;  // set under wakeMutex_, taken by its worker
  std::condition_variable doneSignal_;
  int sleepingWorkers_ = 0;  // asleep in workerWake_ (waitUntilIdle); guarded by wakeMutex_

  // The work is cut into a fixed number of streams, each with its own orbits and random numbers and
  // a share of the target, and each owned by one thread (stream s by thread s mod threads). What
  // lands in the grid therefore depends on the seed alone, never on the number of threads or how
  // they were scheduled: the same preset and seed give the same volume, bit for bit.
  static constexpr int kStreams = 16;
  int threadCount_ = 1;                                              // set before the threads start
  std::array<std::atomic<std::uint64_t>, kStreams> streamPoints_{};  // inside points this generation

  std::vector<std::jthread> threads_;
};

}  // namespace voxflame::core
