#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench.h"
#include "core/error.h"
#include "core/scene.h"
#include "explorer_session.h"
#include "gl/headless_context.h"
#include "headless_frame_loop.h"
#include "preset_library.h"

namespace voxflame::bench {

namespace {

using Clock = std::chrono::steady_clock;

// Context switches of every thread of this process so far (voluntary and not), from each task's
// /proc status: each is a thread that woke up or was made to wait. /proc/self/status alone counts
// the main thread's only, and at rest the other threads are the ones that must sleep.
long long contextSwitches() {
  long long total = 0;
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error)) {
    std::ifstream status(task.path() / "status");
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("voluntary_ctxt_switches:", 0) == 0 || line.rfind("nonvoluntary_ctxt_switches:", 0) == 0)
        total += std::stoll(line.substr(line.find(':') + 1));
  }
  return total;
}

}  // namespace

std::vector<std::filesystem::path> presetsToRun(const BenchOptions& options) {
  const std::filesystem::path shipped = app::findShippedPresetFolder();
  std::vector<std::filesystem::path> paths;
  for (const std::string& name : options.presets) {
    std::filesystem::path path = name;
    if (!std::filesystem::exists(path)) path = shipped / name;
    if (!std::filesystem::exists(path)) path = shipped / (name + ".json");
    if (!std::filesystem::exists(path)) throw core::Error("no preset '" + name + "' (a file, or a shipped preset)");
    paths.push_back(path);
  }
  if (options.presets.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(shipped))
      if (entry.path().extension() == ".json") paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
  }
  return paths;
}

namespace {

// Why the session rests, as the status line says it.
std::string restReason(const app::SessionStatus& status) {
  if (status.converged) return "noise target";
  if (status.capped) return "cap";
  if (!status.error.empty()) return "error: " + status.error;
  if (!status.stats.problem.empty()) return "problem: " + status.stats.problem;
  return status.resting ? "rest" : "none";
}

}  // namespace

// Each preset in the live view at its own grid, with the explorer's default noise target, run as
// the window loop runs it: frames while anything moves, and once app::frameWaitSeconds says it
// rests, sleeps of that length (glfwWaitEventsTimeout with no input arriving). Reports the
// seconds until rest and why, then the CPU share and the context switches per second over a few
// seconds of rest.
void benchRest(const BenchOptions& options) {
  gl::HeadlessContext context;
  constexpr double kGiveUpSeconds = 300.0, kRestSeconds = 5.0;
  for (const std::filesystem::path& path : presetsToRun(options)) {
    const core::Scene scene = core::loadScene(path);
    app::ExplorerSession session;
    HeadlessFrameLoop loop(session, scene, explorerPreviewScale(context.renderer()));
    // --backend: what refines the large grid (the explorer's "refine on" setting).
    loop.state.services.settings.refinementBackend =
        options.backend == "gpu" ? app::BackendChoice::Gpu : app::BackendChoice::Cpu;
    std::vector<double> frameMs;  // of the frames drawn until rest
    bool measuringFrames = true;
    auto step = [&] {
      double ms = -1.0;
      const bool rested = loop.step(session, &ms);
      if (measuringFrames && ms >= 0.0) frameMs.push_back(ms);
      return rested;
    };
    const auto start = Clock::now();
    bool resting = false;
    double nextProgress = 10.0;
    while (!resting && secondsSince(start) < kGiveUpSeconds) {
      resting = step();
      // A line on stderr every ten seconds: a preset can take minutes to rest.
      if (secondsSince(start) >= nextProgress) {
        const app::SessionStatus status = session.status();
        std::fprintf(stderr, "rest: %s %.0f s, %.0f of %.0f points per voxel, noise %.2f%% (last two %.2f%%, %.2f%%)\n",
                     path.stem().c_str(), secondsSince(start), status.pointsPerVoxel, status.capPointsPerVoxel,
                     100.0 * status.noise, 100.0 * status.lastMeasurement, 100.0 * status.previousMeasurement);
        nextProgress += 10.0;
      }
    }
    const double toRest = secondsSince(start);
    const app::SessionStatus rested = session.status();
    nlohmann::json measurement = {{"benchmark", "rest"},
                                  {"backend", std::string(core::toString(session.status().backend))},
                                  {"preset", path.stem().string()},
                                  {"grid", scene.gridResolution},
                                  {"rested", resting},
                                  {"seconds_to_rest", resting ? toRest : -1.0},
                                  {"reason", restReason(rested)},
                                  {"noise_percent", std::isfinite(rested.noise) ? 100.0 * rested.noise : -1.0},
                                  {"points_millions", static_cast<double>(rested.stats.points) / 1e6},
                                  {"points_per_voxel", rested.pointsPerVoxel},
                                  {"cap_points_per_voxel", rested.capPointsPerVoxel}};
    measuringFrames = false;
    if (!frameMs.empty()) {
      std::sort(frameMs.begin(), frameMs.end());
      measurement["frames"] = frameMs.size();
      measurement["frame_ms_p95"] =
          frameMs[std::min(frameMs.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(frameMs.size())))];
      measurement["frame_ms_worst"] = frameMs.back();
    }
    if (resting) {
      const double cpuStart = cpuSeconds(RUSAGE_SELF);
      const long long switchesStart = contextSwitches();
      const auto restStart = Clock::now();
      while (secondsSince(restStart) < kRestSeconds) step();
      const double seconds = secondsSince(restStart);
      measurement["cpu_percent_at_rest"] = 100.0 * (cpuSeconds(RUSAGE_SELF) - cpuStart) / seconds;
      measurement["wakeups_per_second_at_rest"] = static_cast<double>(contextSwitches() - switchesStart) / seconds;
    }
    report(options, measurement);
  }
}

}  // namespace voxflame::bench
