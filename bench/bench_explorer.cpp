
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>
#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stop_token>
#include <thread>
#include <sys/syscall.h>

#include "bench.h"
#include "core/scene_io.h"
#include "explorer_session.h"
#include "export_job.h"
#include "gl/headless_context.h"
#include "headless_frame_loop.h"
#include "live_view.h"
#include "xvfb_explorer.h"

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

// One explorer frame without the window (headless_frame_loop.h). Refines until told otherwise
// (cpuAtRest sets the target).
struct FrameLoop : HeadlessFrameLoop {
  FrameLoop(app::ExplorerSession& session, const core::Scene& scene, float renderScale)
      : HeadlessFrameLoop(session, scene, renderScale) {
    state.services.settings.refineUntilNoisePercent = 0.0;
  }
};

// Peak resident memory of the process so far (VmHWM), in megabytes.
double peakResidentMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1e3;  // kB
  return 0.0;
}

// The most threads of this process found runnable (state 'R' in /proc/self/task/*/stat: running
// or waiting for a core) at once, sampled every few milliseconds on a thread of its own (which
// does not count itself). While the explorer refines this must stay within the cores plus two:
// more runnable threads than cores only queue for them, and the frame's thread queues with them.
class RunnableThreadSampler {
 public:
  // `foreign`: the ids of threads that libraries started (Mesa's queues, a logging pool), counted
  // with the GL driver's and not as the process's own.
  explicit RunnableThreadSampler(std::set<std::string> foreign)
      : foreign_(std::move(foreign)), thread_([this](std::stop_token stop) { run(stop); }) {}
  // The threads now, but the calling one: taken before the explorer starts any, they are the
  // libraries' (the GL context's, and those started as libraries load).
  static std::set<std::string> threadsBut(const std::string& caller) {
    std::set<std::string> ids;
    std::error_code ec;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec))
      if (task.path().filename() != caller) ids.insert(task.path().filename().string());
    return ids;
  }
  int max() const { return max_.load(); }
  // The most runnable at once in two readings a millisecond apart (sample()).
  int maxSustained() const { return maxSustained_.load(); }
  // The most runnable at once since the last call, and which they were: the phase just ended.
  struct Phase {
    int most = 0, mostSustained = 0;
    std::string which, whichSustained;
  };
  Phase endPhase() {
    std::lock_guard lock(mutex_);
    return {std::exchange(phaseMax_, 0), std::exchange(phaseMaxSustained_, 0),
            std::exchange(phaseAtMax_, std::string()), std::exchange(phaseAtSustained_, std::string())};
  }
  // Runnable threads of the GL driver (Mesa's llvmpipe-N rasterisers and its queues) and other
  // libraries, at most at once: software GL standing in for a GPU, counted apart from the
  // process's own.
  int maxDriver() const { return maxDriver_.load(); }
  // Which threads were runnable when the most were, by name ("vf-accumulate×2 voxflame×1").
  std::string atMax() {
    std::lock_guard lock(mutex_);
    return atMax_;
  }
  // ... and those runnable all the while when the most were (maxSustained()).
  std::string atSustainedMax() {
    std::lock_guard lock(mutex_);
    return atSustained_;
  }
  // Samples only while on (the phases that refine), and sleeps without a timer while off, so the
  // CPU measured at rest does not include the sampler.
  void setOn(bool on) {
    {
      std::lock_guard lock(mutex_);
      on_ = on;
    }
    wake_.notify_all();
  }

 private:
  struct Runnable {
    std::string name;
    long voluntarySwitches = -1;  // the times it went to sleep so far
  };
  // The process's own threads (not the driver's) that are runnable now, by id, with their names.
  std::map<std::string, Runnable> runnableNow(const std::string& self, int& driver) {
    std::map<std::string, Runnable> runnable;
    std::error_code ec;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
      if (task.path().filename() == self) continue;
      // One read gives the name, the state and the count of sleeps together.
      std::ifstream status(task.path() / "status");
      std::string line, name;
      bool isRunnable = false;
      long voluntary = -1;
      while (std::getline(status, line)) {
        if (line.rfind("Name:\t", 0) == 0)
          name = line.substr(6);
        else if (line.rfind("State:\t", 0) == 0)
          isRunnable = line.size() > 7 && line[7] == 'R';
        else if (line.rfind("voluntary_ctxt_switches:", 0) == 0)
          voluntary = std::stol(line.substr(24));
      }
      if (!isRunnable) continue;
      const std::string id = task.path().filename().string();
      if (name.rfind("llvmpipe-", 0) == 0 || foreign_.count(id) != 0)
        ++driver;
      else
        runnable[id] = {name, voluntary};
    }
    return runnable;
  }
  void sample(const std::string& self) {
    int driver = 0, driverLater = 0;
    const std::map<std::string, Runnable> first = runnableNow(self, driver);
    // The tasks are read one after another, not at one instant, and this thread can be preempted
    // between two reads: threads runnable in one reading were not always runnable at once (a core
    // handed from one worker to another shows both). A thread runnable in two readings a
    // millisecond apart that did not go to sleep between them (its count of voluntary switches
    // is the same) was runnable all the while, so all those threads were runnable at once from
    // the end of the first reading to the start of the second: at least a millisecond.
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const std::map<std::string, Runnable> second = runnableNow(self, driverLater);
    int sustained = 0;
    std::map<std::string, int> names, sustainedNames;  // the process's own runnable threads by name
    for (const auto& [id, thread] : first) {
      ++names[thread.name];
      const auto later = second.find(id);
      if (later != second.end() && later->second.voluntarySwitches == thread.voluntarySwitches) {
        ++sustained;
        ++sustainedNames[thread.name];
      }
    }
    const int runnable = static_cast<int>(first.size());
    const auto describe = [](const std::map<std::string, int>& byName) {
      std::string text;
      for (const auto& [name, count] : byName) text += (text.empty() ? "" : " ") + name + "×" + std::to_string(count);
      return text;
    };
    {
      std::lock_guard lock(mutex_);
      if (sustained > maxSustained_.load()) atSustained_ = describe(sustainedNames);
      maxSustained_ = std::max(maxSustained_.load(), sustained);
      if (sustained > phaseMaxSustained_) {
        phaseMaxSustained_ = sustained;
        phaseAtSustained_ = describe(sustainedNames);
      }
    }
    {
      std::lock_guard lock(mutex_);
      if (runnable > max_.load() || runnable > phaseMax_) {
        const std::string text = describe(names);
        if (runnable > max_.load()) atMax_ = text;
        if (runnable > phaseMax_) {
          phaseMax_ = runnable;
          phaseAtMax_ = text;
        }
      }
    }
    max_ = std::max(max_.load(), runnable);
    maxDriver_ = std::max(maxDriver_.load(), driver);
  }
  void run(std::stop_token stop) {
    const std::string self = std::to_string(::syscall(SYS_gettid));
    std::unique_lock lock(mutex_);
    while (!stop.stop_requested()) {
      if (!on_) {
        wake_.wait(lock, stop, [&] { return on_; });
        continue;
      }
      lock.unlock();
      sample(self);
      lock.lock();
      // A measurement, not an event to wait for: sampling is periodic by nature.
      wake_.wait_for(lock, stop, std::chrono::milliseconds(5), [&] { return !on_; });
    }
  }
  const std::set<std::string> foreign_;
  std::atomic<int> max_{0}, maxDriver_{0}, maxSustained_{0};
  std::mutex mutex_;
  std::condition_variable_any wake_;
  bool on_ = false;                  // guarded by mutex_
  std::string atMax_, atSustained_;  // guarded by mutex_
  int phaseMax_ = 0;                 // guarded by mutex_, like the three below
  int phaseMaxSustained_ = 0;
  std::string phaseAtMax_, phaseAtSustained_;
  std::jthread thread_;  // last: started after everything it uses
};

