// The end-to-end path shared by the CLI and the explorer: Scene → mesh → inside mask →
// accumulation → snapshot → ray-marched image.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/chunk_sums.h"
#include "core/error.h"
#include "core/flame/image.h"
#include "core/image_io.h"
#include "core/inside_mask.h"
#include "core/packed_volume.h"
#include "core/refinement/refinement_backend.h"
#include "core/scene.h"
#include "gl/headless_context.h"

namespace voxflame::app {

// A scene's mesh and the inside mask over its grid.
struct SceneShape {
  core::TriangleMesh mesh;
  std::shared_ptr<const core::InsideMask> mask;
};

// Loads the scene's mesh and builds its grid and inside mask (through the mask cache); refuses
// grids too large for this machine.
SceneShape buildSceneShape(const core::Scene& scene);

// Refuses (core::Error saying how much it needs) a grid whose buffers would not fit in memory.
void checkGridFitsInMemory(const core::GridGeometry& grid);

// What a still is doing, for progress reports: loading the mesh and its mask, accumulating
// points, ray-marching the image.
enum class StillStage { Loading, Accumulating, Rendering };
const char* toString(StillStage stage);  // "loading", "accumulating", "rendering"

// A still's points split into chunks, each iterating its own seed streams (core/chunk_sums.h): the
// image depends only on the scene, the size and the number of chunks, so a render resumed from a
// checkpoint, or spread over a farm, gives the same file as one run.
struct ChunkPlan {
  int chunks = 64;
  std::optional<std::vector<int>> render;  // the chunks to render here, in this order (none: all)
  // When set, each rendered chunk's own sums go here as it finishes (a checkpoint writes them) and
  // the image is made from them plus those of `earlier` (chunks finished before, read back).
  std::function<void(int chunk, const core::GridSums& sums)> gridDone;    // volume method
  std::function<void(int chunk, const core::ImageSums& sums)> imageDone;  // points method
  const core::GridSums* earlierGrid = nullptr;
  const core::ImageSums* earlierImage = nullptr;
  bool finish = true;                            // false: only render the chunks (a farm task): no image is made
  std::function<void(int chunksDone)> progress;  // after each chunk rendered here (may be empty)
};

struct StillOptions {
  int width = 1280;
  int height = 720;
  std::uint64_t points = 0;  // 0: the scene's own count
  // > 0: accumulate until the estimated noise (core/refinement/convergence.h, a fraction) is this low, with
  // `points` (when set) as a cap. The volume method only: the points method projects a count.
  double untilNoise = 0.0;
  int threads = 0;  // 0: all hardware threads
  // What refines the volume (resolveBackend gives it from the user's choice): the CPU's threads
  // (`threads` of them) or the GPU's compute shaders. A farm's chunks all use one.
  core::BackendKind backend = core::BackendKind::Cpu;
  // The context of the FrameRenderer that will draw the volume (FrameRenderer::shareGroup), when
  // one exists before the accumulation: a GPU backend sharing it packs its grid on the GPU for that
  // renderer (AccumulatedVolume::packed), with no read-back. Empty: the grid comes to host memory.
  gl::ShareGroup renderer;
  bool linearOutput = false;                  // linear light (for EXR) instead of display-encoded
  const std::atomic<bool>* cancel = nullptr;  // when set and raised, renderStill throws RenderCancelled
  std::function<void(const core::AccumulatorStats&, std::uint64_t target)> progress;  // may be empty
  // Set: the points are split into chunks (the volume method's grid, or the points method's
  // screen histogram; the points method's depth grid is not). None: one set of seed streams,
  // as a noise target needs.
  std::optional<ChunkPlan> chunks;
  // Every stage with its fraction done in [0, 1]: Loading once at 0, Accumulating about every
  // quarter second, Rendering after each tile's sub-sample. May be empty.
  std::function<void(StillStage, double fraction)> stage;
};

struct StillResult {
  core::ImageRGBA image;
  core::AccumulatorStats stats;
  double accumulateSeconds = 0.0;
  double renderSeconds = 0.0;
  std::string renderer;                                // GL_RENDERER
  core::BackendKind backend = core::BackendKind::Cpu;  // what refined the volume
  bool gridOnDevice = false;          // the GPU backend's grid reached the renderer on the GPU (no read-back)
  std::string warning;                // e.g. fewer points landed inside the mesh than asked for
  double coverage = 0.0;              // share of the mesh's silhouette where the pattern shows (flame/image.h)
  std::uint64_t pointsProjected = 0;  // points method: points projected into the image (0: volume method)
  double noise = std::numeric_limits<double>::quiet_NaN();  // the grid's final noise estimate (NaN: none)
};

// Thrown by renderStill when StillOptions::cancel was raised.
class RenderCancelled : public core::Error {
 public:
  RenderCancelled() : core::Error("render cancelled") {}
};

// Renders a still headless through EGL, with the scene's camera, tone and render settings
// (samples included). Throws core::Error on anything the user can fix.
StillResult renderStill(const core::Scene& scene, const StillOptions& options);

// The first half of a still: the scene's pattern accumulated into its grid until the scene's
// point count (or options.points) lies inside the mesh, or until options.untilNoise is reached.
// Honours options.cancel and .progress (whose target is then the points the noise is estimated
// to need). The noise is measured along the way (a point count stops a third of the way first, for a
// reference), so the result carries its final estimate.
// For the points method the grid only gives depth (transmittance and shadows), so it takes at
// most kGridPointsForPointsMethod points; the points pass projects the full count.
struct AccumulatedVolume {
  core::VolumeSnapshot snapshot;  // empty where `packed` is set
  // The volume packed on the GPU for StillOptions::renderer (PackedVolume::device), in place of the
  // snapshot, and the backend whose textures it names, kept until the renderer has copied them.
  std::optional<core::PackedVolume> packed;
  std::unique_ptr<core::RefinementBackend> packedBy;
  core::AccumulatorStats stats;
  double seconds = 0.0;
  std::string warning;                                      // e.g. fewer points landed inside the mesh than asked for
  double noise = std::numeric_limits<double>::quiet_NaN();  // the final estimate (core/refinement/convergence.h)
};
// The point count an accumulation with StillOptions::untilNoise and no `points` stops at anyway.
inline constexpr std::uint64_t kUntilNoisePointCap = std::uint64_t{1} << 40;
inline constexpr std::uint64_t kGridPointsForPointsMethod = 40'000'000;
AccumulatedVolume accumulateVolume(const core::Scene& scene, const SceneShape& shape, const StillOptions& options);

// The second half: draws accumulated volumes headless. It keeps one GL context and the uploaded
// volume, so a sequence of frames pays for the context once and re-uploads only a new volume.
class FrameRenderer {
 public:
  FrameRenderer();  // creates the headless context; throws core::Error when there is none
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // The volume (and the shape it was accumulated in) later render() calls draw. One packed on the
  // GPU (AccumulatedVolume::packed) is copied there, and its shadows are swept there too.
  void setVolume(const core::PackedVolume& volume, const SceneShape& shape);
  // This renderer's context, for StillOptions::renderer (on the thread that made the renderer).
  gl::ShareGroup shareGroup() const;
  // For the points method: how many points to project (0: the scene's count) on how many threads,
  // and by which backend (the GPU's projects them on the device, core::ProjectingBackend).
  void setPointsPass(std::uint64_t points, int threads, const ChunkPlan* chunks = nullptr,
                     core::BackendKind backend = core::BackendKind::Cpu);
  // `scene`'s camera, tone and render settings (method, samples, oversample, mesh overlay,
  // lighting). `progress` (may be empty) gets the fraction done (after each tile's sub-sample, or
  // as points are projected); it may throw to stop the render.
  struct Rendered {
    core::ImageRGBA image;
    double coverage = 0.0;              // share of the mesh's silhouette where the pattern shows
    std::uint64_t pointsProjected = 0;  // points method: the points drawn (the grid pass took fewer)
    // With keepSums(true): what the image was finished from (the supersampled sums and the mesh
    // layer at the output size), so tests can hold the GPU's finish to core::finishImage.
    core::DensityImage density;
    core::MeshOverlay mesh;
  };
  void keepSums(bool keep);
  Rendered renderWithStats(const core::Scene& scene, int width, int height, bool linearOutput,
                           const std::function<void(double)>& progress = {});
  core::ImageRGBA render(const core::Scene& scene, int width, int height, bool linearOutput,
                         const std::function<void(double)>& progress = {});
  const std::string& rendererName() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The PNG text chunks that make a render reproducible: the preset and render statistics. Without
// times the statistics leave out how long it took, so the same image rendered again, on any
// machine, is the same file byte for byte (animation frames, which a farm may render).
core::TextChunks stillMetadata(const core::Scene& scene, const StillResult& result, bool withTimes = true);

inline constexpr const char* kPresetChunkKey = "voxflame:preset";

// The scene stored in a PNG rendered by voxflame (its "voxflame:preset" chunk).
core::Scene sceneFromImage(const std::filesystem::path& path);

// `scene` with its mesh replaced by the mesh file at `path` (the pattern and look stay).
core::Scene sceneWithMesh(core::Scene scene, const std::filesystem::path& path);

// Whatever a user can open: a preset (.json), a PNG rendered by voxflame (its preset), a flame
// file (.flame/.flam3: its first flame imported into the default mesh, warnings on stderr), or a
// mesh (any other file: the default pattern fills it). Throws core::Error naming the file.
core::Scene sceneFromFile(const std::filesystem::path& path);

}  // namespace voxflame::app
