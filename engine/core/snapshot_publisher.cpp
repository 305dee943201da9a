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

void SnapshotPublisher::loop(std::stop_token stop) {
  VolumeSnapshot snapshot;
  PackedVolume working;
  std::uint64_t lastVersion = ~std::uint64_t{0};
  while (!stop.stop_requested()) {
    {
      std::unique_lock lock(wakeMutex_);
      wake_.wait_for(lock, stop, interval_, [&] { return wakeRequested_; });
      wakeRequested_ = false;
    }
    if (stop.stop_requested()) break;
    const std::uint64_t version = accumulator_.version();
    if (version == lastVersion) continue;
    accumulator_.snapshot(snapshot);
    packVolume(snapshot, working);
    lastVersion = working.version;
    std::lock_guard lock(mutex_);
    std::swap(working, ready_);
    readyFresh_ = true;
  }
}

}  // namespace voxflame::core
