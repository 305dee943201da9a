#include "pipeline.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "core/camera.h"
#include "core/error.h"
#include "core/mask_cache.h"
#include "core/scene_io.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"
#include "version.h"

namespace voxflame::app {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void checkGridFitsInMemory(const core::GridGeometry& grid) {
  // Per voxel: mask 1 B, density and colour sums 16 B, a snapshot 8 B, its upload copy 8 B.
  constexpr double kBytesPerVoxel = 1.0 + 16.0 + 8.0 + 8.0;
  core::checkGridFitsInMemory(grid, kBytesPerVoxel);
}

std::shared_ptr<const core::InsideMask> buildSceneMask(const core::Scene& scene) {
  const core::TriangleMesh mesh = core::loadSceneMesh(scene);
  const core::GridGeometry grid = core::gridOverBox(mesh.bounds(), scene.gridResolution);
  checkGridFitsInMemory(grid);
  // Reopening a preset finds its mask in the user's cache instead of computing it again.
  return std::make_shared<const core::InsideMask>(
      core::cachedInsideMask(mesh, grid, core::MaskMethod::WindingNumber, core::defaultMaskCacheFolder()));
}

StillResult renderStill(const core::Scene& scene, const StillOptions& options) {
  StillResult result;
  const auto mask = buildSceneMask(scene);
  const std::uint64_t target = options.points ? options.points : scene.points;

  const auto accumulateStart = std::chrono::steady_clock::now();
  core::VolumeSnapshot snapshot;
  {
    core::Accumulator accumulator(mask, options.threads);
    accumulator.setTargetPoints(target);
    accumulator.setPattern(scene.layers, scene.seed);
    // A pattern that mostly misses the mesh would never reach its target: give up after a
    // generous number of iterations and say how many points landed.
    const std::uint64_t iterationLimit = 40 * target + 50'000'000;
    while (!accumulator.waitUntilDone(0.25)) {
      const core::AccumulatorStats stats = accumulator.stats();
      if (options.progress) options.progress(stats, target);
      if (stats.iterations > iterationLimit) {
        result.warning = "only " + std::to_string(stats.points) + " of " + std::to_string(target) +
                         " points landed inside the mesh; the pattern barely overlaps it";
        break;
      }
    }
    result.stats = accumulator.stats();
    if (options.progress) options.progress(result.stats, target);
    if (!result.stats.problem.empty()) throw core::Error(result.stats.problem);
    accumulator.snapshot(snapshot);
  }
  result.accumulateSeconds = secondsSince(accumulateStart);

  const auto renderStart = std::chrono::steady_clock::now();
  gl::HeadlessContext context;
  result.renderer = context.renderer();
  gl::VolumeRenderer renderer;
  renderer.upload(snapshot);
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(scene.camera, mask->geometry.box(),
                                      static_cast<double>(options.width) / static_cast<double>(options.height));
  settings.tone = scene.tone;
  settings.stepVoxels = options.stepVoxels;
  result.image = gl::renderToImage(renderer, settings, options.width, options.height);
  result.renderSeconds = secondsSince(renderStart);
  return result;
}

core::TextChunks stillMetadata(const core::Scene& scene, const StillResult& result) {
  std::ostringstream stats;
  stats << "{\"points\":" << result.stats.points << ",\"iterations\":" << result.stats.iterations
        << ",\"accumulate_seconds\":" << result.accumulateSeconds << ",\"render_seconds\":" << result.renderSeconds
        << ",\"version\":\"" << kVersion << "\"}";
  return {{kPresetChunkKey, core::sceneToJson(scene)},
          {"voxflame:stats", stats.str()},
          {"Software", std::string("voxflame ") + kVersion}};
}

}  // namespace voxflame::app
