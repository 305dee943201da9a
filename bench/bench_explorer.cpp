#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <thread>

#include "bench.h"
#include "core/camera.h"
#include "core/scene_io.h"
#include "explorer_session.h"
#include "export_job.h"
#include "gl/headless_context.h"
#include "live_view.h"

namespace voxflame::bench {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double residentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  long long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

// One explorer frame without the window: app::LiveView, the very frame body the explorer runs
// under its panels, then a wait for the GL to finish so the time is the frame's real cost.
// A headless context has no window: the frame goes to a 1280×720 colour buffer standing in for it.
struct FrameLoop {
  FrameLoop(app::ExplorerSession& session, const core::Scene& scene, float renderScale)
      : view(session, nullptr, nullptr) {
    app::resetExplorerState(state, scene);
    state.renderScale = renderScale;
    state.settings.refineUntilNoisePercent = 0.0;  // refine until told otherwise (cpuAtRest)
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1280, 720);
    glGenFramebuffers(1, &window);
    glBindFramebuffer(GL_FRAMEBUFFER, window);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  }
  ~FrameLoop() {
    glDeleteFramebuffers(1, &window);
    glDeleteRenderbuffers(1, &colour);
  }
  app::ExplorerState state;
  app::LiveView view;
  GLuint colour = 0, window = 0;

  // Returns the post whose volume became visible in this frame, or 0.
  std::uint64_t run() {
    const app::LiveFrame frame = view.frame(state, 1280, 720, window);
    glFinish();
    return frame.newVolumeShown ? frame.shownPost : 0;
  }
};

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The explorer once its volume has converged: the noise target is set a little below the current
// estimate, the frame loop runs as the window's does (it waits instead of drawing when
// app::frameWaitSeconds says so), and the process's CPU time over a few seconds of rest is
// measured. Returns {seconds to converge, CPU percent of one core at rest, noise}; -1 when it
// did not converge within a minute.
std::array<double, 3> cpuAtRest(app::ExplorerSession& session, FrameLoop& loop) {
  const double noise = session.status().noise;
  if (!(noise > 0.0)) return {-1.0, -1.0, -1.0};
  loop.state.settings.refineUntilNoisePercent = 100.0 * 0.9 * noise;
  int restingFrames = 0;
  auto step = [&] {
    loop.state.session = session.status();
    const double wait = app::frameWaitSeconds(loop.state, loop.view.resting(), restingFrames);
    if (wait > 0.0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));  // glfwWaitEventsTimeout, no input
      return;
    }
    loop.run();
    restingFrames = loop.view.resting() && loop.state.session.resting ? restingFrames + 1 : 0;
  };
  const auto start = Clock::now();
  while (restingFrames < 3 && millisecondsSince(start) < 60'000) step();
  if (restingFrames < 3) return {-1.0, -1.0, -1.0};
  const double converged = millisecondsSince(start) / 1000.0;
  const double cpuStart = processCpuSeconds();
  const auto restStart = Clock::now();
  while (millisecondsSince(restStart) < 3000.0) step();
  const double cpu = processCpuSeconds() - cpuStart;
  return {converged, 100.0 * cpu / (millisecondsSince(restStart) / 1000.0), session.status().noise};
}

}  // namespace

