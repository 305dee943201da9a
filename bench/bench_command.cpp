#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "bench.h"
#include "core/error.h"

namespace voxflame::bench {

const std::vector<Benchmark>& benchmarks() {
  static const std::vector<Benchmark> table = {
      {"accumulate", "points per second filling the bunny mask at 256³", &benchAccumulate},
      {"mask", "seconds to build the inside mask: bunny at 256³, dragon at 256³ and 512³", &benchMask},
      {"raymarch", "milliseconds per 1280×720 frame of a 256³ and a 512³ grid, and per 1920×1080 frame at 512³",
       &benchRaymarch},
      {"explorer",
       "explorer frames headless at 192³, 256³ and 512³: edit to first frame and to full resolution, frames while "
       "dragging, orbiting and refining, memory, CPU once converged; then, under Xvfb with xdotool, the seconds "
       "until a typed 16-character string shows in a field of the real explorer (goal 0.5 s)",
       &benchExplorer},
      {"export",
       "seconds for a 3840×2160 still of the default preset: volume at 512³ with 4 samples, points at 100 points "
       "per pixel (--method volume|points); with --print, seconds and peak resident memory of a 15360×8640 print "
       "(points method, 20 points per pixel)",
       &benchExport},
      {"quality",
       "noise of the default preset and two others at 1280×720, both methods: relative luminance RMSE against "
       "10× the points, and seconds",
       &benchQuality},
      {"flame",
       "chaos-game samples per second on 2 threads against flam3-render (when installed) on the same genomes: "
       "flam3's 4-transform sample and the heaviest corpus flame flam3-render renders",
       &benchFlame},
      {"rest",
       "the live view on each shipped preset (or the ones named) at its own grid: seconds until it rests and why, "
       "the frame times until then (p95, worst), then CPU and context switches per second at rest",
       &benchRest},
      {"view",
       "the live view headless at 1280×720 on the shipped presets (or the ones named), as the window loop runs it: "
       "seconds from the last change to a picture with SSIM ≥ 0.95 against the final one, seconds to rest, frame "
       "times while the points refine (mean, p95) and overall p95, CPU at rest, and the view at rest against "
       "`voxflame render` of the same preset at the view's size with its points and samples (SSIM, mean-luminance "
       "ratio)",
       &benchView},
      {"fidelity",
       "the flat view against flam3-render at quality 400, at most 640 pixels wide: SSIM of the luma (and flam3 "
       "against itself with another seed as the ceiling), ratio of mean luminance; flam3's test.flam3 and up to 19 "
       "corpus flames, or the flame files named",
       &benchFidelity},
      {"search",
       "the explorer's Search (F3) on each shipped attractor preset: seconds to the first chaotic candidate, tries "
       "and the strength it widened to (goal: 5 s each)",
       &benchSearch},
  };
  return table;
}

double cpuSeconds(int who) {
  rusage usage{};
  getrusage(who, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void report(const BenchOptions& options, const nlohmann::json& measurement) {
  if (options.json) {
    std::cout << measurement.dump() << std::endl;
    return;
  }
  bool first = true;
  for (auto it = measurement.begin(); it != measurement.end(); ++it) {
    std::cout << (first ? "" : "  ") << it.key() << "=" << (it->is_string() ? it->get<std::string>() : it->dump());
    first = false;
  }
  std::cout << std::endl;
}

namespace {

// The shared test meshes: $VOXFLAME_MESHES, else ../shared/data/meshes from the current folder
// or from the source tree this binary was built from.
std::string findMeshFolder() {
  if (const char* env = std::getenv("VOXFLAME_MESHES")) return env;
  for (const std::filesystem::path& candidate : {std::filesystem::path("../shared/data/meshes"),
                                                 std::filesystem::path(VOXFLAME_SOURCE_DIR) / "../shared/data/meshes"})
    if (std::filesystem::exists(candidate / "bunny.obj")) return std::filesystem::weakly_canonical(candidate).string();
  throw core::Error("cannot find the benchmark meshes; set VOXFLAME_MESHES to the folder holding bunny.obj");
}

}  // namespace

int runBenchmarks(BenchOptions options, const std::string& which) {
  bool found = false;
  for (const Benchmark& benchmark : benchmarks()) {
    if (!which.empty() && which != benchmark.name) continue;
    found = true;
    if (options.meshFolder.empty()) options.meshFolder = findMeshFolder();
    benchmark.run(options);
  }
  if (!found) throw core::Error("unknown benchmark '" + which + "'");
  return 0;
}

}  // namespace voxflame::bench
