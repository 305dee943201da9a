// A CoreBudget is cores that several busy threads share: the workers of the explorer's grid and of
// its proxy, and their snapshot packs. Each holds a core while it works (a batch, a pack) and waits
// for one, asleep, otherwise, so together they keep no more threads runnable than the budget.
//
// Not std::counting_semaphore: libstdc++'s release() wakes every waiter, and on a busy machine
// all of them then queue for a core just to find the one token taken. Here a release wakes one.
#pragma once

#include <condition_variable>
#include <mutex>

namespace voxflame::core {

class CoreBudget {
 public:
  explicit CoreBudget(int cores) : free_(cores > 0 ? cores : 1) {}
  void acquire() {
    std::unique_lock lock(mutex_);
    freed_.wait(lock, [&] { return free_ > 0; });
    --free_;
  }
  bool try_acquire() {
    std::lock_guard lock(mutex_);
    if (free_ == 0) return false;
    --free_;
    return true;
  }
  void release() {
    {
      std::lock_guard lock(mutex_);
      ++free_;
    }
    freed_.notify_one();
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  int free_;  // guarded by mutex_
};

}  // namespace voxflame::core
