#include "explorer_session.h"

#include <pthread.h>
#include <algorithm>
#include <cmath>
#include <new>
#include <thread>
#include <utility>

#include "core/error.h"
#include "core/mask_cache.h"
#include "core/refinement/accumulator.h"
#include "core/refinement/snapshot_publisher.h"
#include "core/scene_io.h"
#include "core/scene_schema.h"
#include "pipeline.h"
#include "refinement_backends.h"

namespace voxflame::app {

namespace {

// The most points any grid refines to (the hit counts of a voxel have 31 bits).
constexpr std::uint64_t kExplorerTargetPoints = 4'000'000'000;

// What decides the shape: the mesh file and the grid over it.
std::string shapeKey(const core::Scene& scene) {
  return scene.resolvedMeshPath().string() + (scene.embedded ? "|embedded|" : "|file|") +
         std::to_string(scene.gridResolution);
}

std::string gridText(const core::GridGeometry& grid) {
  return std::to_string(grid.size.x) + "×" + std::to_string(grid.size.y) + "×" + std::to_string(grid.size.z);
}

int resolvedThreads(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

std::size_t ExplorerSession::estimatedBytes(const core::GridGeometry& grid) {
  auto gridBytes = [](const core::GridGeometry& g) {
    // A byte a voxel of mask; the accumulator; two packed volumes (the snapshot thread's and the
    // live view's) and the textures that mirror them.
    return g.voxelCount() + core::accumulatorBytes(g) + 3 * core::packedVolumeBytes(g);
  };
  std::size_t bytes = gridBytes(grid);
  if (std::max({grid.size.x, grid.size.y, grid.size.z}) > kProxyAbove)
    bytes += gridBytes(core::gridOverBox(grid.box(), kProxyResolution));
  // Shadows: a byte per 2³ voxels, computed on the CPU and uploaded. Then what does not grow with
  // the grid: the live view's frame buffers and the renderer's programs (about 40 MB measured
  // with a 1280×720 view).
  constexpr std::size_t kViewBytes = std::size_t{40} << 20;
  return bytes + 2 * grid.voxelCount() / 8 + kViewBytes;
}

struct ExplorerSession::Proxy {
  // Snapshots of the proxy come quickly: each costs well under a millisecond at 64³.
  static constexpr std::chrono::milliseconds kInterval{15};
  Proxy(std::shared_ptr<const core::InsideMask> insideMask, int threads, std::shared_ptr<core::CoreBudget> cores)
      : mask(std::move(insideMask)),
        backend(makeBackend(core::BackendKind::Cpu, mask, threads, std::move(cores))),
        accumulator(*backend),
        publisher(accumulator, kInterval) {
    accumulator.setCoresFirst(true);  // its burst is what the next frame shows
    const auto inside = static_cast<double>(std::max<std::uint64_t>(accumulator.insideVoxels(), 1));
    targetPoints = static_cast<std::uint64_t>(kProxyPointsPerVoxel * inside);
    dragTargetPoints = static_cast<std::uint64_t>(kProxyDragPointsPerVoxel * inside);
    accumulator.setTargetPoints(targetPoints);
    publisher.setMinimumPoints(static_cast<std::uint64_t>(kProxyShownPointsPerVoxel * inside));
  }
  // The burst of each pattern, and the smaller one while the user drags.
  std::uint64_t targetPoints = 0, dragTargetPoints = 0;
  void setDragging(bool dragging) { accumulator.setTargetPoints(dragging ? dragTargetPoints : targetPoints); }
  std::shared_ptr<const core::InsideMask> mask;
  // The CPU's, whatever refines the large grid: a burst of tens of milliseconds on 64³ is over
  // before a GPU dispatch would have been set up.
  std::unique_ptr<core::RefinementBackend> backend;
  core::RefinementBackend& accumulator;
  core::SnapshotPublisher publisher;
  std::uint64_t patternGeneration = 0;
  std::uint64_t patternPost = 0;
};

struct ExplorerSession::Engine {
  Engine(std::string key, std::shared_ptr<const core::InsideMask> insideMask,
         std::shared_ptr<const core::InsideMask> proxyMask, int threads, std::chrono::milliseconds interval,
         core::BackendKind kind, gl::ShareGroup renderer)
      : shapeKey(std::move(key)),
        mask(std::move(insideMask)),
        // The proxy's burst and the large grid run at once after each edit: they share the cores
        // rather than each keeping a worker runnable per core (twice the cores queueing).
        cores(proxyMask ? std::make_shared<core::CoreBudget>(resolvedThreads(threads)) : nullptr),
        proxy(proxyMask ? std::make_unique<Proxy>(std::move(proxyMask), threads, cores) : nullptr),
        backend(makeBackend(kind, mask, threads, cores, renderer)),
        accumulator(*backend),
        publisher(accumulator, interval) {
    initialCapPoints = std::clamp<std::uint64_t>(
        static_cast<std::uint64_t>(restCapPointsPerVoxel(mask->geometry, accumulator.insideVoxels()) *
                                   static_cast<double>(std::max<std::uint64_t>(accumulator.insideVoxels(), 1))),
        1, kExplorerTargetPoints);
    capPoints = initialCapPoints;
    target = capPoints;
    accumulator.setTargetPoints(capPoints);
    // The live view shows the large grid of a pattern once it holds as many points as the proxy;
    // packing it before then is wasted.
    if (proxy) publisher.setMinimumPoints(proxy->targetPoints);
  }
  std::string shapeKey;
  std::shared_ptr<const core::InsideMask> mask;
  std::shared_ptr<core::CoreBudget> cores;  // shared by the two accumulators; null without a proxy
  std::unique_ptr<Proxy> proxy;             // null for grids no larger than a proxy
  // The large grid's refinement backend (core/refinement/refinement_backend.h): the CPU's, or the
  // GPU's (gl::GpuAccumulator) behind the same calls.
  std::unique_ptr<core::RefinementBackend> backend;
  core::RefinementBackend& accumulator;
  core::SnapshotPublisher publisher;    // after the accumulator it reads, so it is destroyed first
  std::uint64_t patternGeneration = 0;  // the Accumulator generation of the latest applied post
  std::uint64_t patternPost = 0;        // ... and that post's number
  core::ConvergenceMeter meter;         // control thread only, like the two below
  core::DensitySample sample;
  std::uint64_t target = kExplorerTargetPoints;  // what the accumulator was last told
  bool held = false;                             // ... and it was a held target (converged or paused)
  // Refinement rests here whatever the noise (restCapPointsPerVoxel); "refine further" raises it,
  // and until `furtherPoints` the noise target does not stop it either.
  std::uint64_t initialCapPoints = kExplorerTargetPoints;
  std::uint64_t capPoints = kExplorerTargetPoints;
  std::uint64_t furtherPoints = 0;
  // The pattern posted while the user dragged, set once the drag ends (control thread only).
  std::optional<core::Scene> deferredScene;
  std::uint64_t deferredPost = 0;
};

ExplorerSession::ExplorerSession(int threads, std::chrono::milliseconds snapshotInterval)
    : threads_(threads),
      snapshotInterval_(snapshotInterval),
      control_([this](std::stop_token stop) { controlLoop(stop); }) {}

ExplorerSession::~ExplorerSession() {
  control_.request_stop();
  wake_.notify_all();
  control_.join();
  // The engine's destructor joins the accumulation and snapshot threads.
}

void ExplorerSession::post(const core::Scene& scene, bool interacting) {
  {
    std::lock_guard lock(mutex_);
    pending_ = scene;
    lastPosted_ = scene;
    ++requested_;
    if (interacting && !interacting_) {
      interacting_ = true;
      steerRequested_ = true;
    }
    if (viewMoving_) {
      viewMoving_ = false;  // the pattern changes too: a grid without a proxy must show it
      steerRequested_ = true;
    }
  }
  wake_.notify_all();
}

bool ExplorerSession::postIfPatternChanged(const core::Scene& scene, bool interacting) {
  if (postedPattern_ && !core::diff(*postedPattern_, scene).pattern()) return false;
  postedPattern_ = scene;
  post(scene, interacting);
  return true;
}

bool ExplorerSession::takeVolumeIfNewer(core::PackedVolume& out, std::uint64_t* reflectsPost) {
  std::lock_guard lock(mutex_);  // held for a swap at most: the publisher never waits either
  if (!engine_ || !engine_->publisher.takeIfNewer(out)) return false;
  if (reflectsPost) *reflectsPost = out.generation == engine_->patternGeneration ? engine_->patternPost : 0;
  return true;
}

bool ExplorerSession::takeProxyIfNewer(core::PackedVolume& out, std::uint64_t* reflectsPost) {
  std::lock_guard lock(mutex_);
  if (!engine_ || !engine_->proxy || !engine_->proxy->publisher.takeIfNewer(out)) return false;
  if (reflectsPost)
    *reflectsPost = out.generation == engine_->proxy->patternGeneration ? engine_->proxy->patternPost : 0;
  return true;
}

bool ExplorerSession::showProxyVolume(const core::PackedVolume& proxy, std::uint64_t reflectsPost) {
  if (reflectsPost <= takeover_.mainPost ||
      static_cast<double>(proxy.points) < kProxyShownPointsPerVoxel * proxy.insideVoxels)
    return false;
  takeover_.shown = ShownGrid::Proxy;
  takeover_.proxyPost = reflectsPost;
  takeover_.proxyPoints = proxy.points;
  takeover_.proxyInsideVoxels = proxy.insideVoxels;
  return true;
}

bool ExplorerSession::uploadMainVolume(const core::PackedVolume& volume, std::uint64_t reflectsPost) const {
  // While the proxy is shown: a volume of its post with fewer points would not replace it, nor
  // would one of an older pattern (0) while the proxy shows a newer one.
  if (takeover_.shown != ShownGrid::Proxy) return true;
  return reflectsPost != 0 ? reflectsPost != takeover_.proxyPost || volume.points >= takeoverPoints()
                           : takeover_.proxyPost <= takeover_.mainPost;
}

bool ExplorerSession::mainVolumeUploaded(const core::PackedVolume& volume, std::uint64_t reflectsPost) {
  // 0 means an older post than the newest applied one: older than any proxy shown since.
  if (reflectsPost != 0) takeover_.mainPost = reflectsPost;
  const std::uint64_t proxyPost = takeover_.proxyPost;
  // The main grid takes over once it shows the proxy's post (or a later one) with at least
  // takeoverPoints(): with voxels no larger than pixels the picture's noise depends on the points
  // per pixel, so it is then as smooth as the proxy and sharper. A proxy of a newer post stays.
  const bool proxyAhead =
      proxyPost != 0 && (reflectsPost == 0 ? proxyPost > takeover_.mainPost : proxyPost > reflectsPost);
  const bool caughtUp =
      reflectsPost != 0 && reflectsPost >= proxyPost && (reflectsPost > proxyPost || volume.points >= takeoverPoints());
  if (proxyAhead || !(caughtUp || proxyPost == 0 || reflectsPost == 0)) return false;
  takeover_.shown = ShownGrid::Main;
  return true;
}

std::uint64_t ExplorerSession::takeoverPoints() const {
  // The proxy's count, but no more than its burst asks for: the last batches of its streams go
  // past that by up to a third, and the large grid's first volume, packed as soon as it holds the
  // burst's count, would otherwise be dropped (hundreds of milliseconds at 512³) for a difference
  // in noise nobody sees.
  const auto burst = static_cast<std::uint64_t>(kProxyPointsPerVoxel * takeover_.proxyInsideVoxels);
  return std::min(takeover_.proxyPoints, burst);
}

std::optional<core::TriangleMesh> ExplorerSession::takeNewMesh() {
  std::lock_guard lock(mutex_);
  return std::exchange(newMesh_, std::nullopt);
}

std::optional<core::GridGeometry> ExplorerSession::geometry() const {
  std::lock_guard lock(mutex_);
  if (!engine_) return std::nullopt;
  return engine_->mask->geometry;
}

std::shared_ptr<const core::InsideMask> ExplorerSession::mask() const {
  std::lock_guard lock(mutex_);
  return engine_ ? engine_->mask : nullptr;
}

SessionStatus ExplorerSession::status() const {
  std::lock_guard lock(mutex_);
  SessionStatus status;
  status.buildingShape = buildingShape_;
  status.shapeStage = shapeStage_;
  if (buildingShape_)
    status.shapeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - shapeStart_).count();
  status.error = error_;
  status.requestedGeneration = requested_;
  status.appliedGeneration = applied_;
  status.hasShape = engine_ != nullptr;
  if (engine_) status.grid = engine_->mask->geometry;
  if (engine_) status.stats = engine_->accumulator.stats();
  status.noise = noise_;
  status.noiseTarget = noiseTarget_;
  status.converged = converged_;
  status.capped = capped_;
  status.lastMeasurement = lastMeasurement_;
  status.previousMeasurement = previousMeasurement_;
  status.pointsPerVoxel = pointsPerVoxel_;
  status.insideVoxels = insideVoxels_;
  status.capPointsPerVoxel = capPointsPerVoxel_;
  status.paused = paused_ && holding_ && !capped_ && !converged_;
  status.escapeNote = escapeNote_;
  status.showingLastBounded = showingLastBounded_;
  if (engine_) {
    status.backend = engine_->backend->kind();
    status.gridOnDevice = engine_->backend->packsOnDevice();
  }
  status.backendNote = backendNote_;
  status.resting = engine_ && holding_ && status.stats.done && !buildingShape_ && !pending_ && !working_ &&
                   !steerRequested_ && engine_->publisher.caughtUp();
  return status;
}

void ExplorerSession::setBackendChoice(BackendChoice choice, core::RenderMethod method) {
  std::lock_guard lock(mutex_);
  if (backendChoice_ == choice && backendMethod_ == method) return;
  backendChoice_ = choice;
  backendMethod_ = method;
  // The next post applies it; the scene being shown is posted again so it applies now.
  if (!pending_ && lastPosted_) {
    pending_ = *lastPosted_;
    ++requested_;
    wake_.notify_all();
  }
}

void ExplorerSession::clearError() {
  std::lock_guard lock(mutex_);
  error_.clear();
}

bool ExplorerSession::waitUntilApplied(double timeoutSeconds) {
  std::unique_lock lock(mutex_);
  return appliedSignal_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds),
                                 [&] { return applied_ == requested_ && !working_; });
}

