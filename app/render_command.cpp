// `voxflame render`: a still, headless, to PNG or EXR, or the accumulated volume to VDB or NRRD;
// and the helpers the subcommands share (their file argument, Ctrl-C, durations).
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "commands.h"
#include "core/error.h"
#include "core/flat_render.h"
#include "core/image_io.h"
#include "core/keyframes.h"
#include "core/scene_io.h"
#include "core/volume_export.h"
#include "pipeline.h"
#include "progress_pipe.h"
#include "usage_error.h"

namespace voxflame::app {

core::Scene sceneFromArgument(const std::optional<std::string>& file) {
  return file ? sceneFromFile(*file) : core::defaultScene();
}

namespace {

std::atomic<bool> gInterrupted{false};
extern "C" void onInterrupt(int) {
  gInterrupted.store(true);
}

}  // namespace

const std::atomic<bool>& catchInterrupts() {
  gInterrupted = false;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return gInterrupted;
}

std::string formatDuration(double seconds) {
  char text[32];
  if (seconds >= 3600.0)
    std::snprintf(text, sizeof text, "%dh%02dm", static_cast<int>(seconds / 3600.0),
                  static_cast<int>(seconds / 60.0) % 60);
  else if (seconds >= 60.0)
    std::snprintf(text, sizeof text, "%dm%02ds", static_cast<int>(seconds / 60.0), static_cast<int>(seconds) % 60);
  else
    std::snprintf(text, sizeof text, "%.0fs", seconds);
  return text;
}

namespace {

// `render -o OUT.vdb|OUT.nrrd`: accumulates as for a still and writes the grid instead of an image.
int writeVolume(const core::Scene& scene, const StillOptions& options, const std::string& output, bool vdb,
                bool interactive) {
  AccumulatedVolume volume;
  try {
    const SceneShape shape = buildSceneShape(scene);
    volume = accumulateVolume(scene, shape, options);
  } catch (const RenderCancelled&) {
    if (interactive) std::fprintf(stderr, "\n");
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (interactive) std::fprintf(stderr, "\n");
  if (!volume.warning.empty()) std::cerr << "voxflame: warning: " << volume.warning << "\n";
  StillResult stats;
  stats.stats = volume.stats;
  const std::string preset = stillMetadata(scene, stats).at(kPresetChunkKey);
  const auto start = std::chrono::steady_clock::now();
  if (vdb)
    core::writeVdbVolume(output, volume.snapshot, preset);
  else
    core::writeNrrdVolume(output, volume.snapshot, preset);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t active = 0;
  for (float hits : volume.snapshot.density) active += hits > 0.0f;
  const glm::ivec3 size = volume.snapshot.geometry.size;
  std::printf("wrote %s (%d×%d×%d voxels, %zu with density, %llu points inside, %.2f s accumulating, %.2f s writing)\n",
              output.c_str(), size.x, size.y, size.z, active, static_cast<unsigned long long>(volume.stats.points),
              volume.seconds, seconds);
  return 0;
}

// `render --flat`: the flame layer in 2D, framed as flam3 frames it (core/flat_render.h).
int renderFlatCommand(const RenderArguments& arguments, const std::string& output) {
  if (std::filesystem::path(output).extension() != ".png")
    throw UsageError("render --flat writes a PNG: -o OUT.png, not '" + output + "'");
  if (arguments.method || arguments.samples || arguments.grid || arguments.points || arguments.untilNoisePercent ||
      arguments.oversample || arguments.cameraAzimuthDeg || arguments.cameraElevationDeg)
    throw UsageError(
        "render --flat has no mesh, camera or grid: leave out --method, --samples, --points, --grid, --until-noise, "
        "--oversample and the camera options");
  core::Scene scene = sceneFromArgument(arguments.preset);
  scene = core::sceneAtTime(scene, arguments.time.value_or(scene.animation.time));
  core::FlatRenderOptions options;
  options.width = arguments.widthGiven ? arguments.width : 0;
  options.height = arguments.heightGiven ? arguments.height : 0;
  options.quality = arguments.quality;
  options.seed = arguments.seed;
  options.bitDepth = arguments.bitDepth;
  options.cancel = &catchInterrupts();
  const auto start = std::chrono::steady_clock::now();
  core::FlatRenderResult result;
  try {
    result = core::renderFlat(scene, options);
  } catch (const core::FlatRenderCancelled&) {
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  core::writePng(output, result.image, arguments.bitDepth, {{kPresetChunkKey, core::sceneToJson(scene)}});
  std::printf("wrote %s (%d×%d, flat, quality %g, %llu samples, %.2f s)\n", output.c_str(), result.image.width,
              result.image.height, result.quality, static_cast<unsigned long long>(result.samples), seconds);
  return 0;
}

}  // namespace

int renderCommand(const RenderArguments& arguments) {
  checkProgressFd(arguments.progressFd);
  if (!arguments.output) throw UsageError("render needs an output file: -o OUT.png, OUT.exr, OUT.vdb or OUT.nrrd");
  if (arguments.flat) return renderFlatCommand(arguments, *arguments.output);
  if (arguments.quality) throw UsageError("--quality is an option of render --flat");
  const std::string& output = *arguments.output;
  const std::string extension = std::filesystem::path(output).extension().string();
  const bool volumeOutput = extension == ".vdb" || extension == ".nrrd";
  if (extension != ".png" && extension != ".exr" && !volumeOutput)
    throw UsageError("output '" + output + "' must end in .png or .exr (an image) or .vdb or .nrrd (the volume)");
  StillOptions options;
  options.width = arguments.width;
  options.height = arguments.height;
  options.points = arguments.points;
  options.threads = arguments.threads;
  if (static_cast<double>(options.width) * options.height > 1.5e9)
    throw core::Error("an image of " + std::to_string(options.width) + "×" + std::to_string(options.height) +
                      " pixels is too large to hold in memory");

  // Command-line settings go into the scene, so the preset stored in the image reproduces it.
  core::Scene scene = sceneFromArgument(arguments.preset);
  // An animated preset renders the moment it names (a rendered frame stores its own time).
  scene = core::sceneAtTime(scene, arguments.time.value_or(scene.animation.time));
  if (options.points) scene.points = options.points;
  if (arguments.untilNoisePercent) options.untilNoise = 0.01 * *arguments.untilNoisePercent;
  if (arguments.samples) scene.render.samples = *arguments.samples;
  if (arguments.grid) scene.gridResolution = *arguments.grid;
  if (arguments.cameraAzimuthDeg) scene.camera.azimuthDeg = *arguments.cameraAzimuthDeg;
  if (arguments.cameraElevationDeg) scene.camera.elevationDeg = *arguments.cameraElevationDeg;
  if (arguments.method) scene.render.method = *arguments.method;
  if (arguments.oversample) scene.render.oversample = *arguments.oversample;
  if (options.untilNoise > 0.0 && scene.render.method == core::RenderMethod::Points)
    throw UsageError("--until-noise measures the voxel grid, which the points method does not show: use --points");
  options.linearOutput = extension == ".exr";
  // Render exactly what the image will store: values pass through their JSON form first (colours
  // become hex), so rendering the image's preset again gives the same pixels.
  const bool embedded = scene.embedded;
  const std::filesystem::path baseDirectory = scene.baseDirectory;
  scene = core::sceneFromJson(core::sceneToJson(scene), "(command line)");
  scene.embedded = embedded;
  scene.baseDirectory = baseDirectory;

  options.cancel = &catchInterrupts();
  const bool interactive = isatty(fileno(stderr));
  options.progress = [interactive](const core::AccumulatorStats& stats, std::uint64_t target) {
    if (!interactive) return;
    const double done =
        target ? static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 0.0;
    const double insideRate = stats.pointsPerSecond * stats.insideFraction();
    const double left =
        insideRate > 0.0 ? static_cast<double>(target - std::min(stats.points, target)) / insideRate : 0.0;
    std::fprintf(stderr, "\raccumulating %5.1f%%  %6.1f M points/s  %s left   ", 100.0 * done,
                 stats.pointsPerSecond * 1e-6, formatDuration(left).c_str());
    std::fflush(stderr);
  };
  ProgressPipe progressPipe(arguments.progressFd, gInterrupted);
  if (progressPipe.active())
    options.stage = [&progressPipe](StillStage stage, double fraction) {
      progressPipe.report(toString(stage), fraction);
    };
  if (volumeOutput) return writeVolume(scene, options, output, extension == ".vdb", interactive);
  StillResult result;
  try {
    result = renderStill(scene, options);
  } catch (const RenderCancelled&) {
    if (interactive) std::fprintf(stderr, "\n");
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (interactive) std::fprintf(stderr, "\n");
  if (!result.warning.empty()) std::cerr << "voxflame: warning: " << result.warning << "\n";
  // The stored preset reproduces the image with the count the noise target came to.
  if (options.untilNoise > 0.0) scene.points = std::max<std::uint64_t>(result.stats.points, 1);
  progressPipe.report("writing", 0.0);
  if (gInterrupted) {
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (options.linearOutput)
    core::writeExr(output, result.image, stillMetadata(scene, result));
  else
    core::writePng(output, result.image, arguments.bitDepth, stillMetadata(scene, result));
  // The points method's own count is what the image shows; its grid (for depth) took fewer.
  const std::uint64_t shown = result.pointsProjected ? result.pointsProjected : result.stats.points;
  std::printf(
      "wrote %s (%d×%d, %s method, %d samples, %llu points inside, pattern covers %.0f%% of the mesh, %.2f s "
      "accumulating, %.2f s rendering on %s)\n",
      output.c_str(), options.width, options.height, std::string(core::toString(scene.render.method)).c_str(),
      scene.render.samples, static_cast<unsigned long long>(shown), 100.0 * result.coverage, result.accumulateSeconds,
      result.renderSeconds, result.renderer.c_str());
  if (arguments.stats) std::printf("stats %s\n", stillMetadata(scene, result).at("voxflame:stats").c_str());
  // The image is complete on disk: an interruption that came too late to stop it is not a failure.
  return 0;
}

}  // namespace voxflame::app
