#include "core/refinement/snapshot_publisher.h"

#include <pthread.h>
#include <algorithm>
#include <utility>

namespace voxflame::core {

SnapshotPublisher::SnapshotPublisher(const RefinementBackend& accumulator, std::chrono::milliseconds interval)
    : accumulator_(accumulator), interval_(interval), thread_([this](std::stop_token stop) { loop(stop); }) {}

SnapshotPublisher::~SnapshotPublisher() {
  // The jthread's stop request wakes either wait (both take the stop token).
  thread_.request_stop();
  thread_.join();
}

void SnapshotPublisher::requestNow() {
  requested_ = true;
  { std::lock_guard lock(wakeMutex_); }
  wake_.notify_all();
  accumulator_.progress().notify();
}

bool SnapshotPublisher::takeIfNewer(PackedVolume& out) {
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || !readyFresh_) return false;
  std::swap(out, ready_);
  readyFresh_ = false;
  lock.unlock();
  // A fresh volume may have held back the pack of newer points (slow packs wait for their taker);
  // with the accumulator at rest no batch would wake the thread for them.
  if (publishedVersion_.load() != accumulator_.version()) {
    taken_ = true;
    accumulator_.progress().notify();
  }
  return true;
}

bool SnapshotPublisher::caughtUp() {
  // A pack in progress holds the lock for a while: not caught up, and no reason to wait for it.
  std::unique_lock lock(mutex_, std::try_to_lock);
  return lock.owns_lock() && !readyFresh_ && publishedVersion_.load() == accumulator_.version();
}

void SnapshotPublisher::setMinimumPoints(std::uint64_t points) {
  minimumPoints_ = points;
}

void SnapshotPublisher::setHeld(bool held) {
  if (held_.exchange(held) && !held) requestNow();
}

void SnapshotPublisher::loop(std::stop_token stop) {
  // Named for top, perf and the runnable-thread count of `bench explorer`.
  pthread_setname_np(pthread_self(), "vf-publish");
  markBatchThread();
  bool waitingForPoints = false;
  // The accumulator's version when the thread last looked. Version 0 is an accumulator that never
  // had a pattern: nothing to pack until it moves (one that has one is looked at straight away).
  std::uint64_t seen = 0;
  std::chrono::steady_clock::time_point lastLook{};
  std::uint64_t packedGeneration = 0;  // the generation of the last pack
  while (!stop.stop_requested()) {
    // Points keep coming (a notification a batch): the looks are paced by the interval, or more
    // often while a new generation is waiting for its minimum. The pause comes first, on a timer
    // of this thread's own: a pause after a batch's notification has every batch wake the thread
    // only to put it to sleep again, and on a busy machine each such wake-up queues for a core (a
    // runnable thread beside the workers'). A request cuts the pause short.
    if (!requested_.load()) {
      std::chrono::steady_clock::duration pace =
          waitingForPoints ? std::min(interval_, std::chrono::milliseconds(10)) : interval_;
      // Packs of the pattern that refines now take at most a fifth of a core: at 256³ a pack takes
      // tens of milliseconds, and packing every interval took the cores the refinement needs (with
      // the shadow volume recomputed for each volume). A new pattern's first pack is not held back
      // (its requestNow ends the pause).
      if (packedGeneration == accumulator_.generation()) pace = std::max(pace, kPackShare * lastPack_);
      std::unique_lock lock(wakeMutex_);
      wake_.wait_until(lock, stop, lastLook + pace, [&] { return requested_.load(); });
    }
    // Then sleep until there is something to look at: no timer runs while the accumulator rests
    // (the pause above ends once after the last look, then this waits without one).
    if (!accumulator_.progress().wait(
            stop, [&] { return requested_.load() || taken_.load() || accumulator_.version() != seen; }))
      break;
    requested_ = false;
    taken_ = false;
    ++wakeUps_;
    lastLook = std::chrono::steady_clock::now();
    seen = accumulator_.version();
    tellObserver();  // the look (wakeUps) is news too: a waiter may count looks that packed nothing
    if (stop.stop_requested()) break;
    waitingForPoints = false;
    if (held_) continue;
    if (seen == publishedVersion_.load()) continue;
    // A pattern just set has no points yet: a volume of none would only show nothing (and keep a
    // taker from the first real one until the next look), so at least one point is waited for.
    if (const std::uint64_t minimum = std::max<std::uint64_t>(minimumPoints_.load(), 1); minimum > 0) {
      const AccumulatorStats stats = accumulator_.stats();
      if (stats.points < minimum && !stats.done && stats.problem.empty()) {
        waitingForPoints = true;
        continue;
      }
    }
    if (lastPack_ > interval_ / 10) {
      // A fresh volume of the pattern refining now waits for its taker when packs are slow: packed
      // over, the lock the taker needs would be held most of the time (at 512³ a pack takes longer
      // than the interval), and a taker that comes once a frame would rarely find a volume (the
      // first full image of an edit came up to a second late). Quick packs (the proxy's) go on, so
      // the taker gets the newest. One of an older pattern is always packed over.
      std::lock_guard lock(mutex_);
      if (readyFresh_ && ready_.generation == accumulator_.generation()) continue;
    }
    // Packed in place, under the lock: a second buffer to pack into while the last one waits
    // would cost a whole volume of memory (400 MB at 512³), and a taker that finds the lock held
    // simply takes the volume on a later frame. What it hands back in the swap is packed into next.
    // A hold that begins meanwhile (the user starts dragging) stops the pack at the next slab.
    // A pack keeps a core busy like a worker: where the workers share a budget it takes a core of
    // it, so a pack does not add a runnable thread beside every worker's. Taken before the lock, so
    // a taker never finds the lock held by a pack that waits for a core. It goes when its
    // accumulator's workers would: the proxy's burst shows through its packs.
    {
      const HeldCore core(accumulator_.coreBudget(), accumulator_.coresFirst());
      std::lock_guard lock(mutex_);
      const auto packStart = std::chrono::steady_clock::now();
      readyFresh_ = packVolume(accumulator_, ready_, &held_);
      lastPack_ = std::chrono::steady_clock::now() - packStart;
      packedGeneration = ready_.generation;
      if (readyFresh_) {
        publishedVersion_ = ready_.version;
        ++packs_;
      }
    }
    // Once the lock and the core are free: a waiter woken by the news takes the volume at once
    // (takeIfNewer never waits for the lock).
    tellObserver();
  }
}

}  // namespace voxflame::core
