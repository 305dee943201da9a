// Double-buffered snapshots of a running Accumulator, taken and packed for upload on a thread of
// their own so the main thread never spends a frame copying the grid: it only swaps in the newest
// finished volume.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

#include "accumulator.h"
#include "packed_volume.h"

namespace voxflame::core {

class SnapshotPublisher {
 public:
  SnapshotPublisher(const Accumulator& accumulator, std::chrono::milliseconds interval);
  ~SnapshotPublisher();  // joins the thread

  // Swaps the newest snapshot into `out` when one newer than `out.version` is ready; never waits
  // for a snapshot in progress. Returns whether `out` changed.
  bool takeIfNewer(PackedVolume& out);
  void requestNow();  // take the next snapshot without waiting for the interval
  // Everything the accumulator holds has been published and taken: nothing new will come until
  // the accumulator adds points again.
  bool caughtUp();

 private:
  void loop(std::stop_token stop);

  const Accumulator& accumulator_;
  std::chrono::milliseconds interval_;
  std::mutex mutex_;  // guards ready_ and readyFresh_
  PackedVolume ready_;
  bool readyFresh_ = false;
  std::atomic<std::uint64_t> publishedVersion_{~std::uint64_t{0}};
  std::mutex wakeMutex_;
  std::condition_variable_any wake_;
  bool wakeRequested_ = false;  // guarded by wakeMutex_
  std::jthread thread_;
};

}  // namespace voxflame::core