// Mean, 95th percentile and worst frame over a run of frames: a mean hides a few long frames
// that a user feels as stutter.
struct FrameTimes {
  double total = 0.0, worst = 0.0;
  int frames = 0;
  std::vector<double> all;
  // The resolve (finishing the picture on the GPU and drawing it) within those frames, and the
  // rows marched: how much of a frame the finish takes beside the march.
  double resolveTotal = 0.0, uploadTotal = 0.0, scaleTotal = 0.0;
  double rowsTotal = 0.0, targetRowsTotal = 0.0;
  void add(double ms, const app::LiveView& view, const app::ExplorerState& state) {
    uploadTotal += state.frame.metrics.uploadMs;
    scaleTotal += state.frame.metrics.marchScale;
    total += ms;
    worst = std::max(worst, ms);
    ++frames;
    all.push_back(ms);
    resolveTotal += view.resolveMs();
    rowsTotal += view.marchedRows();
    targetRowsTotal += view.targetRows();
  }
  double mean() const { return total / std::max(1, frames); }
  double meanResolve() const { return resolveTotal / std::max(1, frames); }
  double meanUpload() const { return uploadTotal / std::max(1, frames); }
  double meanScale() const { return scaleTotal / std::max(1, frames); }
  double resolveShare() const { return total > 0.0 ? resolveTotal / total : 0.0; }
  // The share of the march target's rows a frame marched, on average.
  double marchedShare() const { return targetRowsTotal > 0.0 ? rowsTotal / targetRowsTotal : 0.0; }
  // The frame time 95% of the frames stay at or under (nearest rank).
  double p95() const {
    if (all.empty()) return 0.0;
    std::vector<double> sorted = all;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
  }
};

