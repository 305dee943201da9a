#include "pipeline.h"

#include "refinement_backends.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "core/camera.h"
#include "core/refinement/accumulator.h"
#include "core/refinement/convergence.h"
#include "core/error.h"
#include "core/flame/image.h"
#include "core/point_renderer.h"
#include "core/packed_volume.h"
#include "core/shadow_volume.h"
#include "core/mask_cache.h"
#include "core/scene_io.h"
#include "gl/gpu_accumulator.h"
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
  // The mask (1 B a voxel), the accumulator, a snapshot (8 B) and its packed copy (10 B: a still
  // packs a colour per voxel).
  const double voxels = static_cast<double>(std::max<std::size_t>(grid.voxelCount(), 1));
  const double bytesPerVoxel = 1.0 + static_cast<double>(core::accumulatorBytes(grid)) / voxels + 8.0 + 10.0;
  core::checkGridFitsInMemory(grid, bytesPerVoxel);
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

namespace {

void reportAccumulation(const StillOptions& options, const core::AccumulatorStats& stats, std::uint64_t target) {
  if (options.progress) options.progress(stats, target);
  if (options.stage)
    options.stage(StillStage::Accumulating,
                  target ? static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 1.0);
}

// The volume method split into chunks (ChunkPlan): chunk by chunk into one grid, or with
// gridDone, each chunk into a cleared grid whose sums are handed over and added up.
AccumulatedVolume accumulateChunks(const core::Scene& scene, const SceneShape& shape, const StillOptions& options) {
  const ChunkPlan& plan = *options.chunks;
  AccumulatedVolume result;
  const std::uint64_t target = options.points ? options.points : scene.points;
  const int chunks = std::max(1, plan.chunks);
  std::vector<int> list;
  if (plan.render)
    list = *plan.render;
  else
    for (int chunk = 0; chunk < chunks; ++chunk) list.push_back(chunk);
  const bool perChunk = static_cast<bool>(plan.gridDone);
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<core::RefinementBackend> backend = makeBackend(options.backend, shape.mask, options.threads);
  core::RefinementBackend& accumulator = *backend;
  core::GridSums total;
  if (perChunk) {
    if (plan.earlierGrid)
      total = *plan.earlierGrid;
    else
      total.reset(shape.mask->geometry, accumulator.colourLayout());
    if (total.geometry.size != shape.mask->geometry.size || total.colour.shift != accumulator.colourLayout().shift)
      throw core::Error("the chunks rendered earlier are of another grid");
  }
  core::ConvergenceMeter meter;
  core::DensitySample sample;
  accumulator.setHeld(true);  // nothing runs until the first chunk's streams are set
  accumulator.setTargetPoints(1);
  accumulator.setDeepSeeds(true);
  accumulator.setPaletteMode(scene.flat.paletteMode);
  accumulator.setPattern(scene.layers, scene.seed);
  const std::uint64_t iterationLimit = 40 * (target / static_cast<std::uint64_t>(chunks)) + 50'000'000;
  std::uint64_t pointsDone = perChunk ? total.points : 0, iterationsDone = perChunk ? total.iterations : 0;
  const std::uint64_t reportedTarget = pointsDone + [&] {
    std::uint64_t sum = 0;
    for (int chunk : list) sum += core::chunkPoints(target, chunks, chunk);
    return sum;
  }();
  int chunksDone = 0;
  for (const int chunk : list) {
    const std::uint64_t chunkTarget = core::chunkPoints(target, chunks, chunk);
    const core::AccumulatorStats before = accumulator.stats();
    accumulator.setChunk(static_cast<std::uint64_t>(chunk), perChunk);
    accumulator.setTargetPoints(std::max<std::uint64_t>(chunkTarget, 1));
    accumulator.setHeld(false);
    const std::uint64_t pointsBefore = perChunk ? 0 : before.points;
    const std::uint64_t iterationsBefore = perChunk ? 0 : before.iterations;
    while (!accumulator.waitUntilDone(0.25)) {
      if (options.cancel && options.cancel->load()) throw RenderCancelled();
      core::AccumulatorStats stats = accumulator.stats();
      if (!stats.problem.empty()) break;
      if (stats.iterations - iterationsBefore > iterationLimit) {
        result.warning = "only " + std::to_string(stats.points - pointsBefore) + " of " + std::to_string(chunkTarget) +
                         " points of chunk " + std::to_string(chunk) +
                         " landed inside the mesh; the pattern barely overlaps it";
        break;
      }
      if (perChunk) stats.points += pointsDone;
      reportAccumulation(options, stats, reportedTarget);
    }
    accumulator.setHeld(true);
    const core::AccumulatorStats stats = accumulator.stats();
    if (!stats.problem.empty()) throw core::Error(stats.problem);
    if (!result.warning.empty()) throw core::Error(result.warning);
    ++chunksDone;
    if (perChunk) {
      core::GridSums sums = core::readGridSums(accumulator, stats);
      plan.gridDone(chunk, sums);
      pointsDone += sums.points;
      iterationsDone += sums.iterations;
      if (plan.finish) total.add(sums);
    } else if (chunksDone == std::max(1, static_cast<int>(list.size()) / 3)) {
      // The noise of the final grid is measured against a third of it, as for an unchunked still.
      accumulator.sampleDensity(sample);
      meter.update(sample);
    }
    if (plan.progress) plan.progress(chunksDone);
  }
  if (perChunk) {
    result.stats.points = pointsDone;
    result.stats.iterations = iterationsDone;
    result.stats.done = true;
    if (plan.finish) core::snapshotFromSums(total, result.snapshot);
  } else {
    result.stats = accumulator.stats();
    accumulator.sampleDensity(sample);
    result.noise = meter.update(sample);
    accumulator.snapshot(result.snapshot);
  }
  reportAccumulation(options, result.stats, reportedTarget);
  result.seconds = secondsSince(start);
  return result;
}

}  // namespace

