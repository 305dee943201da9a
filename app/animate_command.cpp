// `voxflame animate`: renders a preset's keyframed animation to numbered PNG frames, optionally
// encoded to a video by ffmpeg, or writes each frame's accumulated volume (.vdb or .nrrd frames).
//
// Temporal stability comes from two choices. The fit of every layer into the mesh is locked to
// the one of time 0 — of the whole animation, not of the rendered range — so a parameter change
// never moves or resizes the pattern and machines rendering different ranges agree. And every
// frame uses the preset's own seed rather than one derived from the frame number: the orbits start
// from the same points with the same random numbers, so wherever the pattern does not change
// (a camera move, a tone fade, a still stretch between keys) consecutive volumes are identical,
// bit for bit, instead of showing fresh Monte Carlo noise on every frame; where parameters move,
// the noise follows the pattern instead of flickering on its own.
//
// The same two choices let a render farm split the frames (farm_job.h): `--farm slurm` writes the
// job scripts instead of rendering, and `--status PATTERN` lists the frames still missing.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "core/error.h"
#include "core/scene_schema.h"
#include "core/keyframes.h"
#include "core/packed_volume.h"
#include "core/volume_export.h"
#include "farm_job.h"
#include "frame_pattern.h"
#include "pipeline.h"
#include "programs.h"
#include "usage_error.h"

namespace voxflame::app {

namespace {

// Exit status when the frames were written but the asked-for video could not be (no ffmpeg), or
// the farm's job scripts were written but could not be submitted (no sbatch).
constexpr int kNoVideoStatus = 3;

// Replaces each layer's automatic fit by the one of the scene at time 0, so that every frame, on
// every machine, places the pattern the same way.
void lockFits(core::Scene& scene) {
  const core::Scene first = core::sceneAtTime(scene, 0.0);
  const SceneShape shape = buildSceneShape(first);
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    core::LayerTransform& transform = scene.layers[i].transform;
    if (transform.lockFit) continue;
    if (transform.fit == core::FitMode::Previous && i > 0) {
      // Locked with the layer before, so the layers stay in register in every frame.
      const core::LayerTransform& previous = scene.layers[i - 1].transform;
      transform.lockFit = true;
      transform.lockedCenter = previous.lockedCenter;
      transform.lockedScale = previous.lockedScale;
      transform.lockedAxisScale = previous.lockedAxisScale;
      continue;
    }
    const core::PreparedLayer prepared = core::prepareLayer(first.layers[i], *shape.mask, first.seed);
    transform.lockFit = true;
    transform.lockedCenter = prepared.automaticFit.center;
    transform.lockedScale = prepared.automaticFit.scale;
    transform.lockedAxisScale = prepared.automaticFit.axisScale;
  }
}

// What decides the accumulated volume (mesh, grid, layers, seed, points): when a frame's differs
// from the last accumulated one's, accumulate again.
bool needsNewVolume(const std::optional<core::Scene>& accumulated, const core::Scene& moment) {
  if (!accumulated) return true;
  const core::SceneDiff change = core::diff(*accumulated, moment);
  return change.pattern() || change.touches("/points");
}

std::vector<std::string> ffmpegArguments(const std::string& pattern, const FrameRange& range, double fps,
                                         const std::string& video) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  return {"ffmpeg",
          "-y",
          "-loglevel",
          "error",
          "-framerate",
          rate,
          "-start_number",
          std::to_string(range.first),
          "-i",
          pattern,
          "-frames:v",
          std::to_string(range.last - range.first + 1),
          "-vf",
          "pad=ceil(iw/2)*2:ceil(ih/2)*2",  // yuv420p needs even sizes
          "-c:v",
          "libx264",
          "-pix_fmt",
          "yuv420p",
          "-r",
          rate,
          video};
}

// `--status PATTERN`: which frames of the range exist. The range comes from --frames, else the
// preset's whole animation, else the farm job's record beside the frames.
int frameStatus(const std::string& pattern, const std::optional<std::string>& frames,
                const std::optional<std::string>& preset, const std::optional<double>& fps) {
  checkFramePattern(pattern);
  const std::filesystem::path renderScript = frameFolder(pattern, 0) / "farm-render.sbatch";
  const std::optional<FarmRecord> record = readFarmRecord(renderScript);
  FrameRange range;
  if (preset) {
    core::Scene scene = sceneFromArgument(preset);
    const double rate = fps ? *fps : core::animationFps(scene);
    const int frameCount = core::animationFrameCount(scene, rate);
    range = frames ? parseFrameRange(*frames, frameCount, rate) : FrameRange{0, frameCount - 1};
  } else if (frames) {
    range = parseFrameRange(*frames, std::numeric_limits<int>::max(), 0.0);
  } else if (record) {
    range = record->frames;
  } else {
    throw UsageError(
        "--status needs to know which frames to expect: name the preset (voxflame animate PRESET "
        "--status " +
        pattern + ") or give --frames A-B");
  }
  std::vector<int> missing;
  for (int frame = range.first; frame <= range.last; ++frame)
    if (!frameExists(pattern, frame)) missing.push_back(frame);
  const std::string frameList = std::to_string(range.first) + "-" + std::to_string(range.last);
  if (missing.empty()) {
    std::printf("%s: all %d frames (%s) are there\n", pattern.c_str(), range.count(), frameList.c_str());
    return 0;
  }
  std::printf("%s: %d of %d frames (%s) are there; missing %zu: %s\n", pattern.c_str(),
              range.count() - static_cast<int>(missing.size()), range.count(), frameList.c_str(), missing.size(),
              describeFrames(missing).c_str());
  if (record) printRerunAdvice(*record, missing, renderScript);
  return 1;
}

}  // namespace