template <typename Each>
FrameTimes timeFrames(FrameLoop& loop, int frames, double maxMs, Each each) {
  FrameTimes times;
  const auto start = Clock::now();
  for (int i = 0; i < frames && millisecondsSince(start) < maxMs; ++i) {
    each(i);
    const auto frameStart = Clock::now();
    loop.run();
    times.add(millisecondsSince(frameStart), loop.view, loop.state);
  }
  return times;
}

// A 1% nudge of the first number a slider would move, whatever the first layer's kind.
// As a slider would: changes layer 0's first parameter and reports the edit to the document.
void nudgePattern(app::Document& document, double factor) {
  document.edited(core::Affects::Pattern);
  core::PatternLayer& layer = document.scene.layers[0];
  if (layer.kind == core::PatternKind::Flame)
    layer.flame.xforms[0].affine.m[0] *= factor;
  else if (layer.kind == core::PatternKind::QuaternionJulia)
    layer.julia.c.x *= factor;
  else
    layer.params[0] *= factor;
}

// Edit → first frame showing it (the proxy, for large grids) and → the full grid showing it.
struct EditLatencies {
  std::vector<double> ms, frames, fullMs;
};

EditLatencies measureEdits(FrameLoop& loop, app::ExplorerSession& session, int edits) {
  EditLatencies result;
  for (int change = 0; change < edits; ++change) {
    nudgePattern(loop.state.document, change % 2 ? 1.0 / 1.01 : 1.01);
    const auto changed = Clock::now();
    const std::uint32_t firstFrame = loop.view.frameCount();
    const std::uint64_t post = session.status().requestedGeneration + 1;  // the next frame posts it
    bool shown = false;
    while (millisecondsSince(changed) < 60'000) {
      const app::LiveFrame frame = loop.run();
      if (!frame.newVolumeShown || frame.shownPost != post) continue;
      if (!shown) {
        shown = true;
        result.ms.push_back(millisecondsSince(changed));
        result.frames.push_back(loop.view.frameCount() - firstFrame);
      }
      if (frame.fullShown) break;
    }
    if (!shown) {
      result.ms.push_back(millisecondsSince(changed));
      result.frames.push_back(loop.view.frameCount() - firstFrame);
    }
    result.fullMs.push_back(millisecondsSince(changed));
  }
  for (auto* values : {&result.ms, &result.frames, &result.fullMs}) std::sort(values->begin(), values->end());
  return result;
}

