// The seam between whoever steers refinement (the explorer's session, a still's pipeline, the
// benches) and what does it: a RefinementBackend iterates a pattern's orbits and adds their points
// into a voxel grid shaped by an inside mask. Two implement it: core::Accumulator on the CPU's
// threads, and gl::GpuAccumulator in compute shaders (engine/gl/). Both keep the grid in one layout
// (hit counts with the outside flag in their top bit, colour sums in colour cells), so what reads a
// grid (packing for the ray-marcher, chunk sums, checkpoints, the convergence meter) reads either.
//
// Every change of pattern bumps a *generation*: the grid is cleared and work of the older
// generation is thrown away. Readers take versioned views; a backend never blocks its caller for
// longer than a probe or a read-back.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/core_budget.h"
#include "core/grid.h"
#include "core/progress_signal.h"
#include "core/refinement/convergence.h"
#include "core/refinement/prepared_layer.h"
#include "core/scene.h"

namespace voxflame::core {

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

// Which implementation refines: the CPU's worker threads, or compute shaders on the GL device.
enum class BackendKind { Cpu, Gpu };
inline constexpr std::string_view kBackendKindNames[] = {"cpu", "gpu"};

struct PackedVolume;  // core/packed_volume.h, which reads a backend's grid

class RefinementBackend {
 public:
  virtual ~RefinementBackend() = default;

  // What setPattern does with a pattern none of whose layers stays bounded.
  enum class WhenEscaping {
    Clear,            // a new, empty generation that says why it stays empty (a still must not go on)
    KeepLastBounded,  // the grid keeps the last bounded pattern's points, and the refinement stops:
                      // what the explorer shows while a drag passes through an escape
  };

  virtual BackendKind kind() const = 0;
  // Starts a new generation with these layers: the grid is cleared and refinement restarts.
  // Blocks only for the probe of each layer (milliseconds) and the end of a running batch.
  virtual void setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed,
                          WhenEscaping whenEscaping = WhenEscaping::Clear) = 0;
  // How points are added to the grid (default Jittered). Takes effect at the next setPattern.
  virtual void setDeposit(Deposit deposit) = 0;
  // How colour index layers look up their gradient (flam3's palette_mode). Takes effect at the next
  // setPattern.
  virtual void setPaletteMode(PaletteMode mode) = 0;
  // Stop once this many points are inside (0 = refine forever).
  virtual void setTargetPoints(std::uint64_t target) = 0;
  // Restarts every orbit in the random streams of chunk `chunk` (chunk 0 is where setPattern
  // starts), with the counts towards the target back at zero. `clearGrid`: the grid starts empty
  // too; otherwise the chunk adds to what is there. Call while idle or held, then set the target.
  virtual void setChunk(std::uint64_t chunk, bool clearGrid) = 0;
  // Prepare the next patterns with a deep seed pool (prepareLayers): set before setPattern when
  // the points will be split into chunks.
  virtual void setDeepSeeds(bool deep) = 0;
  // While held nothing refines; the grid keeps what it has.
  virtual void setHeld(bool held) = 0;
  // Waits until the target is reached or the pattern cannot accumulate; false on timeout.
  virtual bool waitUntilDone(double timeoutSeconds) = 0;
  // Nothing refines now, nor will until the pattern, target or hold changes: held, done or
  // without a pattern, with no batch (or dispatch) under way, so stats and the grid stay as they
  // are. Never waits: for a caller that waits on the backend's progress (a test) to see that the
  // work in flight when it held the backend has landed.
  virtual bool idle() const = 0;

  virtual AccumulatorStats stats() const = 0;
  // Moves with every batch of points that lands, and every change of pattern.
  virtual std::uint64_t version() const = 0;
  virtual std::uint64_t generation() const = 0;
  // Notified after every batch that lands (version() moved) and every change of pattern, hold or
  // target: what a reader following the grid (or a test) waits on instead of a timer.
  virtual ProgressSignal& progress() const = 0;
  // The budget of CPU cores its work shares (null: none); a reader that works as hard as a worker
  // (a pack) holds a core of it too.
  virtual CoreBudget* coreBudget() const { return nullptr; }
  // Its work takes a freed core of the budget first (the proxy's, so an edit shows at once).
  virtual void setCoresFirst(bool /*first*/) {}
  virtual bool coresFirst() const { return false; }
  virtual const InsideMask& mask() const = 0;
  virtual const std::vector<PreparedLayer>& preparedLayers() const = 0;  // the steering thread's use
  virtual const ColourLayout& colourLayout() const = 0;
  virtual std::uint64_t insideVoxels() const = 0;  // voxels inside the mask
  // The backend's own memory for its grid, in bytes (host memory, or device memory on a GPU).
  virtual std::size_t gridBytes() const = 0;

  // Copies the grid; safe to call while refinement runs.
  virtual void snapshot(VolumeSnapshot& out) const = 0;
  // Shows the grid to `visit` slab by slab in z order (the CPU's slabs under their own locks; a
  // GPU backend's one read-back as a single slab), with nothing copied beyond that: what packing
  // for the renderer and chunk sums read. `reading` is filled in before the first slab.
  template <class Visit>
  void readSlabs(GridReading& reading, Visit&& visit) const {
    using VisitType = std::remove_reference_t<Visit>;
    readSlabsImpl(
        reading, [](const GridSlabView& slab, void* context) { (*static_cast<VisitType*>(context))(slab); },
        const_cast<void*>(static_cast<const void*>(&visit)));
  }
  // The hit counts of every convergenceSampleStride()-th voxel, for a ConvergenceMeter: a few
  // milliseconds at any grid size, safe to call while refinement runs.
  virtual void sampleDensity(DensitySample& out) const = 0;
  // Packs the grid for the renderer where it lies, on the GPU (PackedVolume::device), when this
  // backend can hand its textures to the renderer's context; false (nothing done) otherwise, and
  // then core::packVolume reads the grid through readSlabs.
  virtual bool packOnDevice(PackedVolume& /*out*/) const { return false; }
  virtual bool packsOnDevice() const { return false; }  // whether packOnDevice does

 protected:
  virtual void readSlabsImpl(GridReading& reading, void (*visit)(const GridSlabView&, void*), void* context) const = 0;
};

// A new grid's GridReading::gridId: unique in the process, whichever backend holds the grid.
std::uint64_t nextGridId();

std::string_view toString(BackendKind kind);
BackendKind backendKindFromString(std::string_view name);  // throws core::Error listing the kinds

}  // namespace voxflame::core
