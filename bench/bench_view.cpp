#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "bench.h"
#include "core/image_io.h"
#include "core/image_metrics.h"
#include "core/scene.h"
#include "explorer_session.h"
#include "gl/headless_context.h"
#include "gl/read_back.h"
#include "headless_frame_loop.h"
#include "programs.h"

namespace voxflame::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The headless window's picture (rows top to bottom, values in [0, 1]).
core::ImageRGBA readWindow(const HeadlessFrameLoop& loop) {
  const std::vector<std::uint8_t> bytes =
      gl::readRgba8(loop.window, {0, 0, HeadlessFrameLoop::kWidth, HeadlessFrameLoop::kHeight}, gl::ReadAlpha::Opaque);
  core::ImageRGBA image;
  image.width = HeadlessFrameLoop::kWidth;
  image.height = HeadlessFrameLoop::kHeight;
  image.pixels.resize(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) image.pixels[i] = static_cast<float>(bytes[i]) / 255.0f;
  return image;
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return -1.0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(fraction * static_cast<double>(values.size())))];
}

double mean(const std::vector<double>& values) {
  return values.empty() ? -1.0
                        : std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

}  // namespace

// Each preset opened in the live view (as the window loop runs it: frames while anything moves,
// the loop's sleeps once frameWaitSeconds says it rests), from the moment it is opened (the last
// change) until the view and the session rest. The window is read back at intervals (a quarter
// of a second for the first 10 s, half a second to 20 s, then every 2 s; the read-backs' cost is
// in the frame times), and each picture compared with the final one. At rest, `voxflame render` of the same preset at
// the view's size, with the view's points (or the grid's, for the volume method) and samples, is set beside the view's
// picture.
void benchView(const BenchOptions& options) {
  gl::HeadlessContext context;
  constexpr double kGiveUpSeconds = 300.0, kRestSeconds = 5.0;
  for (const std::filesystem::path& path : presetsToRun(options)) {
    const core::Scene scene = core::loadScene(path);
    app::ExplorerSession session;
    HeadlessFrameLoop loop(session, scene, explorerPreviewScale(context.renderer()));
    // --backend: what refines the large grid (the explorer's "refine on" setting).
    loop.state.services.settings.refinementBackend =
        options.backend == "gpu" ? app::BackendChoice::Gpu : app::BackendChoice::Cpu;
    std::vector<double> frameMs, pointsFrameMs;
    auto step = [&] {
      double ms = -1.0;
      if (loop.step(session, &ms)) return true;
      frameMs.push_back(ms);
      const app::ViewRefinement& view = loop.state.frame.view;
      if (view.points && view.pointsDone > 0 && !view.resting) pointsFrameMs.push_back(ms);
      return false;
    };
    struct Snapshot {
      double seconds;
      core::ImageRGBA image;
    };
    std::vector<Snapshot> snapshots;
    // The picture the points replace, and their first, to compare with the final one: the points
    // take over when they are the closer of the two.
    std::optional<core::ImageRGBA> beforePoints, firstPoints;
    const auto start = Clock::now();
    double nextSnapshot = 0.5;
    bool resting = false;
    while (!resting && secondsSince(start) < kGiveUpSeconds) {
      resting = step();
      const app::ViewRefinement& refinement = loop.state.frame.view;
      if (refinement.points && !firstPoints && loop.view.hasVolume()) {
        if (refinement.pointsShown)
          firstPoints = readWindow(loop);
        else if (refinement.waitingForPoints)
          beforePoints = readWindow(loop);
      }
      const double now = secondsSince(start);
      if (!resting && now >= nextSnapshot && loop.view.hasVolume()) {
        snapshots.push_back({now, readWindow(loop)});
        nextSnapshot = now + (now < 10.0 ? 0.25 : now < 20.0 ? 0.5 : 2.0);
      }
    }
    const double toRest = secondsSince(start);
    const app::SessionStatus rested = session.status();
    const app::ViewRefinement view = loop.state.frame.view;
    nlohmann::json measurement = {{"benchmark", "view"},
                                  {"backend", std::string(core::toString(session.status().backend))},
                                  {"preset", path.stem().string()},
                                  {"renderer", context.renderer()},
                                  {"method", scene.render.method == core::RenderMethod::Points ? "points" : "volume"},
                                  {"rested", resting},
                                  {"seconds_to_rest", resting ? toRest : -1.0},
                                  {"samples", view.samples},
                                  {"points_millions", static_cast<double>(view.pointsDone) * 1e-6},
                                  {"grid_points_millions", static_cast<double>(rested.stats.points) * 1e-6},
                                  {"frames", frameMs.size()},
                                  {"frame_ms_p95", percentile(frameMs, 0.95)},
                                  {"points_frame_ms_mean", mean(pointsFrameMs)},
                                  {"points_frame_ms_p95", percentile(pointsFrameMs, 0.95)}};
    if (resting) {
      const core::ImageRGBA final = readWindow(loop);
      double toSimilar = -1.0;
      for (const Snapshot& snapshot : snapshots)
        if (core::ssimLuma(snapshot.image, final) >= 0.95) {
          toSimilar = snapshot.seconds;
          break;
        }
      measurement["seconds_to_ssim_0_95"] = toSimilar >= 0.0 ? toSimilar : toRest;
      if (beforePoints && firstPoints) {
        measurement["ssim_volume_before_points"] = core::ssimLuma(*beforePoints, final);
        measurement["ssim_first_points"] = core::ssimLuma(*firstPoints, final);
      }
      const double cpuStart = cpuSeconds(RUSAGE_SELF);
      const auto restStart = Clock::now();
      while (secondsSince(restStart) < kRestSeconds) step();
      measurement["cpu_percent_at_rest"] = 100.0 * (cpuSeconds(RUSAGE_SELF) - cpuStart) / secondsSince(restStart);
      // The export of the view: the same document at the view's size, points and samples.
      const std::filesystem::path exported =
          std::filesystem::temp_directory_path() / ("voxflame-bench-view-" + std::to_string(getpid()) + ".png");
      const bool points = scene.render.method == core::RenderMethod::Points;
      const std::vector<std::string> arguments = {app::currentExecutable(),
                                                  "render",
                                                  path.string(),
                                                  "-o",
                                                  exported.string(),
                                                  "--width",
                                                  std::to_string(HeadlessFrameLoop::kWidth),
                                                  "--height",
                                                  std::to_string(HeadlessFrameLoop::kHeight),
                                                  "--samples",
                                                  std::to_string(std::max(1, view.samples)),
                                                  "--points",
                                                  std::to_string(points ? scene.points : rested.stats.points)};
      std::string output;
      if (app::runProgram(arguments[0], arguments, &output, true) == 0) {
        const core::ImageRGBA render = core::readPng(exported).image;
        // VOXFLAME_BENCH_IMAGES names a folder to keep both pictures in, to set side by side.
        if (const char* folder = std::getenv("VOXFLAME_BENCH_IMAGES")) {
          core::writePng(std::filesystem::path(folder) / (path.stem().string() + "-view.png"), final, 8, {});
          core::writePng(std::filesystem::path(folder) / (path.stem().string() + "-export.png"), render, 8, {});
        }
        measurement["ssim_vs_export"] = core::ssimLuma(final, render);
        measurement["luminance_ratio_vs_export"] =
            core::meanLinearLuminance(final) / std::max(1e-9, core::meanLinearLuminance(render));
      } else {
        std::fprintf(stderr, "view: the export failed: %s\n", output.c_str());
      }
      std::error_code ignored;
      std::filesystem::remove(exported, ignored);
    }
    report(options, measurement);
  }
}

}  // namespace voxflame::bench
