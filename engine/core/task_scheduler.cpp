#include "task_scheduler.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_scheduler_observer.h>
#include <pthread.h>

namespace voxflame::core {

namespace {

int hardwareThreads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Names oneTBB's workers as they join an arena, so that top, perf and the runnable-thread count
// of `bench explorer` tell them from the process's other threads.
class WorkerNamer : public tbb::task_scheduler_observer {
 public:
  explicit WorkerNamer(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) { observe(true); }
  ~WorkerNamer() override { observe(false); }
  void on_scheduler_entry(bool isWorker) override {
    if (isWorker) pthread_setname_np(pthread_self(), "vf-task");
  }
};

// The arena is replaced, never changed in place, when the cap changes: a loop running on the old
// one keeps it alive through its shared_ptr until it returns.
struct Arena {
  std::mutex mutex;
  std::shared_ptr<tbb::task_arena> arena;
  std::shared_ptr<WorkerNamer> namer;  // observes `arena`
  int threads = 0;
  // Arenas replaced by a new cap, kept with their namers still observing. oneTBB frees an
  // observer's record only once no worker is looking at it, which may be after the process has
  // exited; kept observing, the record stays reachable instead of showing up as a leak.
  std::vector<std::pair<std::shared_ptr<tbb::task_arena>, std::shared_ptr<WorkerNamer>>> retired;
};

// Never destroyed, for the same reason: its namer would stop observing during the process's exit.
Arena& arena() {
  static Arena* const instance = new Arena;
  return *instance;
}

[[maybe_unused]] std::shared_ptr<tbb::task_arena> currentArena() {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  if (!a.arena) {
    if (a.threads <= 0) a.threads = hardwareThreads();
    a.arena = std::make_shared<tbb::task_arena>(a.threads);
    a.arena->initialize();
    a.namer = std::make_shared<WorkerNamer>(*a.arena);
  }
  return a.arena;
}

}  // namespace

#if defined(__SANITIZE_THREAD__)
// ThreadSanitizer cannot see oneTBB's own synchronisation (Debian's libtbb is not instrumented),
// so it would report every loop body as racing with the code around the loop. Under it a loop
// runs on threads of its own instead, whose start and join it does see: the same bodies over
// ranges of the grain, taken in turn by no more threads than the cap, checked in full.
void parallelFor(std::size_t count, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& fn) {
  if (count == 0) return;
  grain = std::max<std::size_t>(1, grain);
  const std::size_t chunks = (count + grain - 1) / grain;
  const std::size_t threads = std::min<std::size_t>(chunks, static_cast<std::size_t>(std::max(1, taskConcurrency())));
  if (threads == 1) {
    fn(0, count);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(threads);
  auto run = [&](std::size_t thread) {
    try {
      for (std::size_t chunk = next++; chunk < chunks; chunk = next++)
        fn(chunk * grain, std::min(count, (chunk + 1) * grain));
    } catch (...) {
      errors[thread] = std::current_exception();
      next = chunks;  // the others stop after the range they are in
    }
  };
  {
    std::vector<std::jthread> workers;
    for (std::size_t thread = 1; thread < threads; ++thread) workers.emplace_back(run, thread);
    run(0);
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}
#else
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

#endif

void setTaskConcurrency(int threads) {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  const int wanted = threads > 0 ? threads : hardwareThreads();
  if (wanted == a.threads && a.arena) return;
  a.threads = wanted;
  if (a.arena) a.retired.emplace_back(std::move(a.arena), std::move(a.namer));
  a.arena.reset();  // made afresh with the new cap on the next call
  a.namer.reset();
}

int taskConcurrency() {
  Arena& a = arena();
  std::lock_guard lock(a.mutex);
  return a.threads > 0 ? a.threads : hardwareThreads();
}

}  // namespace voxflame::core