AccumulatedVolume accumulateVolume(const core::Scene& scene, const SceneShape& shape, const StillOptions& options) {
  if (options.chunks && options.untilNoise <= 0.0 && scene.render.method != core::RenderMethod::Points)
    return accumulateChunks(scene, shape, options);
  AccumulatedVolume result;
  const bool untilNoise = options.untilNoise > 0.0;
  std::uint64_t target = options.points ? options.points : untilNoise ? kUntilNoisePointCap : scene.points;
  if (scene.render.method == core::RenderMethod::Points) target = std::min(target, kGridPointsForPointsMethod);
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<core::RefinementBackend> backend =
      makeBackend(options.backend, shape.mask, options.threads, nullptr, options.renderer);
  core::RefinementBackend& accumulator = *backend;
  core::ConvergenceMeter meter;
  core::DensitySample sample;
  auto measure = [&] {
    accumulator.sampleDensity(sample);
    return meter.update(sample);
  };
  // The target a progress report shows: with a noise target, the points it is estimated to need
  // (noise falls like 1/sqrt(points)), so the fraction and the time left mean what they say.
  std::uint64_t reported = target;
  auto report = [&](const core::AccumulatorStats& stats, double noise) {
    if (untilNoise && std::isfinite(noise) && noise > 0.0)
      reported = std::clamp(static_cast<std::uint64_t>(static_cast<double>(stats.points) *
                                                       (noise / options.untilNoise) * (noise / options.untilNoise)),
                            stats.points, target);
    reportAccumulation(options, stats, untilNoise ? reported : target);
  };
  // A point count stops a third of the way first: the sample there is what the final count's noise is
  // measured against. (A noise target without a count is measured along the way.)
  const std::uint64_t halfway = target < kUntilNoisePointCap ? target / 3 : 0;
  accumulator.setTargetPoints(halfway ? halfway : target);
  accumulator.setPaletteMode(scene.flat.paletteMode);
  accumulator.setPattern(scene.layers, scene.seed);
  // A pattern that mostly misses the mesh would never reach its target: give up after a
  // generous number of iterations and say how many points landed.
  const std::uint64_t iterationLimit = 40 * target + 50'000'000;
  bool reached = false;
  // Polls start often and slow down geometrically, like the points between two measurements: a
  // small render stops near its noise target, a large one samples a few times a second at most.
  double poll = untilNoise ? 0.02 : 0.25;
  for (bool second = false;; second = true) {
    while (!accumulator.waitUntilDone(poll)) {
      poll = std::min(0.25, 1.5 * poll);
      if (options.cancel && options.cancel->load()) throw RenderCancelled();
      const double noise = measure();
      const core::AccumulatorStats stats = accumulator.stats();
      report(stats, noise);
      if (untilNoise && !reached && noise <= options.untilNoise) {
        reached = true;
        // Reached: the streams finish the batch they are in and the workers stop.
        accumulator.setTargetPoints(std::max<std::uint64_t>(stats.points, 1));
        continue;
      }
      if (stats.iterations > iterationLimit) {
        result.warning = "only " + std::to_string(stats.points) + " of " + std::to_string(target) +
                         " points landed inside the mesh; the pattern barely overlaps it";
        break;
      }
    }
    if (reached && result.warning.empty()) {
      // The measurement once the workers have stopped is the one reported: when it is a fresh one
      // above the target (the estimate moves a little between measurements), refining goes on, so
      // the render never reports more noise than it was asked to stop at.
      result.noise = measure();
      const core::AccumulatorStats stats = accumulator.stats();
      if (std::isfinite(result.noise) && result.noise > options.untilNoise && stats.points < target) {
        reached = false;
        accumulator.setTargetPoints(target);
        continue;  // (as the second pass: the count, if one was given, is then the limit)
      }
    }
    // A noise target reached in the first third stops there: the count is only its limit.
    if (second || !halfway || reached || !result.warning.empty()) break;
    measure();
    accumulator.setTargetPoints(target);
  }
  result.stats = accumulator.stats();
  if (!reached || !result.warning.empty()) result.noise = measure();  // else measured once stopped, above
  report(result.stats, result.noise);
  if (!result.stats.problem.empty()) throw core::Error(result.stats.problem);
  if (accumulator.packsOnDevice() && scene.render.method == core::RenderMethod::Volume) {
    // The grid stays on the GPU: packed there for the renderer, which copies it there.
    result.packed.emplace();
    core::packVolume(accumulator, *result.packed);
    result.packedBy = std::move(backend);
  } else {
    accumulator.snapshot(result.snapshot);
  }
  result.seconds = secondsSince(start);
  return result;
}

