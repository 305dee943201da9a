// The GPU's refinement backend (core/refinement/refinement_backend.h): orbits iterated by a
// compute shader (shaders/accumulate.comp.glsl, with the attractor catalogue in
// shaders/attractors.glsl), one invocation per orbit, their points added to the grid with integer
// atomics in the CPU accumulator's layout, so everything that reads a grid reads this one too.
//
// It runs on a thread of its own ("vf-gpu") with its own headless GL context (EGL): GL stays on the
// thread that owns the context, and the caller's thread (the session's, a still's) only posts
// patterns, targets and holds, exactly as it does to core::Accumulator. Reading the grid
// (readSlabs, snapshot) copies it back to host memory; the density sample for the convergence meter
// is gathered on the GPU and reads back kilobytes.
//
// What it runs: the attractor layers of the catalogue, both integrators, quaternion Julia layers,
// and flame layers whose variations the GPU has (flame_kernel.h: a kernel generated per genome).
// Other flames are the CPU's: setPattern says so in the stats' problem (gpuSupports tells beforehand).
// The same seed gives the same grid on the same kind of device (software or hardware renderer):
// each orbit's random numbers depend on the seed, the chunk and its index alone, integer sums do not
// depend on the order of the adds, and the steps of each dispatch follow from the counts alone.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/chunk_sums.h"
#include "core/inside_mask.h"
#include "core/point_renderer.h"
#include "core/progress_signal.h"
#include "core/refinement/refinement_backend.h"
#include "gl/headless_context.h"

namespace voxflame::gl {

// Empty when the GPU backend runs every one of these layers; else why not, for a message.
std::string gpuUnsupportedReason(const std::vector<core::PatternLayer>& layers);
inline bool gpuSupports(const std::vector<core::PatternLayer>& layers) {
  return gpuUnsupportedReason(layers).empty();
}

// Whether a headless GL context here runs on a hardware GPU (not a software rasteriser such as
// llvmpipe): what `--backend auto` asks. Creates and drops a context; false when none can be made.
bool hardwareGpuAvailable();

class ShaderProgram;

class GpuAccumulator final : public core::RefinementBackend {
 public:
  // Starts the GPU thread and its context; throws core::Error when no OpenGL 4.3 context can be made
  // or the grid does not fit. With `shareWith` (the renderer's context, currentShareGroup() on its
  // thread) the context shares its objects, and packOnDevice hands the renderer GPU textures.
  explicit GpuAccumulator(std::shared_ptr<const core::InsideMask> mask, ShareGroup shareWith = {});
  ~GpuAccumulator() override;  // stops and joins the GPU thread
  GpuAccumulator(const GpuAccumulator&) = delete;
  GpuAccumulator& operator=(const GpuAccumulator&) = delete;

  core::BackendKind kind() const override { return core::BackendKind::Gpu; }
  void setPattern(const std::vector<core::PatternLayer>& layers, std::uint64_t seed,
                  WhenEscaping whenEscaping = WhenEscaping::Clear) override;
  void setDeposit(core::Deposit deposit) override;
  void setPaletteMode(core::PaletteMode mode) override;  // colour index layers (flames, Julia sets)
  void setTargetPoints(std::uint64_t target) override;
  void setChunk(std::uint64_t chunk, bool clearGrid) override;
  void setDeepSeeds(bool deep) override { deepSeeds_.store(deep); }
  // Whether groups of a flame's orbits share each step's transform (flame_kernel.h): the default
  // (bench accumulate on llvmpipe: the default flame 1.5× the steps per second of orbits that draw
  // one by one). From the next setPattern on; the tests and the benchmark run both ways.
  void setGroupChoice(bool group) { groupChoice_.store(group); }
  bool groupChoice() const { return groupChoice_.load(); }
  void setHeld(bool held) override;
  bool waitUntilDone(double timeoutSeconds) override;
  bool idle() const override;  // the GPU thread waits with no task and no dispatch to make

  core::AccumulatorStats stats() const override;
  std::uint64_t version() const override { return version_.load(std::memory_order_acquire); }
  std::uint64_t generation() const override { return generation_.load(std::memory_order_acquire); }
  core::ProgressSignal& progress() const override { return progress_; }
  const core::InsideMask& mask() const override { return *mask_; }
  const std::vector<core::PreparedLayer>& preparedLayers() const override { return layers_; }
  const core::ColourLayout& colourLayout() const override { return colour_; }
  std::uint64_t insideVoxels() const override { return insideVoxels_; }
  std::size_t gridBytes() const override;
  void snapshot(core::VolumeSnapshot& out) const override;
  void sampleDensity(core::DensitySample& out) const override;
  // Packs on the GPU into textures of the renderer's share group (gpu_volume.h), when this backend
  // was made sharing the renderer's context on a hardware GPU; the grid never leaves the device.
  // On a software rasteriser the device is the CPU: its compute passes would run on every core at
  // once, beside the frame (bench explorer at 256³ on llvmpipe: refining frames 29 → 50 ms), where
  // the host pack takes a fifth of one core on the publisher's thread. There it packs on the host,
  // unless the process asks for the device path anyway (the tests, to check it without a GPU).
  bool packOnDevice(core::PackedVolume& out) const override;
  bool sharesWithRenderer() const { return sharesWithRenderer_; }
  bool packsOnDevice() const override {
    return sharesWithRenderer_ && (!software_ || packOnDeviceWithSoftwareRenderer_.load());
  }
  static void setPackOnDeviceWithSoftwareRenderer(bool always) { packOnDeviceWithSoftwareRenderer_.store(always); }