int animateCommand(const AnimateArguments& arguments) {
  const std::optional<std::string>& output = arguments.output;
  const std::optional<std::string>& frames = arguments.frames;
  const std::optional<std::string>& video = arguments.video;
  if (arguments.statusPattern) {
    if (output) throw UsageError("--status takes the frame pattern itself (--status frames/%04d.png); leave out -o");
    if (arguments.farm || video) throw UsageError("--status only lists frames; it goes without --farm and --video");
    return frameStatus(*arguments.statusPattern, frames, arguments.preset, arguments.fps);
  }
  if (!arguments.farm && (arguments.tasks || arguments.partition || arguments.submit))
    throw UsageError("--tasks, --partition and --submit go with --farm slurm");
  if (arguments.partition) checkPartition(*arguments.partition);
  if (!output) throw UsageError("animate needs an output pattern: -o frames/%04d.png");
  checkFramePattern(*output);
  if (video && video->empty()) throw UsageError("--video needs a file name such as out.mp4");
  const FrameKind kind = frameKind(*output);
  if (kind != FrameKind::Png && video)
    throw UsageError("--video encodes PNG frames; volume frames (" + *output + ") are not a video");
  if (kind != FrameKind::Png && arguments.motionBlur > 1)
    throw UsageError("--motion-blur averages PNG frames; a volume frame holds one moment of the animation");

  core::Scene scene = sceneFromArgument(arguments.preset);
  if (arguments.points) scene.points = arguments.points;
  if (arguments.samples) scene.render.samples = *arguments.samples;
  if (arguments.grid) scene.gridResolution = *arguments.grid;
  // Through the JSON form once, like render: the preset each frame stores reproduces the frame.
  {
    const bool embedded = scene.embedded;
    const std::filesystem::path baseDirectory = scene.baseDirectory;
    scene = core::sceneFromJson(core::sceneToJson(scene), "(command line)");
    scene.embedded = embedded;
    scene.baseDirectory = baseDirectory;
  }
  const double fps = arguments.fps.value_or(core::animationFps(scene));
  scene.animation.fps = fps;
  const int frameCount = core::animationFrameCount(scene, fps);
  const FrameRange range = frames ? parseFrameRange(*frames, frameCount, fps) : FrameRange{0, frameCount - 1};
  if (arguments.farm) {
    FarmJob job;
    job.binary = currentExecutable();
    job.workingDirectory = std::filesystem::current_path().string();
    job.preset = arguments.preset;
    job.pattern = *output;
    job.frames = range;
    job.tasks = arguments.tasks.value_or(1);
    job.partition = arguments.partition.value_or("");
    job.options = arguments.taskOptions;
    if (video) job.videoCommand = ffmpegArguments(*output, range, fps, *video);
    return writeFarmJob(job, arguments.submit);
  }
  lockFits(scene);

  const std::filesystem::path folder = std::filesystem::path(framePath(*output, range.first)).parent_path();
  if (!folder.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw core::Error("cannot create the folder '" + folder.string() + "' for the frames: " + ec.message());
  }

  const std::atomic<bool>& interrupted = catchInterrupts();
  const bool interactive = isatty(fileno(stderr));
  StillOptions options;
  options.threads = arguments.threads;
  // One backend for every frame: keyframes change values, never a layer's kind.
  options.backend = resolveBackend(arguments.backend, scene.layers);
  // Split into chunks as `render` splits a still (its default K), so `voxflame render FRAME.png`
  // makes the frame again, byte for byte.
  options.chunks = ChunkPlan{};
  options.cancel = &interrupted;
  int current = range.first;
  options.progress = [&](const core::AccumulatorStats& stats, std::uint64_t target) {
    if (!interactive) return;
    const double done =
        target ? static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 0.0;
    std::fprintf(stderr, "\rframe %d: accumulating %5.1f%%  %6.1f M points/s   ", current, 100.0 * done,
                 stats.pointsPerSecond * 1e-6);
    std::fflush(stderr);
  };

  std::optional<FrameRenderer> renderer;
  SceneShape shape;
  int shapeResolution = 0;
  core::PackedVolume volume;
  std::optional<core::Scene> volumeScene;  // the moment the accumulated volume shows
  AccumulatedVolume accumulated;
  const auto start = std::chrono::steady_clock::now();
  const int total = range.last - range.first + 1;
  try {
    for (int frame = range.first; frame <= range.last; ++frame) {
      current = frame;
      const auto frameStart = std::chrono::steady_clock::now();
      const double time = frame / fps;
      StillResult result;
      double accumulateSeconds = 0.0;
      const std::string path = framePath(*output, frame);
      // Accumulates the moment's volume unless the last one shows it already; true when it did.
      auto accumulateFor = [&](const core::Scene& moment) {
        if (!needsNewVolume(volumeScene, moment)) return false;
        if (moment.gridResolution != shapeResolution) {
          shape = buildSceneShape(moment);
          shapeResolution = moment.gridResolution;
        }
        accumulated = accumulateVolume(moment, shape, options);
        accumulateSeconds += accumulated.seconds;
        if (!accumulated.warning.empty())
          std::cerr << "\nvoxflame: warning: frame " << frame << ": " << accumulated.warning << "\n";
        volumeScene = moment;
        return true;
      };
      auto reportFrame = [&] {
        const double frameSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
        const int done = frame - range.first + 1;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "%sframe %d (%d of %d, %.3f s): wrote %s in %.2f s, %s left\n", interactive ? "\r" : "",
                     frame, done, total, time, path.c_str(), frameSeconds,
                     formatDuration(elapsed / done * (total - done)).c_str());
      };
      if (kind != FrameKind::Png) {
        // The frame's accumulated volume, with the same locked fit and seed as its PNG would have:
        // a volume that does not change between frames (a camera move) is written again as it is.
        const core::Scene moment = core::sceneAtTime(scene, time);
        accumulateFor(moment);
        if (interrupted) throw RenderCancelled();
        result.stats = accumulated.stats;
        // No times in the file: a frame rendered again, here or on a farm, holds the same preset.
        const std::string preset = stillMetadata(moment, result, false).at(kPresetChunkKey);
        if (kind == FrameKind::Vdb)
          core::writeVdbVolume(path, accumulated.snapshot, preset);
        else
          core::writeNrrdVolume(path, accumulated.snapshot, preset);
        reportFrame();
        continue;
      }
      std::vector<double> sum;
      for (int sub = 0; sub < arguments.motionBlur; ++sub) {
        // Sub-frames spread evenly over the shutter interval, centred on the frame's time.
        const double offset =
            arguments.motionBlur > 1 ? ((sub + 0.5) / arguments.motionBlur - 0.5) * arguments.shutter / fps : 0.0;
        const core::Scene moment = core::sceneAtTime(scene, std::max(0.0, time + offset));
        // Under the GPU backend the renderer comes first: the backend shares its context and
        // leaves each frame's grid on the GPU.
        if (!renderer && options.backend == core::BackendKind::Gpu) {
          renderer.emplace();
          options.renderer = renderer->shareGroup();
        }
        if (accumulateFor(moment)) {
          if (accumulated.packed)
            volume = std::move(*accumulated.packed);
          else
            core::packVolume(accumulated.snapshot, volume);
          if (!renderer) renderer.emplace();
          renderer->setVolume(volume, shape);
        }
        if (interrupted) throw RenderCancelled();
        const core::ImageRGBA image = renderer->render(moment, arguments.width, arguments.height, false);
        if (sum.empty()) sum.assign(image.pixels.size(), 0.0);
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += image.pixels[i];
        if (sub == 0) result.image = image;
      }
      for (std::size_t i = 0; i < sum.size(); ++i)
        result.image.pixels[i] = static_cast<float>(sum[i] / arguments.motionBlur);
      if (interrupted) throw RenderCancelled();
      result.stats = accumulated.stats;
      result.accumulateSeconds = accumulateSeconds;
      result.renderer = renderer->rendererName();
      result.renderSeconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count() - accumulateSeconds;
      // No times in the frame: a frame rendered again, here or on a farm, is the same file.
      core::writePng(path, result.image, 8, stillMetadata(core::sceneAtTime(scene, time), result, false));
      reportFrame();
    }
  } catch (const RenderCancelled&) {
    std::cerr << (interactive ? "\n" : "") << "voxflame: interrupted; frame " << current << " was not written";
    if (current > range.first) std::cerr << " (frames " << range.first << "-" << current - 1 << " are complete)";
    std::cerr << "\n";
    return 130;
  }
  std::printf("wrote %d frames (%d-%d) to %s\n", total, range.first, range.last, output->c_str());

  if (!video) return 0;
  const std::vector<std::string> command = ffmpegArguments(*output, range, fps, *video);
  const auto ffmpeg = findOnPath("ffmpeg");
  if (!ffmpeg) {
    std::cerr << "voxflame: --video: ffmpeg is not installed (not found on PATH), so no video was made; the frames "
                 "are written. Install ffmpeg and run:\n  "
              << shellQuoted(command) << "\n";
    return kNoVideoStatus;
  }
  const int status = runProgram(*ffmpeg, command);
  if (status != 0)
    throw core::Error("ffmpeg failed (exit status " + std::to_string(status) + ") encoding '" + *video + "'");
  std::printf("wrote %s (H.264, %g fps)\n", video->c_str(), fps);
  return 0;
}

}  // namespace voxflame::app
