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
  // A pack in progress holds the lock for a while: not caught up, and no reason to wait for it.
  std::unique_lock lock(mutex_, std::try_to_lock);
  return lock.owns_lock() && !readyFresh_ && publishedVersion_.load() == accumulator_.version();
}

void SnapshotPublisher::loop(std::stop_token stop) {
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
    // Packed in place, under the lock: a second buffer to pack into while the last one waits
    // would cost a whole volume of memory (400 MB at 512³), and a taker that finds the lock held
    // simply takes the volume on a later frame. What it hands back in the swap is packed into next.
    std::lock_guard lock(mutex_);
    packVolume(accumulator_, ready_);
    publishedVersion_ = ready_.version;
    readyFresh_ = true;
  }
}

}  // namespace voxflame::core
