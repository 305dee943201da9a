// A CoreBudget is cores that several busy threads share: the workers of the explorer's grid and of
// its proxy, and their snapshot packs. Each holds a core while it works (a batch, a pack) and waits
// for one, asleep, otherwise, so together they keep no more threads runnable than the budget.
//
// Not std::counting_semaphore: libstdc++'s release() wakes every waiter, and on a busy machine
// all of them then queue for a core just to find the one token taken. Here a release wakes one,
// unless a thread that goes first (the proxy's, whose burst is what the next frame shows) waits:
// a freed core is then its own before any other waiter's.
#pragma once

#include <condition_variable>
#include <mutex>

namespace voxflame::core {

class CoreBudget {
 public:
  explicit CoreBudget(int cores) : free_(cores > 0 ? cores : 1) {}
  // `first`: this thread's work is wanted sooner than the others' (the proxy's burst).
  void acquire(bool first = false) {
    std::unique_lock lock(mutex_);
    ++waiting_;
    if (first) {
      ++firstWaiting_;
      freed_.wait(lock, [&] { return free_ > 0; });
      --firstWaiting_;
    } else {
      freed_.wait(lock, [&] { return free_ > 0 && firstWaiting_ == 0; });
    }
    --waiting_;
    --free_;
  }
  // Threads in acquire() now (for tests).
  int waiting() {
    std::lock_guard lock(mutex_);
    return waiting_;
  }
  bool try_acquire() {
    std::lock_guard lock(mutex_);
    if (free_ == 0) return false;
    --free_;
    return true;
  }
  void release() {
    bool firstWaits = false;
    {
      std::lock_guard lock(mutex_);
      ++free_;
      firstWaits = firstWaiting_ > 0;
    }
    // One woken at random could be a waiter that must let a first one go, and would sleep again.
    if (firstWaits)
      freed_.notify_all();
    else
      freed_.notify_one();
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  int free_;              // guarded by mutex_, like the count below
  int firstWaiting_ = 0;  // threads waiting that go first
  int waiting_ = 0;       // all threads waiting
};

}  // namespace voxflame::core