std::optional<core::AccumulatorStats> ExplorerSession::proxyStats() const {
  std::lock_guard lock(mutex_);
  if (!engine_ || !engine_->proxy) return std::nullopt;
  return engine_->proxy->accumulator.stats();
}

bool ExplorerSession::gridIdle() const {
  std::lock_guard lock(mutex_);
  return engine_ && engine_->accumulator.idle();
}

bool ExplorerSession::waitForNews(std::uint64_t seen, double timeoutSeconds) const {
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeoutSeconds));
  return news_.waitPast(seen, deadline);
}

void ExplorerSession::setRefinement(double noiseTarget, bool paused, bool interacting, bool viewMoving,
                                    std::uint64_t gridPointCap) {
  {
    std::lock_guard lock(mutex_);
    if (noiseTarget == noiseTarget_ && paused == paused_ && interacting == interacting_ && viewMoving == viewMoving_ &&
        gridPointCap == gridPointCap_)
      return;
    gridPointCap_ = gridPointCap;
    noiseTarget_ = noiseTarget;
    paused_ = paused;
    interacting_ = interacting;
    viewMoving_ = viewMoving;
    steerRequested_ = true;
  }
  wake_.notify_all();
}

double ExplorerSession::restCapPointsPerVoxel(const core::GridGeometry& grid, std::uint64_t insideVoxels) {
  const double side = std::max({grid.size.x, grid.size.y, grid.size.z, 1});
  const double thickness = std::cbrt(static_cast<double>(std::max<std::uint64_t>(insideVoxels, 1)));
  const double thicknessFactor = std::clamp(kReferenceThicknessAt192 * (side / 192.0) / thickness, 0.5, 2.0);
  return std::clamp(kRestCapPointsPerVoxel * (192.0 / side) * (192.0 / side) * thicknessFactor, kRestCapMinimum,
                    kRestCapMaximum);
}

