// `voxflame animate`: renders a preset's keyframed animation to numbered PNG frames, optionally
// encoded to a video by ffmpeg.
//
// Temporal stability comes from two choices. The fit of every layer into the mesh is locked to
// the one of time 0 — of the whole animation, not of the rendered range — so a parameter change
// never moves or resizes the pattern and machines rendering different ranges agree. And every
// frame uses the preset's own seed rather than one derived from the frame number: the orbits start
// from the same points with the same random numbers, so wherever the pattern does not change
// (a camera move, a tone fade, a still stretch between keys) consecutive volumes are identical,
// bit for bit, instead of showing fresh Monte Carlo noise on every frame; where parameters move,
// the noise follows the pattern instead of flickering on its own.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "arguments.h"
#include "commands.h"
#include "core/accumulator.h"
#include "core/error.h"
#include "core/keyframes.h"
#include "core/packed_volume.h"
#include "pipeline.h"

namespace voxflame::app {

namespace {

// Exit status when the frames were written but the asked-for video could not be (no ffmpeg).
constexpr int kNoVideoStatus = 3;

// A frame pattern holds exactly one integer conversion (%d, with an optional 0 flag and width;
// %% is a literal percent sign), so snprintf with the frame number is safe and ffmpeg reads it.
void checkFramePattern(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern.size() && pattern[j] == '0') ++j;
    const std::size_t widthStart = j;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
    if (j >= pattern.size()) throw UsageError("-o '" + pattern + "' ends in an unfinished % conversion");
    if (j - widthStart > 2) throw UsageError("-o '" + pattern + "': a frame number wider than 99 digits is not useful");
    if (pattern[j] == 's')
      throw UsageError("-o '" + pattern + "': %s is not allowed; the frame number is an integer, e.g. frames/%04d.png");
    if (pattern[j] != 'd')
      throw UsageError("-o '" + pattern + "': '" + pattern.substr(i, j - i + 1) +
                       "' is not a frame number; use %d or %04d (and %% for a percent sign)");
    ++conversions;
    i = j;
  }
  if (conversions == 0)
    throw UsageError("-o '" + pattern + "' has no frame number; give a printf pattern such as frames/%04d.png");
  if (conversions > 1)
    throw UsageError("-o '" + pattern + "' has " + std::to_string(conversions) +
                     " conversions; it needs exactly one frame number such as %04d");
  std::string extension = std::filesystem::path(pattern).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png") throw UsageError("-o '" + pattern + "' must end in .png (frames are PNG images)");
}

std::string framePath(const std::string& pattern, int frame) {
  // checkFramePattern allows exactly one %d: the format is safe with one int.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  const int length = std::snprintf(nullptr, 0, pattern.c_str(), frame);
  std::string path(static_cast<std::size_t>(length) + 1, '\0');
  std::snprintf(path.data(), path.size(), pattern.c_str(), frame);
#pragma GCC diagnostic pop
  path.resize(static_cast<std::size_t>(length));
  return path;
}

struct FrameRange {
  int first = 0;
  int last = 0;
};

FrameRange parseFrameRange(const std::string& text, int frameCount, double fps) {
  const auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      throw UsageError("--frames expects A-B or N (frame numbers from 0), not '" + text + "'");
    return std::stoi(part);
  };
  const std::size_t dash = text.find('-');
  FrameRange range;
  range.first = number(text.substr(0, dash));
  range.last = dash == std::string::npos ? range.first : number(text.substr(dash + 1));
  if (range.first > range.last) throw UsageError("--frames " + text + ": the first frame comes after the last");
  if (range.last >= frameCount) {
    char fpsText[32];
    std::snprintf(fpsText, sizeof fpsText, "%g", fps);
    throw UsageError("--frames " + text + ": the animation has " + std::to_string(frameCount) + " frames (0-" +
                     std::to_string(frameCount - 1) + ") at " + fpsText + " fps");
  }
  return range;
}

// Replaces each layer's automatic fit by the one of the scene at time 0, so that every frame, on
// every machine, places the pattern the same way.
void lockFits(core::Scene& scene) {
  const core::Scene first = core::sceneAtTime(scene, 0.0);
  const SceneShape shape = buildSceneShape(first);
  for (std::size_t i = 0; i < scene.layers.size(); ++i) {
    core::LayerTransform& transform = scene.layers[i].transform;
    if (transform.lockFit) continue;
    const core::PreparedLayer prepared = core::prepareLayer(first.layers[i], *shape.mask, first.seed);
    transform.lockFit = true;
    transform.lockedCenter = prepared.automaticFit.center;
    transform.lockedScale = prepared.automaticFit.scale;
    transform.lockedAxisScale = prepared.automaticFit.axisScale;
  }
}

// What decides the accumulated volume: when a frame's differs from the last one's, accumulate again.
std::string patternKey(const core::Scene& scene) {
  const nlohmann::json document = core::sceneToDocument(scene, false);
  nlohmann::json key;
  for (const char* member : {"mesh", "grid", "layers", "seed", "points"}) key[member] = document.at(member);
  return key.dump();
}

std::optional<std::string> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::string folders = path;
  std::size_t start = 0;
  while (start <= folders.size()) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::string folder = folders.substr(start, end - start);
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
    start = end + 1;
  }
  return std::nullopt;
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

