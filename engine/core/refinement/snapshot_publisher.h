// Packed volumes of a running refinement backend (an Accumulator or a GPU one), read and packed for upload on a thread
// of their own so the main thread never spends a frame copying the grid: it only swaps in the newest finished volume,
// handing back the one it had (which the next pack reuses). One buffer here and one with the taker: no other copy of
// the grid exists.
//
// The thread runs on events, not a timer: it sleeps on the accumulator's progress signal until a
// batch lands (or the pattern, hold or target changes), a taker asks, or a volume is taken while
// newer points wait. An accumulator at rest (converged, held, stopped) therefore never wakes it.
// The interval only paces packs while points keep coming: a pack follows the last one by at least
// that long.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "core/refinement/refinement_backend.h"
#include "core/packed_volume.h"
#include "core/progress_signal.h"

namespace voxflame::core {

class SnapshotPublisher {
 public:
  SnapshotPublisher(const RefinementBackend& accumulator, std::chrono::milliseconds interval);
  ~SnapshotPublisher();  // joins the thread

  // Swaps the newest volume into `out` when a fresh one is ready; never waits for a pack in
  // progress (it returns false then). Returns whether `out` changed. Where packs are slow next to
  // the interval, a fresh volume waits for its taker (it is not packed over, so the lock is free)
  // unless the accumulator's pattern changed.
  bool takeIfNewer(PackedVolume& out);
  void requestNow();  // look at the accumulator now, without waiting for progress or the interval
  // A volume of a generation still refining is not packed before it holds this many points (0:
  // any): one that would not be shown is not worth a pack (hundreds of milliseconds at 512³).
  void setMinimumPoints(std::uint64_t points);
  // While held nothing is packed (the user drags: each generation is thrown away at once), and a
  // pack under way stops.
  void setHeld(bool held);
  // Everything the accumulator holds has been published and taken: nothing new will come until
  // the accumulator adds points again.
  bool caughtUp();
  // How often the thread has woken to look at the accumulator (tests: none while it rests).
  std::uint64_t wakeUps() const { return wakeUps_.load(); }
  // How many volumes the thread has packed (each one fresh for takeIfNewer when packed).
  std::uint64_t packs() const { return packs_.load(); }
  // Notified after every look (wakeUps() moved) and every finished pack (packs() moved), so a taker
  // may sleep until there is news instead of polling: tests, and the session's waitForNews. Null
  // (the default): nobody. The observer must outlive the publisher or be replaced first.
  void setObserver(EventCounter* observer) { observer_.store(observer); }

  // After a pack of the pattern refining now, the next waits this many times as long as it took
  // (at least the interval): packs take at most a fifth of a core.
  static constexpr int kPackShare = 5;

 private:
  void loop(std::stop_token stop);

  const RefinementBackend& accumulator_;
  std::chrono::milliseconds interval_;
  std::mutex mutex_;  // guards ready_ and readyFresh_; held while packing
  PackedVolume ready_;
  bool readyFresh_ = false;
  std::chrono::steady_clock::duration lastPack_{};  // how long the last pack held the lock (this thread only)
  std::atomic<std::uint64_t> publishedVersion_{~std::uint64_t{0}};
  std::atomic<std::uint64_t> minimumPoints_{0};
  std::atomic<bool> held_{false};
  // Set, then announced on the accumulator's progress signal (which the thread waits on for
  // events) and on wake_ (which it waits on while pacing packs).
  std::atomic<bool> requested_{false};  // requestNow
  std::atomic<bool> taken_{false};      // a volume was taken while the accumulator had moved on
  std::atomic<std::uint64_t> wakeUps_{0};
  std::atomic<std::uint64_t> packs_{0};
  std::atomic<EventCounter*> observer_{nullptr};
  void tellObserver() {
    if (EventCounter* observer = observer_.load()) observer->notify();
  }
  std::mutex wakeMutex_;
  std::condition_variable_any wake_;
  std::jthread thread_;
};

}  // namespace voxflame::core
