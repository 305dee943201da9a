#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench.h"
#include "core/error.h"
#include "core/scene_io.h"
#include "pipeline.h"

extern char** environ;

namespace voxflame::bench {

namespace {

void report(const BenchOptions& options, const char* method, int grid, int samples, double seconds,
            const app::StillResult& result) {
  voxflame::bench::report(options, {{"bench", "export"},
                                    {"method", method},
                                    {"width", 3840},
                                    {"height", 2160},
                                    {"grid", grid},
                                    {"samples", samples},
                                    {"seconds", seconds},
                                    {"points", result.stats.points},
                                    {"points_projected", result.pointsProjected},
                                    {"accumulate_seconds", result.accumulateSeconds},
                                    {"render_seconds", result.renderSeconds},
                                    {"coverage", result.coverage},
                                    {"renderer", result.renderer}});
}

// A print for sale: the default preset at 15360×8640 with the points method and 20 points a
// pixel, rendered by `voxflame render` in a process of its own, so its peak resident memory
// (wait4's ru_maxrss) is the render's alone. Goals on a 2-core machine: 5 minutes, 6 GB.
void benchPrint(const BenchOptions& options) {
  constexpr int kWidth = 15360, kHeight = 8640, kPointsPerPixel = 20;
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("voxflame-bench-print-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::filesystem::path preset = folder / "print.json", output = folder / "print.png";
  std::ofstream(preset) << core::sceneToJson(core::defaultScene());
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<std::string> arguments = {self,
                                        "render",
                                        preset.string(),
                                        "-o",
                                        output.string(),
                                        "--method",
                                        "points",
                                        "--width",
                                        std::to_string(kWidth),
                                        "--height",
                                        std::to_string(kHeight),
                                        "--points",
                                        std::to_string(std::uint64_t{kPointsPerPixel} * kWidth * kHeight)};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t child = 0;
  if (const int error = posix_spawn(&child, self.c_str(), nullptr, nullptr, argv.data(), environ); error != 0) {
    std::filesystem::remove_all(folder);
    throw core::Error("bench export --print: could not start voxflame render");
  }
  int status = 0;
  rusage usage{};
  while (::wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool written = std::filesystem::exists(output);
  std::filesystem::remove_all(folder);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !written)
    throw core::Error("bench export --print: voxflame render failed (status " + std::to_string(status) + ")");
  voxflame::bench::report(options, {{"bench", "export"},
                                    {"print", true},
                                    {"method", "points"},
                                    {"width", kWidth},
                                    {"height", kHeight},
                                    {"points_per_pixel", kPointsPerPixel},
                                    {"seconds", seconds},
                                    {"peak_resident_mb", static_cast<double>(usage.ru_maxrss) / 1024.0},
                                    {"goal_seconds", 300},
                                    {"goal_peak_resident_mb", 6000}});
}

}  // namespace

// The exports a user makes of the default preset for a 4K still: the volume method at 512³ with 4
// samples, and the points method with 100 points per pixel (flam3's "quality" 100).
void benchExport(const BenchOptions& options) {
  if (options.print) {
    benchPrint(options);
    return;
  }
  if (options.method.empty() || options.method == "volume") {
    core::Scene scene = core::defaultScene();
    scene.render.method = core::RenderMethod::Volume;
    scene.gridResolution = 512;
    scene.render.samples = 4;
    app::StillOptions still;
    still.width = 3840;
    still.height = 2160;
    const auto start = std::chrono::steady_clock::now();
    const app::StillResult result = app::renderStill(scene, still);
    report(options, "volume", 512, 4, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
           result);
  }
  if (options.method.empty() || options.method == "points") {
    core::Scene scene = core::defaultScene();
    scene.render.method = core::RenderMethod::Points;
    app::StillOptions still;
    still.width = 3840;
    still.height = 2160;
    still.points = 100ULL * 3840ULL * 2160ULL;
    const auto start = std::chrono::steady_clock::now();
    const app::StillResult result = app::renderStill(scene, still);
    report(options, "points", scene.gridResolution, 100,
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), result);
  }
}

}  // namespace voxflame::bench
