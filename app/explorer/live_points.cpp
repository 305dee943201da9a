#include "live_points.h"

#include <pthread.h>

#include <algorithm>
#include <utility>

#include "core/chunk_sums.h"
#include "core/error.h"
#include "core/point_renderer.h"
#include "gl/gpu_accumulator.h"

namespace voxflame::app {

namespace {

// Thrown from the progress callback to end a run that was stopped.
struct Stopped {};

// The picture of `sums` (the chunks so far): densities scaled to the whole count, so the
// brightness is the final picture's, and density estimation's hit counts of the points it holds.
core::DensityImage pictureOf(const core::ImageSums& sums, const LivePointsRequest& request, std::uint64_t target) {
  core::DensityImage image;
  image.width = sums.width;
  image.height = sums.height;
  const double points = static_cast<double>(std::max<std::uint64_t>(sums.points, 1));
  image.hitsPerUnitDensity = core::hitsPerUnitDensity(request.camera, request.mask->geometry, points,
                                                      static_cast<double>(request.volume->insideVoxels), sums.height);
  // Each count stands for a share of D that assumed `target` points (PointProjector::unit).
  const double scale = static_cast<double>(target) / points;
  image.values.resize(sums.counts.size());
  for (std::size_t i = 0; i < sums.counts.size(); ++i)
    image.values[i] = static_cast<float>(core::densityOfCount(sums.counts[i], sums.unit) * scale);
  return image;
}

}  // namespace

struct LivePoints::Run {
  std::mutex mutex;
  core::DensityImage newest;  // guarded by mutex, like the two below
  bool fresh = false;
  LivePointsProgress progress;
  std::atomic<bool> done{false};
};

LivePoints::~LivePoints() {
  stop();
  for (auto& [run, thread] : stopping_) thread.join();
}

void LivePoints::start(LivePointsRequest request) {
  stop();
  joinFinished();
  if (!request.mask || !request.volume || request.width <= 0 || request.height <= 0) return;
  auto run = std::make_shared<Run>();
  run->progress.target = request.scene.points;
  run_ = run;
  thread_ = std::jthread([run, request = std::move(request)](std::stop_token stop) {
    pthread_setname_np(pthread_self(), "vf-points");  // for top, perf and bench explorer's thread count
    const std::uint64_t target = std::max<std::uint64_t>(request.scene.points, 1);
    core::ImageSums total;
    core::PointsPassOptions options;
    options.points = target;
    options.threads = request.threads;
    options.chunks = kChunks;
    options.makeImage = false;
    options.progressInterval = 0.05;
    if (request.backend == core::BackendKind::Gpu)
      options.projectingBackend = [](std::shared_ptr<const core::InsideMask> mask,
                                     const core::PointProjection& projection,
                                     int) { return gl::makeGpuProjectingBackend(std::move(mask), projection); };
    options.progress = [&stop](double) {
      if (stop.stop_requested()) throw Stopped{};
    };
    options.chunkDone = [&](int, const core::ImageSums& sums) {
      if (stop.stop_requested()) throw Stopped{};
      if (total.counts.empty()) total.reset(sums.width, sums.height, sums.unit);
      total.add(sums);
      core::DensityImage picture = pictureOf(total, request, target);
      std::lock_guard lock(run->mutex);
      run->newest = std::move(picture);
      run->fresh = true;
      run->progress.points = total.points;
    };
    try {
      core::projectScenePoints(request.scene, request.mask, *request.volume, request.camera, request.width,
                               request.height, options);
      std::lock_guard lock(run->mutex);
      run->progress.finished = true;
    } catch (const Stopped&) {
    } catch (const core::Error& e) {
      std::lock_guard lock(run->mutex);
      run->progress.error = e.what();
    } catch (const std::exception& e) {  // out of memory for a huge view: the volume picture stays
      std::lock_guard lock(run->mutex);
      run->progress.error = e.what();
    }
    run->done.store(true, std::memory_order_release);
  });
}

void LivePoints::stop() {
  if (!run_) return;
  thread_.request_stop();
  stopping_.emplace_back(std::move(run_), std::move(thread_));
  run_.reset();
  thread_ = std::jthread();
}

void LivePoints::joinFinished() {
  std::erase_if(stopping_, [](auto& entry) {
    if (!entry.first->done.load(std::memory_order_acquire)) return false;
    entry.second.join();
    return true;
  });
}

bool LivePoints::working() const {
  if (run_ && !run_->done.load(std::memory_order_acquire)) return true;
  return std::any_of(stopping_.begin(), stopping_.end(),
                     [](const auto& entry) { return !entry.first->done.load(std::memory_order_acquire); });
}

bool LivePoints::takeIfNewer(core::DensityImage& out) {
  joinFinished();
  if (!run_) return false;
  std::lock_guard lock(run_->mutex);
  if (!run_->fresh) return false;
  std::swap(out, run_->newest);
  run_->fresh = false;
  return true;
}

LivePointsProgress LivePoints::progress() const {
  if (!run_) return {};
  std::lock_guard lock(run_->mutex);
  return run_->progress;
}

}  // namespace voxflame::app
