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
// It is the CPU's RefinementBackend (refinement_backend.h: generations, versions, the grid's
// layout). It never touches GL. Threads are std::jthreads owned here and joined in the destructor.
#pragma once

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
#include <vector>

#include "core/core_budget.h"
#include "core/inside_mask.h"
#include "core/progress_signal.h"
#include "core/refinement/prepared_layer.h"
#include "core/refinement/refinement_backend.h"
#include "core/scene.h"

namespace voxflame::core {

// The accumulator's own memory for a grid, in bytes (hit counts, colour sums and slab bookkeeping):
// what the explorer's grid slider and the memory check count.
std::size_t accumulatorBytes(const GridGeometry& grid);

namespace detail {
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

class Accumulator final : public RefinementBackend {
 public:
  // threads == 0 means one per hardware thread. `cores`: a budget shared with other accumulators
  // (null: none, the workers run whenever they have work).
  Accumulator(std::shared_ptr<const InsideMask> mask, int threads = 0, std::shared_ptr<CoreBudget> cores = nullptr);
  ~Accumulator() override;
  Accumulator(const Accumulator&) = delete;
  Accumulator& operator=(const Accumulator&) = delete;

  BackendKind kind() const override { return BackendKind::Cpu; }
  // Starts a new generation with these layers: the grid is cleared and refinement restarts.
  // Blocks only for the probe of each layer (milliseconds) and the end of a running batch.
  void setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed,
                  WhenEscaping whenEscaping = WhenEscaping::Clear) override;
  // How points are added to the grid (default Jittered). Takes effect at the next setPattern.
  void setDeposit(Deposit deposit) override;
  // How colour index layers (ColorMode::Index) look up their gradient, as flam3 does (the scene's
  // flat.palette_mode): Step takes entry ⌊256 c⌋; Linear blends it with the next entry by the
  // fraction of 256 c, here by taking the next entry with that probability, which sums to the
  // blend in every voxel and pixel. Default Step. Takes effect at the next setPattern.
  void setPaletteMode(PaletteMode mode) override;
  // When a sink is set, accepted points go to it instead of the grid (they still count as points
  // towards the target and in stats). Set it before setPattern; nullptr restores grid deposits.
  // The sink must outlive the pattern's generation. Positions are exact (never jittered) and the
  // inside test is the voxel's mask flag. The same seed gives the same set of points whatever the
  // number of threads (their order and batching may differ).
  void setPointSink(PointSink* sink);
  // Stop once this many points are inside (0 = refine forever).
  void setTargetPoints(std::uint64_t target) override;
  // Restarts every orbit in the seed streams of chunk `chunk` (streams chunk·kStreams onwards;
  // chunk 0 is where setPattern starts), with the stream counts back at zero so the target counts
  // the chunk's own points. `clearGrid`: the grid starts empty too (a new generation); otherwise
  // the chunk adds to what is there and the statistics go on counting. A still's points split into
  // chunks (chunk_sums.h) so it can be resumed or spread over a farm. Call when the workers are
  // idle (the previous chunk reached its target) or held, then set the chunk's target.
  void setChunk(std::uint64_t chunk, bool clearGrid) override;
  // Prepare the next patterns with a deep seed pool (prepareLayers): set before setPattern when
  // the points will be split into chunks.
  void setDeepSeeds(bool deep) override { deepSeeds_.store(deep); }
  static constexpr int streamsPerChunk() { return kStreams; }
  // While held the workers start no batch (and sleep), whatever the target; the grid keeps what
  // it has, and a new pattern set meanwhile waits, cleared, until the hold ends.
  void setHeld(bool held) override;
  // Waits until the target is reached or the pattern cannot accumulate; false on timeout.
  bool waitUntilDone(double timeoutSeconds) override;
  // Waits until every worker sleeps for want of work (after waitUntilDone: the batches under way
  // when the target was reached have landed), so stats and the grid stay as they are; false on
  // timeout. For tests and tools that read the grid at rest.
  bool waitUntilIdle(double timeoutSeconds);
  // Every worker sleeps and none is asked to wake.
  bool idle() const override;

  AccumulatorStats stats() const override;
  std::uint64_t version() const override { return version_.load(std::memory_order_acquire); }
  // Notified after every batch that lands (version() moved) and every change of pattern, hold or
  // target: what a reader following the grid waits on instead of a timer. Silent while the
  // workers rest.
  ProgressSignal& progress() const override { return progress_; }
  // The budget its workers share (null: none); a reader that works as hard as a worker (a pack)
  // holds a core of it too.
  CoreBudget* coreBudget() const override { return cores_.get(); }
  // Its workers take a freed core of the budget before the other accumulator's (the proxy's, so
  // an edit shows within two frames while the large grid refines).
  void setCoresFirst(bool first) override { coresFirst_.store(first, std::memory_order_relaxed); }
  bool coresFirst() const override { return coresFirst_.load(std::memory_order_relaxed); }
  std::uint64_t generation() const override { return generation_.load(std::memory_order_acquire); }
  int threadCount() const { return static_cast<int>(threads_.size()); }
  const InsideMask& mask() const override { return *mask_; }
  const std::vector<PreparedLayer>& preparedLayers() const override { return layers_; }  // main-thread use

  // Copies the grid; safe to call while the workers run.
  void snapshot(VolumeSnapshot& out) const override;
  // readSlabs (RefinementBackend) shows each slab under its own lock (workers wait for that slab
  // only), with nothing copied: what packing for the renderer reads, so no full-size snapshot
  // exists in between.
  const ColourLayout& colourLayout() const override { return colour_; }
  std::uint64_t insideVoxels() const override { return insideVoxels_; }  // voxels inside the mask
  // The hit counts of every convergenceSampleStride()-th voxel, for a ConvergenceMeter: a few
  // milliseconds at any grid size, safe to call while the workers run.
  void sampleDensity(DensitySample& out) const override;
  std::size_t gridBytes() const override;

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
  void readSlabsImpl(GridReading& reading, void (*visit)(const GridSlabView&, void*), void* context) const override;
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
  mutable std::mutex wakeMutex_;
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