void ExplorerSession::refineFurther() {
  {
    std::lock_guard lock(mutex_);
    refineFurtherRequested_ = true;
    steerRequested_ = true;
  }
  wake_.notify_all();
}

bool ExplorerSession::holdsForInteraction(const Engine& engine) const {
  std::lock_guard lock(mutex_);
  return (interacting_ && engine.proxy) || viewMoving_;
}

void ExplorerSession::applyPattern(Engine& engine, const core::Scene& scene, std::uint64_t post) {
  // A new pattern refines afresh: a held target would stop it at the old generation's count, and
  // points asked for by "refine further" were the old pattern's.
  engine.capPoints = engine.initialCapPoints;
  engine.furtherPoints = 0;
  engine.target = engine.capPoints;
  engine.held = false;
  engine.accumulator.setTargetPoints(engine.target);
  // The colour lookup a still makes (pipeline.cpp), so the view's colours are the export's.
  engine.accumulator.setPaletteMode(scene.flat.paletteMode);
  engine.accumulator.setPattern(scene.layers, scene.seed, core::RefinementBackend::WhenEscaping::KeepLastBounded);
  noteEscape(engine.accumulator, scene);
  steer(engine);  // a pause still holds the new pattern (at a preview)
  engine.publisher.requestNow();
  std::lock_guard lock(mutex_);
  engine.patternGeneration = engine.accumulator.generation();
  engine.patternPost = post;
}

