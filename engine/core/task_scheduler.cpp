#include "task_scheduler.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <thread>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

namespace voxflame::core {

namespace {

int hardwareThreads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// The arena is replaced, never changed in place, when the cap changes: a loop running on the old
// one keeps it alive through its shared_ptr until it returns.
struct Arena {
  std::mutex mutex;
  std::shared_ptr<tbb::task_arena> arena;
  int threads = 0;
};

Arena& arena() {
  static Arena instance;
  return instance;
}

std::shared_ptr<tbb::task_arena> currentArena() {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  if (!a.arena) {
    if (a.threads <= 0) a.threads = hardwareThreads();
    a.arena = std::make_shared<tbb::task_arena>(a.threads);
  }
  return a.arena;
}

}  // namespace

void parallelFor(std::size_t count, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& fn) {
  if (count == 0) return;
  grain = std::max<std::size_t>(1, grain);
  if (count <= grain) {
    fn(0, count);  // no task is worth its hand-off
    return;
  }
  const std::shared_ptr<tbb::task_arena> shared = currentArena();
  shared->execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                      [&](const tbb::blocked_range<std::size_t>& range) { fn(range.begin(), range.end()); });
  });
}

void setTaskConcurrency(int threads) {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  const int wanted = threads > 0 ? threads : hardwareThreads();
  if (wanted == a.threads && a.arena) return;
  a.threads = wanted;
  a.arena.reset();  // made afresh with the new cap on the next call
}

int taskConcurrency() {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  return a.threads > 0 ? a.threads : hardwareThreads();
}

}  // namespace voxflame::core