struct FrameRenderer::Impl {
  gl::HeadlessContext context;
  std::string name = context.renderer();
  gl::VolumeRenderer renderer;
  const core::PackedVolume* volume = nullptr;
  const SceneShape* shape = nullptr;
  bool meshUploaded = false;
  std::uint64_t points = 0;
  int threads = 0;
  const ChunkPlan* chunks = nullptr;
  core::BackendKind pointsBackend = core::BackendKind::Cpu;
  bool keepSums = false;
};

FrameRenderer::FrameRenderer() : impl_(std::make_unique<Impl>()) {}
FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::keepSums(bool keep) {
  impl_->keepSums = keep;
}

const std::string& FrameRenderer::rendererName() const {
  return impl_->name;
}

gl::ShareGroup FrameRenderer::shareGroup() const {
  return gl::currentShareGroup();
}

void FrameRenderer::setVolume(const core::PackedVolume& volume, const SceneShape& shape) {
  impl_->renderer.upload(volume);
  impl_->volume = &volume;
  if (impl_->shape != &shape) impl_->meshUploaded = false;
  impl_->shape = &shape;
}

void FrameRenderer::setPointsPass(std::uint64_t points, int threads, const ChunkPlan* chunks,
                                  core::BackendKind backend) {
  impl_->points = points;
  impl_->threads = threads;
  impl_->chunks = chunks;
  impl_->pointsBackend = backend;
}

core::ImageRGBA FrameRenderer::render(const core::Scene& scene, int width, int height, bool linearOutput,
                                      const std::function<void(double)>& progress) {
  return renderWithStats(scene, width, height, linearOutput, progress).image;
}