// The explorer once its volume has converged: the noise target is set a little below the current
// estimate, the frame loop runs as the window's does (it waits instead of drawing when
// app::frameWaitSeconds says so), and the process's CPU time over a few seconds of rest is
// measured. Returns {seconds to converge, CPU percent of one core at rest, noise}; -1 when it
// did not converge within a minute.
std::array<double, 3> cpuAtRest(app::ExplorerSession& session, FrameLoop& loop) {
  const double noise = session.status().noise;
  if (!(noise > 0.0)) return {-1.0, -1.0, -1.0};
  loop.state.services.settings.refineUntilNoisePercent = 100.0 * 0.9 * noise;
  int restingFrames = 0;
  auto step = [&] {
    loop.state.frame.session = session.status();
    const double wait = app::frameWaitSeconds(loop.state, loop.view.resting(), restingFrames);
    if (wait > 0.0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));  // glfwWaitEventsTimeout, no input
      if (!loop.state.frame.view.waitingForPoints) return;               // frames between points pictures draw after it
    }
    loop.run();
    restingFrames = loop.view.resting() && loop.state.frame.session.resting ? restingFrames + 1 : 0;
  };
  const auto start = Clock::now();
  while (restingFrames < 3 && millisecondsSince(start) < 60'000) step();
  if (restingFrames < 3) return {-1.0, -1.0, -1.0};
  const double converged = millisecondsSince(start) / 1000.0;
  const double cpuStart = cpuSeconds(RUSAGE_SELF);
  const auto restStart = Clock::now();
  while (millisecondsSince(restStart) < 3000.0) step();
  const double cpu = cpuSeconds(RUSAGE_SELF) - cpuStart;
  return {converged, 100.0 * cpu / (millisecondsSince(restStart) / 1000.0), session.status().noise};
}

}  // namespace