namespace {

std::string escapeNoteFor(const std::vector<core::PatternLayer>& lastBounded, const core::Scene& escaping) {
  // One number of the pattern moved (a drag, a typed value): name it and its value, as the slider
  // shows them. The look may have changed too since the last bounded pattern; only the layers count.
  core::Scene base = escaping;
  base.layers = lastBounded;
  const core::SceneDiff changed = core::diff(base, escaping);
  if (changed.paths.size() == 1) {
    const std::string& path = changed.paths.front();
    const core::ValueRef value = core::resolveValue(escaping, path);
    if (value.kind == core::ValueRef::Kind::Number && !value.numbers.empty()) {
      char text[200];
      std::snprintf(text, sizeof text, "escapes at %s = %.5g; showing the last bounded value",
                    path.substr(path.rfind('/') + 1).c_str(), value.numbers.front().get());
      return text;
    }
  }
  return "these parameters escape; showing the last bounded pattern";
}

}  // namespace

void ExplorerSession::noteEscape(const core::RefinementBackend& accumulator, const core::Scene& scene) {
  const core::AccumulatorStats stats = accumulator.stats();
  std::string note;
  if (stats.problem.empty())
    lastBounded_ = scene.layers;  // the layers only: this runs for every edit of a drag
  else if (stats.showingLastBounded && lastBounded_)
    note = escapeNoteFor(*lastBounded_, scene);
  else
    note = stats.problem;
  std::lock_guard lock(mutex_);
  escapeNote_ = std::move(note);
  showingLastBounded_ = stats.showingLastBounded;
}