FrameRenderer::Rendered FrameRenderer::renderWithStats(const core::Scene& scene, int width, int height,
                                                       bool linearOutput, const std::function<void(double)>& progress) {
  Impl& d = *impl_;
  if (!d.volume || !d.shape) throw core::Error("no volume to render");
  // The mesh is always uploaded: its silhouette measures how much of it the pattern covers.
  if (!d.meshUploaded) {
    d.renderer.setMesh(d.shape->mesh);
    d.meshUploaded = true;
  }
  if (scene.render.lighting) {
    const glm::dvec3 light = core::lightDirection(scene.render.lightAzimuthDeg, scene.render.lightElevationDeg);
    if (d.volume->onDevice()) {
      d.renderer.computeShadow(gl::VolumeRenderer::Source::Main, light, core::kAbsorptionPerDensity, kShadowDownsample);
    } else {
      core::ShadowVolume shadow;
      core::computeShadowVolume(*d.volume, light, core::kAbsorptionPerDensity, kShadowDownsample, shadow);
      d.renderer.uploadShadow(shadow, kShadowDownsample);
    }
  }
  gl::RenderSettings settings;
  settings.camera = core::orbitCamera(scene.camera, d.shape->mask->geometry.box(),
                                      static_cast<double>(width) / static_cast<double>(height));
  settings.tone = scene.tone;
  settings.render = scene.render;
  const int oversample = std::clamp(scene.render.oversample, 1, 4);
  core::DensityImage density;
  core::MeshOverlay mesh;
  std::uint64_t pointsProjected = 0;
  if (scene.render.method == core::RenderMethod::Points) {
    core::PointsPassOptions points;
    points.points = d.points;
    points.threads = d.threads;
    points.progress = progress;
    points.pointsInside = &pointsProjected;
    if (d.pointsBackend == core::BackendKind::Gpu)
      points.projectingBackend = [](std::shared_ptr<const core::InsideMask> mask,
                                    const core::PointProjection& projection,
                                    int) { return gl::makeGpuProjectingBackend(std::move(mask), projection); };
    if (d.chunks) {
      points.chunks = d.chunks->chunks;
      points.chunkList = d.chunks->render;
      if (d.chunks->imageDone) points.chunkDone = d.chunks->imageDone;
      points.earlierSums = d.chunks->earlierImage;
      points.makeImage = d.chunks->finish;
      points.chunkFinished = d.chunks->progress;
    }
    density = core::projectScenePoints(scene, d.shape->mask, *d.volume, settings.camera, width * oversample,
                                       height * oversample, points);
    if (d.chunks && !d.chunks->finish) return {};  // a farm task: its chunks' sums are all it makes
    mesh = gl::renderMeshOverlay(d.renderer, settings, width, height);
  } else {
    gl::MarchedImage marched = gl::marchImage(d.renderer, settings, width, height, gl::kDefaultMaxTile, progress);
    density = std::move(marched.density);
    mesh = std::move(marched.mesh);
  }
  core::FinishSettings finish;
  finish.tone = scene.tone;
  finish.oversample = oversample;
  finish.filterRadius = scene.render.filterRadius;
  finish.linearOutput = linearOutput;
  // Large images finish in smaller tiles (the GL's copies of a tile and its aprons are a few of
  // them), and the opacity rides in the image's fourth channel until the coverage is taken: a 16K
  // print holds neither a separate opacity plane nor 2048² tiles.
  const bool large = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > std::size_t{64} << 20;
  core::FinishedImage finished =
      gl::finishImageOnGpu(d.renderer.finisher(), density, finish, &mesh, large ? 1024 : gl::kDefaultMaxTile, true);
  Rendered result;
  if (d.keepSums) {
    result.density = std::move(density);
    result.mesh = mesh;
  }
  std::vector<float>().swap(density.values);  // a 16K print's sums go before its PNG is made
  result.coverage = core::takeSilhouetteCoverage(finished.image, mesh);
  result.pointsProjected = pointsProjected;
  result.image = std::move(finished.image);
  return result;
}

