#include "snapshot_publisher.h"

#include <utility>

namespace voxflame::core {

SnapshotPublisher::SnapshotPublisher(const Accumulator& accumulator, std::chrono::milliseconds interval)
    : accumulator_(accumulator), interval_(interval), thread_([this](std::stop_token stop) { loop(stop); }) {}

SnapshotPublisher::~SnapshotPublisher() {
  thread_.request_stop();
  wake_.notify_all();
}

void SnapshotPublisher::requestNow() {
  {
    std::lock_guard lock(wakeMutex_);
    wakeRequested_ = true;
  }
  wake_.notify_all();
}

bool SnapshotPublisher::takeIfNewer(PackedVolume& out) {
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || !readyFresh_) return false;
  std::swap(out, ready_);
  readyFresh_ = false;
  return true;
}

bool SnapshotPublisher::caughtUp() {
  std::lock_guard lock(mutex_);
  return !readyFresh_ && publishedVersion_.load() == accumulator_.version();
}

void SnapshotPublisher::loop(std::stop_token stop) {
  VolumeSnapshot snapshot;
  PackedVolume working;
  while (!stop.stop_requested()) {
    {
      std::unique_lock lock(wakeMutex_);
      wake_.wait_for(lock, stop, interval_, [&] { return wakeRequested_; });
      wakeRequested_ = false;
    }
    if (stop.stop_requested()) break;
    const std::uint64_t version = accumulator_.version();
    // An accumulator at rest adds nothing: the wake-up costs a load and a compare.
    if (version == publishedVersion_.load()) continue;
    accumulator_.snapshot(snapshot);
    packVolume(snapshot, working);
    std::lock_guard lock(mutex_);
    publishedVersion_ = working.version;
    std::swap(working, ready_);
    readyFresh_ = true;
  }
}

}  // namespace voxflame::core