  // The points method on the device (core/point_renderer.h): from here on every accepted point is
  // projected through `projection`'s camera into a screen histogram of its size, dimmed by its
  // transmittance and shadow volumes (uploaded here), in core::pointScale's units, and the grid
  // gets none. Throws core::Error when the histogram is larger than the device binds at once.
  void projectPoints(const core::PointProjection& projection);
  // The histogram's sums since the last call, and it starts again from zero (call while held).
  core::ImageSums takeScreenSums();

  std::string renderer() const { return renderer_; }  // GL_RENDERER of its context
  bool softwareRenderer() const { return software_; }
  // Orbits per layer, and the steps each takes per dispatch: fewer on a software rasteriser, whose
  // dispatches run on the CPU's cores, so holds and new patterns still take effect within milliseconds.
  std::uint32_t orbitsPerLayer() const { return orbits_; }
  int stepsPerDispatch() const { return stepsPerDispatch_; }

 private:
  struct Device;  // the GL objects: created, used and destroyed on the GPU thread only
  void readSlabsImpl(core::GridReading& reading, void (*visit)(const core::GridSlabView&, void*),
                     void* context) const override;
  void loop(std::stop_token stop, std::exception_ptr* startError, std::mutex* startMutex,
            std::condition_variable* started, bool* ready);
  // Runs `task` on the GPU thread and waits for it; rethrows what it threw.
  // `changesGrid`: the task clears or reseeds (setPattern, setChunk); a reader's (a read-back, a
  // density sample, a pack) leaves the grid and the counts as they are, so the backend stays idle().
  void runOnDevice(const std::function<void(Device&)>& task, bool changesGrid = false) const;
  void dispatchRound(Device& device);  // GPU thread: one dispatch of every layer, then the counts
  void setProjectionUniforms(const Device& device, const ShaderProgram& program) const;
  bool targetReached() const;
  void clearGrid(Device& device) const;  // GPU thread: an empty grid, outside flags from the mask
  void notifyWorkChanged();

  std::shared_ptr<const core::InsideMask> mask_;
  ShareGroup shareWith_;
  bool sharesWithRenderer_ = false;  // its context shares the renderer's (set before the constructor returns)
  static inline std::atomic<bool> packOnDeviceWithSoftwareRenderer_{false};
  core::ColourLayout colour_;
  std::uint64_t insideVoxels_ = 0;
  core::InsideBox insideBox_;
  std::vector<std::uint8_t> rowInside_;  // per row of voxels (j, k): does any lie inside the mask
  std::uint64_t gridId_ = 0;
  std::string renderer_;
  bool software_ = true;
  std::uint32_t orbits_ = 0;
  int stepsPerDispatch_ = 0;

  // What the caller set; the GPU thread reads it under mutex_.
  mutable std::mutex mutex_;
  mutable std::condition_variable_any wake_;  // tasks, holds, targets, patterns, stop
  mutable std::deque<std::function<void(Device&)>> tasks_;
  bool dispatching_ = false;                 // the GPU thread runs a round of dispatches (idle())
  mutable int changingTasks_ = 0;            // tasks that change the grid, queued or running (idle())
  std::vector<core::PreparedLayer> layers_;  // the current generation's (set under mutex_)
  std::uint64_t seed_ = 1;
  std::uint64_t chunk_ = 0;
  bool orbitsFresh_ = true;     // the next dispatch seeds every orbit (new pattern or chunk)
  double pointsPerStep_ = 0.0;  // inside points one step of every layer's orbits gave last round
  std::atomic<core::Deposit> deposit_{core::Deposit::Jittered};
  std::atomic<bool> deepSeeds_{false};
  std::atomic<bool> linearPalette_{false};  // PaletteMode::Linear: colour indices dither to the next entry
  std::atomic<bool> groupChoice_{true};     // setGroupChoice
  std::atomic<bool> held_{false};
  std::atomic<bool> active_{false};
  std::atomic<std::uint64_t> targetPoints_{0};
  std::atomic<std::uint64_t> chunkPoints_{0};  // inside points since the last setChunk
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<std::uint64_t> version_{0};
  std::atomic<std::uint64_t> iterations_{0};
  std::atomic<std::uint64_t> points_{0};
  std::atomic<std::uint64_t> outside_{0};
  std::atomic<std::uint64_t> escapes_{0};
  std::atomic<double> generationStart_{0.0};
  std::string problem_;  // under mutex_
  bool showingLastBounded_ = false;
  mutable core::ProgressSignal progress_;
  mutable std::condition_variable_any doneSignal_;  // waitUntilDone, under mutex_

  // The grid as last read back (readSlabs), under hostMutex_.
  mutable std::mutex hostMutex_;
  mutable std::vector<core::detail::ColourCell> hostCells_;
  mutable std::vector<std::uint32_t> hostHits_;

  std::jthread thread_;  // last: started once everything it uses exists
};

// The points method's projecting backend on the GPU (for core::PointsPassOptions::projectingBackend):
// a GpuAccumulator whose accepted points go into its screen histogram, never to the host.
std::unique_ptr<core::ProjectingBackend> makeGpuProjectingBackend(std::shared_ptr<const core::InsideMask> mask,
                                                                  const core::PointProjection& projection);

}  // namespace voxflame::gl