StillResult renderStill(const core::Scene& scene, const StillOptions& options) {
  StillResult result;
  result.backend = options.backend;
  if (options.stage) options.stage(StillStage::Loading, 0.0);
  const SceneShape shape = buildSceneShape(scene);
  core::PackedVolume volume;
  // Under the GPU backend the renderer comes first, so the backend can share its context and
  // leave the grid on the GPU (a chunked render reads its grids back, chunk by chunk).
  std::optional<FrameRenderer> renderer;
  StillOptions accumulation = options;
  // The points method reads the grid on the host (its camera's and light's transmittance).
  if (options.backend == core::BackendKind::Gpu && !options.chunks &&
      scene.render.method != core::RenderMethod::Points) {
    renderer.emplace();
    accumulation.renderer = renderer->shareGroup();
  }
  {
    AccumulatedVolume accumulated = accumulateVolume(scene, shape, accumulation);
    result.stats = accumulated.stats;
    result.warning = accumulated.warning;
    result.accumulateSeconds = accumulated.seconds;
    result.noise = accumulated.noise;
    // A farm task's chunks of the volume method are all it renders.
    if (options.chunks && !options.chunks->finish && scene.render.method != core::RenderMethod::Points) return result;
    if (accumulated.packed) {
      result.gridOnDevice = true;
      volume = std::move(*accumulated.packed);
      // Copied while the backend that packed it still holds its textures.
      renderer->setVolume(volume, shape);
    } else {
      core::packVolume(accumulated.snapshot, volume);
    }
  }
  if (options.cancel && options.cancel->load()) throw RenderCancelled();
  const auto renderStart = std::chrono::steady_clock::now();
  if (!renderer) renderer.emplace();
  result.renderer = renderer->rendererName();
  if (!volume.onDevice()) renderer->setVolume(volume, shape);
  renderer->setPointsPass(options.points, options.threads, options.chunks ? &*options.chunks : nullptr,
                          options.backend);
  // Between sub-samples a cancelled render stops and a progress bar moves.
  std::function<void(double)> renderProgress;
  if (options.cancel || options.stage)
    renderProgress = [&options](double fraction) {
      if (options.cancel && options.cancel->load()) throw RenderCancelled();
      if (options.stage) options.stage(StillStage::Rendering, fraction);
    };
  if (options.stage) options.stage(StillStage::Rendering, 0.0);
  FrameRenderer::Rendered rendered =
      renderer->renderWithStats(scene, options.width, options.height, options.linearOutput, renderProgress);
  result.image = std::move(rendered.image);
  result.coverage = rendered.coverage;
  result.pointsProjected = rendered.pointsProjected;
  result.renderSeconds = secondsSince(renderStart);
  return result;
}

core::TextChunks stillMetadata(const core::Scene& scene, const StillResult& result, bool withTimes) {
  std::ostringstream stats;
  stats << "{\"points\":" << result.stats.points << ",\"iterations\":" << result.stats.iterations;
  if (withTimes)
    stats << ",\"accumulate_seconds\":" << result.accumulateSeconds << ",\"render_seconds\":" << result.renderSeconds;
  // Like the times, the noise depends on when it was measured: a frame that must be the same file
  // on any machine leaves it out.
  if (withTimes && std::isfinite(result.noise)) stats << ",\"noise\":" << result.noise;
  stats << ",\"method\":\"" << core::toString(scene.render.method) << "\",\"coverage\":" << result.coverage
        << ",\"points_projected\":" << result.pointsProjected << ",\"version\":\"" << kVersion << "\"}";
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

namespace voxflame::app {

core::Scene sceneWithMesh(core::Scene scene, const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw core::Error(path.string() + ": no such file");
  scene.meshPath = std::filesystem::absolute(path).lexically_normal().string();
  scene.baseDirectory.clear();
  scene.embedded = false;
  return scene;
}

core::Scene sceneFromFile(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension == ".json") return core::loadScene(path);
  if (extension == ".png") return sceneFromImage(path);
  if (core::isFlameFilePath(path)) {
    // The first flame of the file in the default mesh; the warnings go where a command line sees them.
    core::Scene scene;
    const core::FlameFileContents contents = importFlameScene(path, importBaseScene(), {}, scene);
    for (const std::string& warning : contents.flame.warnings)
      std::cerr << "voxflame: warning: " << path.string() << ": " << warning << "\n";
    return scene;
  }
  core::Scene scene = sceneWithMesh(core::defaultScene(), path);
  scene.name = path.stem().string();
  return scene;
}

}  // namespace voxflame::app
