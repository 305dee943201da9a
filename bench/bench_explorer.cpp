#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

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
      while (job.poll().state == app::ExportState::Running) {
        const auto frameStart = Clock::now();
        loop.run();
        const double ms = millisecondsSince(frameStart);
        worstExporting = std::max(worstExporting, ms);
        totalExporting += ms;
        ++exportingFrames;
      }
      std::filesystem::remove(output);
    }
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
                     {"worst_frame_ms_during_export", worstExporting}});
  }
}

}  // namespace voxflame::bench