// Runs a program with these arguments (no shell, so no quoting); returns its exit status.
int runProgram(const std::string& program, const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0) throw core::Error("cannot start " + program);
  if (child == 0) {
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) throw core::Error("lost track of " + program);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

std::string shellQuoted(const std::vector<std::string>& arguments) {
  std::string line;
  for (const std::string& argument : arguments) {
    if (!line.empty()) line += ' ';
    const bool plain = std::all_of(argument.begin(), argument.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) ||
             std::string_view("-_./%:=+").find(c) != std::string_view::npos;
    });
    line += plain ? argument : "'" + argument + "'";
  }
  return line;
}

}  // namespace

int animateCommand(const CommandArgs& args) {
  Arguments arguments(args, 2);
  const auto output = arguments.take("-o", "--output");
  const auto frames = arguments.take("--frames");
  const int width = static_cast<int>(arguments.integer("--width", 1280, 1, 16384));
  const int height = static_cast<int>(arguments.integer("--height", 720, 1, 16384));
  const auto fpsOption = arguments.take("--fps");
  const double fpsValue = arguments.real("--fps", 0.0, 0.01, 1000.0);
  const int motionBlur = static_cast<int>(arguments.integer("--motion-blur", 1, 1, 256));
  const double shutter = arguments.real("--shutter", 0.5, 0.0, 1.0);
  const auto video = arguments.take("--video");
  const auto samples = arguments.take("--samples");
  const int sampleCount = static_cast<int>(arguments.integer("--samples", 0, 1, 1024));
  const std::uint64_t points = static_cast<std::uint64_t>(arguments.integer("--points", 0, 0, 1LL << 40));
  const auto grid = arguments.take("--grid");
  const int gridResolution = static_cast<int>(arguments.integer("--grid", 0, 16, 1024));
  const int threads = static_cast<int>(arguments.integer("--threads", 0, 0, 1024));
  arguments.finish(1);
  if (!output) throw UsageError("animate needs an output pattern: -o frames/%04d.png");
  checkFramePattern(*output);
  if (video && video->empty()) throw UsageError("--video needs a file name such as out.mp4");

  core::Scene scene = sceneFromArgument(arguments.positional());
  if (points) scene.points = points;
  if (samples) scene.render.samples = sampleCount;
  if (grid) scene.gridResolution = gridResolution;
  // Through the JSON form once, like render: the preset each frame stores reproduces the frame.
  {
    const bool embedded = scene.embedded;
    const std::filesystem::path baseDirectory = scene.baseDirectory;
    scene = core::sceneFromJson(core::sceneToJson(scene), "(command line)");
    scene.embedded = embedded;
    scene.baseDirectory = baseDirectory;
  }
  const double fps = fpsOption ? fpsValue : core::animationFps(scene);
  scene.animation.fps = fps;
  const int frameCount = core::animationFrameCount(scene, fps);
  const FrameRange range = frames ? parseFrameRange(*frames, frameCount, fps) : FrameRange{0, frameCount - 1};
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
  options.threads = threads;
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
  std::string volumeKey;
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
      std::vector<double> sum;
      for (int sub = 0; sub < motionBlur; ++sub) {
        // Sub-frames spread evenly over the shutter interval, centred on the frame's time.
        const double offset = motionBlur > 1 ? ((sub + 0.5) / motionBlur - 0.5) * shutter / fps : 0.0;
        const core::Scene moment = core::sceneAtTime(scene, std::max(0.0, time + offset));
        const std::string key = patternKey(moment);
        if (key != volumeKey) {
          if (moment.gridResolution != shapeResolution) {
            shape = buildSceneShape(moment);
            shapeResolution = moment.gridResolution;
          }
          accumulated = accumulateVolume(moment, shape, options);
          accumulateSeconds += accumulated.seconds;
          if (!accumulated.warning.empty())
            std::cerr << "\nvoxflame: warning: frame " << frame << ": " << accumulated.warning << "\n";
          core::packVolume(accumulated.snapshot, volume);
          if (!renderer) renderer.emplace();
          renderer->setVolume(volume, shape);
          volumeKey = key;
        }
        if (interrupted) throw RenderCancelled();
        const core::ImageRGBA image = renderer->render(moment, width, height, false);
        if (sum.empty()) sum.assign(image.pixels.size(), 0.0);
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += image.pixels[i];
        if (sub == 0) result.image = image;
      }
      for (std::size_t i = 0; i < sum.size(); ++i) result.image.pixels[i] = static_cast<float>(sum[i] / motionBlur);
      if (interrupted) throw RenderCancelled();
      result.stats = accumulated.stats;
      result.accumulateSeconds = accumulateSeconds;
      result.renderer = renderer->rendererName();
      const double frameSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
      result.renderSeconds = frameSeconds - accumulateSeconds;
      const std::string path = framePath(*output, frame);
      core::writePng(path, result.image, 8, stillMetadata(core::sceneAtTime(scene, time), result));
      const int done = frame - range.first + 1;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "%sframe %d (%d of %d, %.3f s): wrote %s in %.2f s, %s left\n", interactive ? "\r" : "",
                   frame, done, total, time, path.c_str(), frameSeconds,
                   formatDuration(elapsed / done * (total - done)).c_str());
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
