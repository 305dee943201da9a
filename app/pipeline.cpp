#include "pipeline.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "core/camera.h"
#include "core/error.h"
#include "core/packed_volume.h"
#include "core/shadow_volume.h"
#include "core/mask_cache.h"
#include "core/scene_io.h"
#include "gl/headless_context.h"
#include "gl/volume_renderer.h"
#include "version.h"

namespace voxflame::app {

namespace {

// Shadows are smooth: a cell of 2³ voxels keeps them sharp enough at an eighth of the work.
constexpr int kShadowDownsample = 2;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

const char* toString(StillStage stage) {
  switch (stage) {
    case StillStage::Loading:
      return "loading";
    case StillStage::Accumulating:
      return "accumulating";
    case StillStage::Rendering:
      return "rendering";
  }
  return "loading";
}

void checkGridFitsInMemory(const core::GridGeometry& grid) {
  // Per voxel: mask 1 B, density and colour sums 16 B, a snapshot 8 B, its upload copy 8 B.
  constexpr double kBytesPerVoxel = 1.0 + 16.0 + 8.0 + 8.0;
  core::checkGridFitsInMemory(grid, kBytesPerVoxel);
}

SceneShape buildSceneShape(const core::Scene& scene) {
  SceneShape shape;
  shape.mesh = core::loadSceneMesh(scene);
  const core::GridGeometry grid = core::gridOverBox(shape.mesh.bounds(), scene.gridResolution);
  checkGridFitsInMemory(grid);
  // Reopening a preset finds its mask in the user's cache instead of computing it again.
  shape.mask = std::make_shared<const core::InsideMask>(
      core::cachedInsideMask(shape.mesh, grid, core::MaskMethod::WindingNumber, core::defaultMaskCacheFolder()));
  return shape;
}

StillResult renderStill(const core::Scene& scene, const StillOptions& options) {
  StillResult result;
  if (options.stage) options.stage(StillStage::Loading, 0.0);
  const SceneShape shape = buildSceneShape(scene);
  const auto& mask = shape.mask;
  const std::uint64_t target = options.points ? options.points : scene.points;
  const auto reportAccumulation = [&](const core::AccumulatorStats& stats) {
    if (options.progress) options.progress(stats, target);
    if (options.stage)
      options.stage(StillStage::Accumulating,
                    target ? static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 1.0);
  };

  const auto accumulateStart = std::chrono::steady_clock::now();
  core::PackedVolume volume;
  {
    core::Accumulator accumulator(mask, options.threads);
    accumulator.setTargetPoints(target);
    accumulator.setPattern(scene.layers, scene.seed);
    // A pattern that mostly misses the mesh would never reach its target: give up after a
    // generous number of iterations and say how many points landed.
    const std::uint64_t iterationLimit = 40 * target + 50'000'000;
    while (!accumulator.waitUntilDone(0.25)) {
      if (options.cancel && options.cancel->load()) throw RenderCancelled();
      const core::AccumulatorStats stats = accumulator.stats();
      reportAccumulation(stats);
      if (stats.iterations > iterationLimit) {
        result.warning = "only " + std::to_string(stats.points) + " of " + std::to_string(target) +
                         " points landed inside the mesh; the pattern barely overlaps it";
        break;
      }
    }
    result.stats = accumulator.stats();
    reportAccumulation(result.stats);
    if (!result.stats.problem.empty()) throw core::Error(result.stats.problem);
    core::VolumeSnapshot snapshot;
    accumulator.snapshot(snapshot);
    core::packVolume(snapshot, volume);
  }
  result.accumulateSeconds = secondsSince(accumulateStart);

  if (options.cancel && options.cancel->load()) throw RenderCancelled();
  const auto renderStart = std::chrono::steady_clock::now();
  gl::HeadlessContext context;
  result.renderer = context.renderer();
  gl::VolumeRenderer renderer;
  renderer.upload(volume);
  if (scene.render.meshDisplay != core::MeshDisplay::Off) renderer.setMesh(shape.mesh);
  if (scene.render.lighting) {
    core::ShadowVolume shadow;
    core::computeShadowVolume(volume,
                              core::lightDirection(scene.render.lightAzimuthDeg, scene.render.lightElevationDeg),
                              scene.tone.brightness, kShadowDownsample, shadow);
    renderer.uploadShadow(shadow, kShadowDownsample);
  }
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(scene.camera, mask->geometry.box(),
                                      static_cast<double>(options.width) / static_cast<double>(options.height));
  settings.tone = scene.tone;
  settings.render = scene.render;
  // Between sub-samples a cancelled render stops and a progress bar moves.
  std::function<void(double)> renderProgress;
  if (options.cancel || options.stage)
    renderProgress = [&options](double fraction) {
      if (options.cancel && options.cancel->load()) throw RenderCancelled();
      if (options.stage) options.stage(StillStage::Rendering, fraction);
    };
  if (options.stage) options.stage(StillStage::Rendering, 0.0);
  result.image = gl::renderToImage(renderer, settings, options.width, options.height, options.linearOutput,
                                   gl::kDefaultMaxTile, renderProgress);
  result.renderSeconds = secondsSince(renderStart);
  return result;
}

core::TextChunks stillMetadata(const core::Scene& scene, const StillResult& result) {
  std::ostringstream stats;
  stats << "{\"points\":" << result.stats.points << ",\"iterations\":" << result.stats.iterations
        << ",\"accumulate_seconds\":" << result.accumulateSeconds << ",\"render_seconds\":" << result.renderSeconds
        << ",\"version\":\"" << kVersion << "\"}";
  // A preset inside an image must find its mesh from wherever the image goes.
  core::Scene stored = scene;
  if (!stored.embedded)
    stored.meshPath = std::filesystem::absolute(scene.resolvedMeshPath()).lexically_normal().string();
  return {{kPresetChunkKey, core::sceneToJson(stored)},
          {"voxflame:stats", stats.str()},
          {"Software", std::string("voxflame ") + kVersion}};
}

core::Scene sceneFromImage(const std::filesystem::path& path) {
  const core::PngInfo png = core::readPng(path);
  const auto preset = png.text.find(kPresetChunkKey);
  if (preset == png.text.end())
    throw core::Error("image '" + path.string() + "' carries no voxflame preset (no \"" + kPresetChunkKey +
                      "\" chunk)");
  core::Scene scene = core::sceneFromJson(preset->second, path.string());
  if (!scene.embedded) scene.baseDirectory = path.parent_path();
  return scene;
}

}  // namespace voxflame::app
