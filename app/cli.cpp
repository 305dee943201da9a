#include "cli.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "arguments.h"
#include "commands.h"
#include "core/error.h"
#include "core/keyframes.h"
#include "core/scene_io.h"
#include "core/volume_export.h"
#include "explorer.h"
#include "pipeline.h"
#include "progress_pipe.h"
#include "version.h"

namespace voxflame::app {

namespace {

constexpr const char* kUsage = R"(voxflame — strange attractors filling the volume of a mesh

usage:
  voxflame [PRESET.json | IMAGE.png | FILE.flame | MESH] [--screenshot FILE --frames N] [--ui-scale S]
      Open the explorer on a preset (the built-in default when none is given), on the preset
      stored in a PNG rendered by voxflame, on an imported flame, or on a mesh filled with the
      default pattern.
  voxflame render [PRESET.json|IMAGE.png] -o OUT.png|OUT.exr|OUT.vdb|OUT.nrrd [--width W] [--height H]
                  [--samples S] [--points N] [--grid R] [--bit-depth 8|16] [--time SECONDS]
                  [--camera-azimuth DEG] [--camera-elevation DEG] [--threads T]
                  [--progress-fd N] [--method volume|points] [--oversample 1-4] [--stats]
      Render a still headless (no display needed). A PNG carries its preset: rendering
      it again reproduces it. EXR is linear 32-bit float. VDB and NRRD hold the volume
      itself (normalised density and colour, in the mesh's coordinates) for other renderers. --progress-fd N writes lines
      "progress STAGE FRACTION" to file descriptor N for a parent process.
  voxflame animate [PRESET.json|FRAME.png] -o PATTERN [--frames A-B] [--width W] [--height H]
                   [--fps F] [--motion-blur N] [--shutter S] [--video OUT.mp4]
                   [--samples S] [--points N] [--grid R] [--threads T]
      Render the preset's keyframed animation to PNG frames named by a printf pattern
      (frames/%04d.png); --frames renders part of it (frames split across machines agree).
      --video encodes the frames with ffmpeg when it is installed.
  voxflame animate [PRESET.json|FRAME.png] -o PATTERN --farm slurm [--tasks N] [--partition P]
                   [--submit] [--frames A-B] [--video OUT.mp4] [the options above]
      Write a Slurm array job beside the frames (farm-render.sbatch: N tasks, each rendering one
      contiguous range) and a job that checks every frame and makes the video when they have
      ended (farm-finish.sbatch); --submit submits both with sbatch.
  voxflame animate [PRESET.json] --status PATTERN [--frames A-B] [--fps F]
      List the frames still missing (exit status 1 when any is) and the farm tasks that
      render them.
  voxflame list [--json]
      The attractor catalogue: ids, kinds, parameters with defaults.
  voxflame list --variations [--json | --markdown]
      The flame variation catalogue: names, 2D/3D, parameters with defaults, formulas
      (--markdown writes presets/VARIATIONS.md).
  voxflame info [PRESET.json] [--attractor ID] [--set NAME] [--param NAME=VALUE]...
                [--integrator euler|rk4] [--step H] [--json]
      Boundedness, Lyapunov exponents (largest first) and dimension of one parameter set;
      for a flame or quaternion Julia preset, how well it fills its box.
  voxflame search [PRESET.json | --attractor ID] [--seed N] [--count K] [--strength S]
                  [--set NAME] [--param NAME=VALUE]... [--json]
      Find K nearby parameter sets that are bounded, chaotic and fill a volume.
      On a flame or quaternion Julia preset: K mutations of it that fill their box
      (--random: new random ones), best first; -o OUT.json writes the best as a preset.
  voxflame mask MESH -o OUT.nrrd [--grid N] [--stats]
                [--method winding-number|exact-winding-number|parity]
      Write the mesh's inside mask (N voxels along its longest axis, 32-1024, default 256)
      as an NRRD volume in the mesh's own coordinates.
  voxflame import FILE.flame|FILE.flam3 -o PRESET.json [--mesh MESH] [--depth D]
                  [--index N | --name NAME]
      Turn a flame from flam3, Apophysis, Fractorium or JWildfire into a preset: transforms,
      variations voxflame knows (others are named in a warning), final transform, symmetry,
      palette and tone. A flat flame gains depth D (default 0.5, 0 keeps it flat); --mesh
      fills another mesh (default builtin:meshes/bunny.obj); --index (from 1) or --name picks
      one flame of a file that holds several (default the first).
  voxflame bench [accumulate|mask|raymarch|explorer|export|quality|flame] [--method volume|points] [--json]
      Measure performance (Release build).
  voxflame --help | --version
)";

}  // namespace

core::Scene sceneFromArgument(const std::vector<std::string>& positional) {
  if (positional.empty()) return core::defaultScene();
  return sceneFromFile(positional.front());
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

}  // namespace

int renderCommand(const std::vector<std::string>& args) {
  Arguments arguments(args, 2, {"--stats"});
  const auto output = arguments.take("-o", "--output");
  StillOptions options;
  options.width = static_cast<int>(arguments.integer("--width", 1280, 1, 65536));
  options.height = static_cast<int>(arguments.integer("--height", 720, 1, 65536));
  options.points = static_cast<std::uint64_t>(arguments.integer("--points", 0, 0, 1LL << 40));
  options.threads = static_cast<int>(arguments.integer("--threads", 0, 0, 1024));
  const auto samples = arguments.take("--samples");
  const int sampleCount = static_cast<int>(arguments.integer("--samples", 0, 1, 1024));
  const auto grid = arguments.take("--grid");
  const int gridResolution = static_cast<int>(arguments.integer("--grid", 0, 16, 1024));
  const auto azimuth = arguments.take("--camera-azimuth");
  const double azimuthDeg = arguments.real("--camera-azimuth", 0.0, -3600.0, 3600.0);
  const auto elevation = arguments.take("--camera-elevation");
  const double elevationDeg = arguments.real("--camera-elevation", 0.0, -360.0, 360.0);
  const auto time = arguments.take("--time");
  const double seconds = arguments.real("--time", 0.0, 0.0, core::kMaxAnimationSeconds);
  const int bitDepth = static_cast<int>(arguments.integer("--bit-depth", 8, 8, 16));
  if (bitDepth != 8 && bitDepth != 16) throw UsageError("--bit-depth must be 8 or 16");
  const int progressFd = static_cast<int>(arguments.integer("--progress-fd", -1, 0, 1 << 20));
  checkProgressFd(progressFd);
  const auto method = arguments.take("--method");
  if (method && *method != "volume" && *method != "points")
    throw UsageError("--method must be 'volume' or 'points', not '" + *method + "'");
  const auto oversample = arguments.take("--oversample");
  const int oversampleValue = static_cast<int>(arguments.integer("--oversample", 1, 1, 4));
  const bool printStats = arguments.flag("--stats");
  arguments.finish(1);
  if (!output) throw UsageError("render needs an output file: -o OUT.png, OUT.exr, OUT.vdb or OUT.nrrd");
  const std::string extension = std::filesystem::path(*output).extension().string();
  const bool volumeOutput = extension == ".vdb" || extension == ".nrrd";
  if (extension != ".png" && extension != ".exr" && !volumeOutput)
    throw UsageError("output '" + *output + "' must end in .png or .exr (an image) or .vdb or .nrrd (the volume)");
  if (static_cast<double>(options.width) * options.height > 1.5e9)
    throw core::Error("an image of " + std::to_string(options.width) + "×" + std::to_string(options.height) +
                      " pixels is too large to hold in memory");

  // Command-line settings go into the scene, so the preset stored in the image reproduces it.
  core::Scene scene = sceneFromArgument(arguments.positional());
  // An animated preset renders the moment it names (a rendered frame stores its own time).
  scene = core::sceneAtTime(scene, time ? seconds : scene.animation.time);
  if (options.points) scene.points = options.points;
  if (samples) scene.render.samples = sampleCount;
  if (grid) scene.gridResolution = gridResolution;
  if (azimuth) scene.camera.azimuthDeg = azimuthDeg;
  if (elevation) scene.camera.elevationDeg = elevationDeg;
  if (method) scene.render.method = *method == "points" ? core::RenderMethod::Points : core::RenderMethod::Volume;
  if (oversample) scene.render.oversample = oversampleValue;
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
  ProgressPipe progressPipe(progressFd, gInterrupted);
  if (progressPipe.active())
    options.stage = [&progressPipe](StillStage stage, double fraction) {
      progressPipe.report(toString(stage), fraction);
    };
  if (volumeOutput) return writeVolume(scene, options, *output, extension == ".vdb", interactive);
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
  progressPipe.report("writing", 0.0);
  if (gInterrupted) {
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (options.linearOutput)
    core::writeExr(*output, result.image, stillMetadata(scene, result));
  else
    core::writePng(*output, result.image, bitDepth, stillMetadata(scene, result));
  // The points method's own count is what the image shows; its grid (for depth) took fewer.
  const std::uint64_t shown = result.pointsProjected ? result.pointsProjected : result.stats.points;
  std::printf(
      "wrote %s (%d×%d, %s method, %d samples, %llu points inside, pattern covers %.0f%% of the mesh, %.2f s "
      "accumulating, %.2f s rendering on %s)\n",
      output->c_str(), options.width, options.height, std::string(core::toString(scene.render.method)).c_str(),
      scene.render.samples, static_cast<unsigned long long>(shown), 100.0 * result.coverage, result.accumulateSeconds,
      result.renderSeconds, result.renderer.c_str());
  if (printStats) std::printf("stats %s\n", stillMetadata(scene, result).at("voxflame:stats").c_str());
  // The image is complete on disk: an interruption that came too late to stop it is not a failure.
  return 0;
}

namespace {

int explorerCommand(const std::vector<std::string>& args) {
  Arguments arguments(args, 1);
  ExplorerOptions options;
  if (const auto screenshot = arguments.take("--screenshot")) options.screenshotPath = *screenshot;
  options.frames = static_cast<int>(arguments.integer("--frames", 0, 0, 1'000'000));
  options.uiScale = static_cast<float>(arguments.real("--ui-scale", 0.0, 0.5, 4.0));
  options.width = static_cast<int>(arguments.integer("--width", 0, 320, 16384));
  options.height = static_cast<int>(arguments.integer("--height", 0, 240, 16384));
  arguments.finish(1);
  if (!options.screenshotPath.empty() && options.frames == 0) options.frames = 60;
  return runExplorer(sceneFromArgument(arguments.positional()), options);
}

}  // namespace

int runCommandLine(const std::vector<std::string>& args) {
  try {
    const std::string command = args.size() > 1 ? args[1] : "";
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (command == "--version") {
      std::cout << "voxflame " << kVersion << "\n";
      return 0;
    }
    for (const Subcommand& subcommand : subcommands())
      if (command == subcommand.name) return subcommand.run(args);
    return explorerCommand(args);
  } catch (const UsageError& e) {
    std::cerr << "voxflame: " << e.what() << "\n\n" << kUsage;
    return 2;
  } catch (const core::Error& e) {
    std::cerr << "voxflame: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "voxflame: out of memory; try a smaller grid or image\n";
    return 1;
  }
}

}  // namespace voxflame::app

namespace voxflame::app {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"render", &renderCommand}, {"animate", &animateCommand}, {"bench", &benchCommand}, {"list", &listCommand},
      {"info", &infoCommand},     {"search", &searchCommand},   {"mask", &maskCommand},   {"import", &importCommand},
  };
  return table;
}

}  // namespace voxflame::app