void ExplorerSession::steer(Engine& engine) {
  const bool interacting = holdsForInteraction(engine);
  double target = 0.0;
  bool paused = false, further = false;
  std::uint64_t gridPointCap = 0;
  {
    std::lock_guard lock(mutex_);
    target = noiseTarget_;
    paused = paused_;
    gridPointCap = gridPointCap_;
    further = std::exchange(refineFurtherRequested_, false);
  }
  const core::AccumulatorStats stats = engine.accumulator.stats();
  std::uint64_t points = stats.points;
  if (further) {
    // From the points already there to twice as many: neither the noise target nor the cap
    // stops it before then (the meter goes on measuring the same generation).
    engine.furtherPoints = std::min(kExplorerTargetPoints, 2 * std::max<std::uint64_t>(points, 1));
    engine.capPoints = std::max(engine.capPoints, engine.furtherPoints);
    engine.held = false;
  }
  engine.accumulator.sampleDensity(engine.sample);
  const double noise = engine.meter.update(engine.sample);
  // The target is reached when two measurements in a row are at or under it (false while either
  // is NaN): a single one may dip under it by chance, or while a flow's orbits dwell in one part
  // of the attractor between two samples.
  const bool converged = target > 0.0 && engine.meter.twoMeasurementsWithin(target) && points >= engine.furtherPoints;
  // "Refine further" goes past a grid cap as it goes past the rest cap.
  const std::uint64_t capPoints =
      gridPointCap > 0 ? std::min(engine.capPoints, std::max(gridPointCap, engine.furtherPoints)) : engine.capPoints;
  const bool capped = points >= capPoints;
  std::uint64_t wanted = capPoints;
  if (converged || paused) {
    // A target already held stays: raising it to the points counted now would send the streams
    // that are behind on another batch each time, and the workers would never quite rest.
    wanted = engine.held            ? engine.target
             : paused && !converged ? std::max(points, kPausedPreviewPoints)
                                    : std::max<std::uint64_t>(points, 1);
    wanted = std::min(wanted, capPoints);
  }
  engine.held = converged || paused;
  engine.accumulator.setHeld(interacting);
  engine.publisher.setHeld(interacting);
  if (engine.proxy) engine.proxy->setDragging(interacting);
  if (wanted != engine.target) {
    engine.target = wanted;
    engine.accumulator.setTargetPoints(wanted);
    engine.publisher.requestNow();  // the last points before the workers stop, or the first after
  }
  const double inside = static_cast<double>(std::max<std::uint64_t>(engine.accumulator.insideVoxels(), 1));
  std::lock_guard lock(mutex_);
  noise_ = noise;
  converged_ = converged;
  capped_ = capped && !converged;
  pointsPerVoxel_ = static_cast<double>(points) / inside;
  insideVoxels_ = engine.accumulator.insideVoxels();
  lastMeasurement_ = engine.meter.lastMeasurement();
  previousMeasurement_ = engine.meter.previousMeasurement();
  capPointsPerVoxel_ = static_cast<double>(capPoints) / inside;
  // The control thread sleeps until it is asked for something once refinement will add nothing.
  // An escaping pattern does not refine at all: nothing to measure until the next edit.
  holding_ = converged || paused || capped || !stats.problem.empty();
}