// The explorer's numbers: time from a parameter change to the first frame showing it, the worst
// frame time while the volume refines, and the memory the session holds at 256³ and 512³.
void benchExplorer(const BenchOptions& options) {
  gl::HeadlessContext context;
  // As the explorer does: software GL marches a quarter of the pixels.
  const bool software = context.renderer().find("llvmpipe") != std::string::npos;
  for (int resolution : {256, 512}) {
    const double baseline = residentMegabytes();
    core::Scene initial = core::defaultScene();
    initial.gridResolution = resolution;
    app::ExplorerSession session;
    FrameLoop loop(session, initial, software ? 0.5f : 1.0f);
    core::Scene& scene = loop.state.scene;
    loop.run();  // posts the scene
    session.waitUntilApplied(600.0);
    // Wait for the first volume, then refine for a while as a user watching would.
    const auto start = Clock::now();
    while (!loop.view.hasVolume() && millisecondsSince(start) < 120'000) loop.run();
    double worstRefining = 0.0, totalRefining = 0.0;
    int refiningFrames = 0;
    const auto refineStart = Clock::now();
    while (millisecondsSince(refineStart) < 4000.0) {
      const auto frameStart = Clock::now();
      loop.run();
      const double ms = millisecondsSince(frameStart);
      worstRefining = std::max(worstRefining, ms);
      totalRefining += ms;
      ++refiningFrames;
    }
    const double memory = residentMegabytes() - baseline;

    // Parameter changes, as a slider drag makes them: time until the first frame showing each.
    std::vector<double> latencies, frames;
    for (int change = 0; change < 5; ++change) {
      // A 1% nudge of the first number a slider would move, whatever the first layer's kind.
      const double factor = change % 2 ? 1.0 / 1.01 : 1.01;
      core::PatternLayer& layer = scene.layers[0];
      if (layer.kind == core::PatternKind::Flame)
        layer.flame.xforms[0].affine.m[0] *= factor;
      else if (layer.kind == core::PatternKind::QuaternionJulia)
        layer.julia.c.x *= factor;
      else
        layer.params[0] *= factor;
      const auto changed = Clock::now();
      const std::uint32_t firstFrame = loop.view.frameCount();
      const std::uint64_t post = session.status().requestedGeneration + 1;  // the next frame posts it
      while (millisecondsSince(changed) < 60'000)
        if (loop.run() == post) break;
      latencies.push_back(millisecondsSince(changed));
      frames.push_back(loop.view.frameCount() - firstFrame);
    }
    // A still exported from the Export panel runs in a child process; the window's frames go on.
    double worstExporting = 0.0, totalExporting = 0.0;
    int exportingFrames = 0;
    if (resolution == 256) {
      const std::filesystem::path output = std::filesystem::temp_directory_path() / "voxflame-bench-export.png";
      app::ExportJob job;
      app::ExportRequest request;
      request.scene = core::defaultScene();
      request.output = output;
      request.settings.width = 1280;
      request.settings.height = 720;
      request.settings.points = 20'000'000;
      job.start(request);
      // As in the explorer, refinement pauses while the export runs.
      while ((loop.state.exportStatus = job.poll()).state == app::ExportState::Running) {
        const auto frameStart = Clock::now();
        loop.run();
        const double ms = millisecondsSince(frameStart);
        worstExporting = std::max(worstExporting, ms);
        totalExporting += ms;
        ++exportingFrames;
      }
      std::filesystem::remove(output);
    }
    loop.state.exportStatus = app::ExportStatus{};
    const auto [convergeSeconds, cpuPercent, restNoise] = cpuAtRest(session, loop);
    std::sort(latencies.begin(), latencies.end());
    std::sort(frames.begin(), frames.end());
    report(options, {{"bench", "explorer"},
                     {"grid", resolution},
                     {"renderer", context.renderer()},
                     {"render_scale", loop.state.renderScale},
                     {"mean_frame_ms", totalRefining / std::max(1, refiningFrames)},
                     {"worst_frame_ms", worstRefining},
                     {"change_to_frame_ms_median", latencies[latencies.size() / 2]},
                     {"change_to_frame_ms_worst", latencies.back()},
                     {"change_to_frame_frames_median", frames[frames.size() / 2]},
                     {"memory_mb", memory},
                     {"frames_during_export", exportingFrames},
                     {"mean_frame_ms_during_export", totalExporting / std::max(1, exportingFrames)},
                     {"worst_frame_ms_during_export", worstExporting},
                     {"seconds_to_converge", convergeSeconds},
                     {"noise_converged", restNoise},
                     {"cpu_percent_converged", cpuPercent}});
  }
}

}  // namespace voxflame::bench