// The explorer's numbers at 192³, 256³ and 512³: edit → first frame (frames and ms) and → the
// first full-resolution image, mean and worst frame while a slider drags the pattern, while the
// camera orbits and while a still view refines, and the memory the session holds.
// Typing into the real explorer under Xvfb: how long after xdotool starts typing a 16-character
// string the whole of it is in a field on screen (the explorer's --input-log says when the frame
// showing it was drawn). The goal is 0.5 s; typing itself (xdotool's 12 ms between keys) is
// about 0.2 s of it. Measured while the default preset refines and again once it rests.
nlohmann::json measureTyping() {
  constexpr const char* kTyped = "sprott quadratic";
  nlohmann::json result = {{"bench", "explorer"}, {"measurement", "typing"}, {"typed", kTyped}, {"goal_s", 0.5}};
  if (!haveXvfbAndXdotool()) {
    result["skipped"] = "needs Xvfb and xdotool (the setup script installs them)";
    return result;
  }
  XvfbServer server("1280x800x24");
  if (!server.running()) {
    result["skipped"] = "Xvfb did not start";
    return result;
  }
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("voxflame-bench-typing-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::filesystem::path log = folder / "typed.log";
  {
    BackgroundExplorer explorer(server, std::filesystem::read_symlink("/proc/self/exe"), folder,
                                {"--input-log", log.string(), "--width", "1280", "--height", "800"});
    if (!explorer.started() || server.xdotool(kFindExplorerWindow) != 0) {
      result["skipped"] = "the explorer's window did not show: " + explorer.output();
      std::filesystem::remove_all(folder);
      return result;
    }
    // The seconds from the start of typing to the frame that shows the whole string; -1 when it
    // did not show within 10 s.
    const auto typeOnce = [&](double& typingSeconds) {
      // Ctrl+F puts the keyboard in the attractor filter; Ctrl+A and BackSpace empty it.
      server.xdotool(std::string(kFindExplorerWindow) +
                     " windowfocus --sync key ctrl+f sleep 0.3 key ctrl+a BackSpace");
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      const auto start = Clock::now();
      server.xdotool(std::string("type --delay 12 '") + kTyped + "'");
      typingSeconds = secondsSince(start);
      const double startSeconds = std::chrono::duration<double>(start.time_since_epoch()).count();
      while (secondsSince(start) < 10.0) {
        std::ifstream in(log);
        for (std::string line; std::getline(in, line);) {
          const std::size_t space = line.find(' '), tab = line.find('\t');
          if (space == std::string::npos || tab == std::string::npos || tab < space) continue;
          const double shownAt = std::stod(line.substr(0, space));
          if (shownAt >= startSeconds && line.substr(space + 1, tab - space - 1) == "attractor filter" &&
              line.substr(tab + 1) == kTyped)
            return shownAt - startSeconds;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      std::ifstream in(log);
      std::string last;
      for (std::string line; std::getline(in, line);) last = line;
      result["last_logged_when_missed"] = last;  // what the field held instead, to see why
      return -1.0;
    };
    // Three times each: from 5 s after the window shows, while the default preset refines (it
    // rests after about 14 s here), and once it has rested for a while (frames wait for input).
    const auto typeThrice = [&](const std::string& when) {
      std::vector<double> shown, typing;
      for (int i = 0; i < 3; ++i) {
        double seconds = 0.0;
        shown.push_back(typeOnce(seconds));
        typing.push_back(seconds);
        std::this_thread::sleep_for(std::chrono::seconds(1));
      }
      const bool missed = std::find(shown.begin(), shown.end(), -1.0) != shown.end();
      result["seconds_to_show_" + when] = shown;
      result["seconds_typing_" + when] = typing;
      result["worst_seconds_to_show_" + when] = missed ? -1.0 : *std::max_element(shown.begin(), shown.end());
    };
    std::this_thread::sleep_for(std::chrono::seconds(5));
    typeThrice("while_refining");
    std::this_thread::sleep_for(std::chrono::seconds(25));
    typeThrice("at_rest");
    server.xdotool("key Escape");
  }
  std::filesystem::remove_all(folder);
  return result;
}

void benchExplorer(const BenchOptions& options) {
  gl::HeadlessContext context;
  const std::set<std::string> libraryThreads = RunnableThreadSampler::threadsBut(std::to_string(::syscall(SYS_gettid)));
  // As the explorer does: software GL refines a still view at a quarter of the pixels.
  const bool software = context.renderer().find("llvmpipe") != std::string::npos;
  const std::vector<int> grids = options.grids.empty() ? std::vector<int>{192, 256, 512} : options.grids;
  for (int resolution : grids) {
    const double baseline = residentMegabytes();
    core::Scene initial = core::defaultScene();
    initial.gridResolution = resolution;
    app::ExplorerSession session;
    RunnableThreadSampler runnable(libraryThreads);
    FrameLoop loop(session, initial, software ? 0.5f : 1.0f);
    // --backend: what refines the large grid (the explorer's "refine on" setting).
    loop.state.services.settings.refinementBackend =
        options.backend == "gpu" ? app::BackendChoice::Gpu : app::BackendChoice::Cpu;
    core::Scene& scene = loop.state.document.scene;
    loop.run();  // posts the scene
    session.waitUntilApplied(600.0);
    // Wait for the full grid, then refine for a while as a user watching would.
    const auto start = Clock::now();
    runnable.setOn(true);
    while (millisecondsSince(start) < 120'000 && !loop.run().fullShown) {
    }
    const FrameTimes refining = timeFrames(loop, 1 << 30, 4000.0, [](int) {});
    const double memory = residentMegabytes() - baseline;
    // Each phase's most runnable threads at once, and which they were.
    nlohmann::json runnableByPhase = nlohmann::json::object();
    const auto endPhase = [&](const char* name) {
      const auto phase = runnable.endPhase();
      runnableByPhase[name] = {{"max_runnable_threads", phase.most},
                               {"max_sustained_runnable_threads", phase.mostSustained},
                               {"runnable_threads_at_max", phase.which},
                               {"runnable_threads_at_sustained_max", phase.whichSustained}};
    };
    endPhase("refining_first");

    // Pattern edits one at a time, each waited for.
    const EditLatencies edits = measureEdits(loop, session, 7);
    endPhase("edits");
    // A slider drag: a small edit every frame; then the camera orbiting; then the still view
    // refining again. The slider (then the view) is held throughout, as the panels tell the view.
    loop.state.frame.interacting = true;
    const FrameTimes dragging =
        timeFrames(loop, 40, 20'000.0, [&](int i) { nudgePattern(loop.state.document, i % 2 ? 1.0 / 1.002 : 1.002); });
    endPhase("dragging");
    const FrameTimes orbiting = timeFrames(loop, 40, 20'000.0, [&](int) {
      scene.camera.azimuthDeg += 2.0;
      loop.state.document.edited(core::Affects::View);
    });
    endPhase("orbiting");
    loop.state.frame.interacting = false;
    const FrameTimes refiningAfter = timeFrames(loop, 1 << 30, 3000.0, [](int) {});
    endPhase("refining");

    // A still exported from the Export panel runs in a child process; the window's frames go on.
    FrameTimes exporting;
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
      while ((loop.state.services.exportStatus = job.poll()).state == app::ExportState::Running) {
        const auto frameStart = Clock::now();
        loop.run();
        exporting.add(millisecondsSince(frameStart), loop.view, loop.state);
      }
      std::filesystem::remove(output);
    }
    if (resolution == 256) endPhase("during_export");
    auto median = [](const std::vector<double>& sorted) { return sorted[sorted.size() / 2]; };
    loop.state.services.exportStatus = app::ExportStatus{};
    runnable.setOn(false);  // sampling costs CPU, which the rest's figure must not include
    const auto [convergeSeconds, cpuPercent, restNoise] = cpuAtRest(session, loop);
    // Each phase's mean, 95th percentile and worst frame, and its resolve's mean and share.
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, times] : {std::pair<const char*, const FrameTimes*>{"refining_first", &refining},
                                      {"dragging", &dragging},
                                      {"orbiting", &orbiting},
                                      {"refining", &refiningAfter},
                                      {"during_export", &exporting}}) {
      phases[name] = {{"frames", times->frames},
                      {"mean_ms", times->mean()},
                      {"p95_ms", times->p95()},
                      {"worst_ms", times->worst},
                      {"mean_resolve_ms", times->meanResolve()},
                      {"resolve_share", times->resolveShare()},
                      {"mean_upload_ms", times->meanUpload()},
                      {"mean_march_scale", times->meanScale()},
                      {"marched_rows_share", times->marchedShare()}};
      if (runnableByPhase.contains(name)) phases[name].update(runnableByPhase[name]);
    }
    phases["edits"] = runnableByPhase["edits"];
    report(options, {{"bench", "explorer"},
                     {"backend", std::string(core::toString(session.status().backend))},
                     {"grid", resolution},
                     {"renderer", context.renderer()},
                     {"render_scale", loop.state.panels.scene.renderScale},
                     {"frame_budget_ms", loop.state.panels.scene.frameBudgetMs},
                     {"mean_frame_ms", refining.mean()},
                     {"p95_frame_ms", refining.p95()},
                     {"worst_frame_ms", refining.worst},
                     {"change_to_frame_ms_median", median(edits.ms)},
                     {"change_to_frame_ms_worst", edits.ms.back()},
                     {"change_to_frame_frames_median", median(edits.frames)},
                     {"change_to_frame_frames_worst", edits.frames.back()},
                     {"change_to_full_ms_median", median(edits.fullMs)},
                     {"change_to_full_ms_worst", edits.fullMs.back()},
                     {"mean_frame_ms_dragging", dragging.mean()},
                     {"p95_frame_ms_dragging", dragging.p95()},
                     {"worst_frame_ms_dragging", dragging.worst},
                     {"mean_frame_ms_orbiting", orbiting.mean()},
                     {"p95_frame_ms_orbiting", orbiting.p95()},
                     {"worst_frame_ms_orbiting", orbiting.worst},
                     {"mean_frame_ms_refining", refiningAfter.mean()},
                     {"p95_frame_ms_refining", refiningAfter.p95()},
                     {"worst_frame_ms_refining", refiningAfter.worst},
                     {"memory_mb", memory},
                     {"estimated_memory_mb",
                      static_cast<double>(app::ExplorerSession::estimatedBytes(session.status().grid)) / 1e6},
                     {"peak_resident_mb", peakResidentMegabytes()},
                     {"frames_during_export", exporting.frames},
                     {"mean_frame_ms_during_export", exporting.mean()},
                     {"p95_frame_ms_during_export", exporting.p95()},
                     {"worst_frame_ms_during_export", exporting.worst},
                     {"seconds_to_converge", convergeSeconds},
                     {"noise_converged", restNoise},
                     {"cpu_percent_converged", cpuPercent},
                     {"cores", std::max(1u, std::thread::hardware_concurrency())},
                     {"max_runnable_threads", runnable.max()},
                     {"max_sustained_runnable_threads", runnable.maxSustained()},
                     {"max_runnable_gl_driver_threads", runnable.maxDriver()},
                     {"runnable_threads_at_max", runnable.atMax()},
                     {"runnable_threads_at_sustained_max", runnable.atSustainedMax()},
                     {"phases", phases}});
  }
  report(options, measureTyping());
}

}  // namespace voxflame::bench