void ExplorerSession::controlLoop(std::stop_token stop) {
  // Named for top, perf and the runnable-thread count of `bench explorer`.
  pthread_setname_np(pthread_self(), "vf-session");
  std::string failedShapeKey;  // a mesh that failed to load is not retried on every edit
  while (!stop.stop_requested()) {
    core::Scene scene;
    std::uint64_t post = 0;
    {
      std::unique_lock lock(mutex_);
      // While the volume refines the noise is measured every kMeterInterval; once refinement is
      // held (or before there is a volume) this thread sleeps until it is asked for something.
      const auto asked = [&] { return pending_.has_value() || steerRequested_; };
      if (engine_ && !holding_)
        wake_.wait_for(lock, stop, kMeterInterval, asked);
      else
        wake_.wait(lock, stop, asked);
      if (stop.stop_requested()) return;
      steerRequested_ = false;
      if (!pending_) {
        Engine* engine = engine_.get();  // only this thread replaces it
        lock.unlock();
        if (engine) {
          if (engine->deferredScene && !holdsForInteraction(*engine)) {
            const core::Scene deferred = *std::exchange(engine->deferredScene, std::nullopt);
            try {
              applyPattern(*engine, deferred, engine->deferredPost);
            } catch (const core::Error& e) {
              std::lock_guard relock(mutex_);
              error_ = e.what();
            }
          } else {
            steer(*engine);
          }
        }
        news_.notify();  // the status may have changed
        continue;
      }
      scene = std::move(*pending_);
      pending_.reset();
      post = requested_;
      working_ = true;
    }
    std::string error;
    try {
      // The backend is part of what the grid is: another one rebuilds it, as another mesh does.
      BackendChoice choice = BackendChoice::Cpu;
      core::RenderMethod method = core::RenderMethod::Volume;
      {
        std::lock_guard lock(mutex_);
        choice = backendChoice_;
        method = backendMethod_;
      }
      std::string backendNote;
      core::BackendKind kind = core::BackendKind::Cpu;
      try {
        kind = resolveBackend(choice, scene.layers);
      } catch (const core::Error& why) {
        backendNote = std::string(why.what()) + "; refining on the CPU";
      }
      // Under the points method the points are dimmed by the grid in host memory: a GPU backend
      // then reads its grid back rather than handing it to the renderer on the GPU.
      const bool gridForPoints = method == core::RenderMethod::Points && kind == core::BackendKind::Gpu;
      const std::string key =
          shapeKey(scene) + "|" + std::string(core::toString(kind)) + (gridForPoints ? "|read back" : "");
      // Only this thread replaces engine_, so it may use it without the lock; the UI reaches it
      // only under the lock, for calls that never wait.
      Engine* current = engine_.get();
      if (current && current->shapeKey == key) failedShapeKey.clear();  // back on a good mesh
      if ((!current || current->shapeKey != key) && key != failedShapeKey) {
        auto setStage = [&](std::string stage) {
          std::lock_guard lock(mutex_);
          shapeStage_ = std::move(stage);
        };
        {
          std::lock_guard lock(mutex_);
          buildingShape_ = true;
          shapeStart_ = std::chrono::steady_clock::now();
        }
        setStage("loading mesh " + scene.resolvedMeshPath().filename().string() + " …");
        try {
          core::TriangleMesh mesh = core::loadSceneMesh(scene);
          const core::GridGeometry grid = core::gridOverBox(mesh.bounds(), scene.gridResolution);
          checkGridFitsInMemory(grid);
          setStage("building the inside mask on a " + gridText(grid) + " grid …");
          auto mask = std::make_shared<const core::InsideMask>(
              core::cachedInsideMask(mesh, grid, core::MaskMethod::WindingNumber, core::defaultMaskCacheFolder()));
          std::shared_ptr<const core::InsideMask> proxyMask;
          if (std::max({grid.size.x, grid.size.y, grid.size.z}) > kProxyAbove) {
            const core::GridGeometry proxyGrid = core::gridOverBox(mesh.bounds(), kProxyResolution);
            proxyMask = std::make_shared<const core::InsideMask>(core::cachedInsideMask(
                mesh, proxyGrid, core::MaskMethod::WindingNumber, core::defaultMaskCacheFolder()));
          }
          if (stop.stop_requested()) return;
          // The old grid goes before the new one is allocated, so a switch never needs both.
          setStage("allocating the " + gridText(grid) + " grid …");
          std::unique_ptr<Engine> old;
          {
            std::lock_guard lock(mutex_);
            old = std::exchange(engine_, nullptr);
          }
          old.reset();
          std::unique_ptr<Engine> engine;
          try {
            engine = std::make_unique<Engine>(key, mask, proxyMask, threads_, snapshotInterval_, kind,
                                              gridForPoints ? gl::ShareGroup{} : rendererShareGroup());
          } catch (const core::Error& why) {
            if (kind == core::BackendKind::Cpu) throw;
            // No GPU context here after all (or the grid does not fit it): the CPU refines.
            backendNote = std::string(why.what()) + "; refining on the CPU";
            engine = std::make_unique<Engine>(key, std::move(mask), std::move(proxyMask), threads_, snapshotInterval_,
                                              core::BackendKind::Cpu, gl::ShareGroup{});
          }
          engine->publisher.setObserver(&news_);
          if (engine->proxy) engine->proxy->publisher.setObserver(&news_);
          std::lock_guard lock(mutex_);
          engine_ = std::move(engine);
          newMesh_ = std::move(mesh);
          buildingShape_ = false;
          failedShapeKey.clear();
        } catch (...) {
          failedShapeKey = key;
          std::lock_guard lock(mutex_);
          buildingShape_ = false;
          throw;
        }
        current = engine_.get();
      }
      {
        std::lock_guard lock(mutex_);
        backendNote_ = backendNote;
      }
      if (current) {
        // The proxy first: its grid clears in no time and its burst runs while the large grid is
        // cleared, so the edit is on screen long before the large grid has anything to show.
        const bool dragging = holdsForInteraction(*current);
        if (Proxy* proxy = current->proxy.get()) {
          proxy->setDragging(dragging);
          proxy->accumulator.setPaletteMode(scene.flat.paletteMode);
          proxy->accumulator.setPattern(scene.layers, scene.seed,
                                        core::RefinementBackend::WhenEscaping::KeepLastBounded);
          noteEscape(proxy->accumulator, scene);
          proxy->publisher.requestNow();
          std::lock_guard lock(mutex_);
          proxy->patternGeneration = proxy->accumulator.generation();
          proxy->patternPost = post;
        }
        // While the user drags, the large grid of a shape with a proxy holds, and only the last
        // pattern is set on it once the drag ends (steer): each edit's would be thrown away, and
        // setting one costs a probe of the pattern on this thread.
        if (dragging) {
          current->accumulator.setHeld(true);
          current->publisher.setHeld(true);
          current->deferredScene = std::move(scene);
          current->deferredPost = post;
        } else {
          current->deferredScene.reset();
          applyPattern(*current, scene, post);
        }
      }
    } catch (const core::Error& e) {
      error = e.what();
    } catch (const std::bad_alloc&) {
      error = "out of memory: choose a smaller grid resolution";
    }
    std::lock_guard lock(mutex_);
    if (!error.empty())
      error_ = error;
    else if (failedShapeKey.empty())
      error_.clear();
    applied_ = post;
    working_ = false;
    appliedSignal_.notify_all();
    news_.notify();
  }
}

}  // namespace voxflame::app
