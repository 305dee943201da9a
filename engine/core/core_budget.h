// A CoreBudget is cores that several busy threads share: the workers of the explorer's grid and of
// its proxy, and their snapshot packs. Each holds a core while it works (a batch, a pack) and waits
// for one, asleep, otherwise, so together they keep no more threads runnable than the budget.
//
// Not std::counting_semaphore: libstdc++'s release() wakes every waiter, and on a busy machine
// all of them then queue for a core just to find the one token taken. Here a release wakes one:
// a thread that goes first (the proxy's, whose burst is what the next frame shows) if one waits,
// for a freed core is then its own before any other waiter's; otherwise one of the others.
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
      firstFreed_.wait(lock, [&] { return free_ > 0; });
      --firstWaiting_;
    } else {
      othersFreed_.wait(lock, [&] { return free_ > 0 && firstWaiting_ == 0; });
    }
    --waiting_;
    --free_;
    // A core is still free (several were released at once): pass it on, or the next waiter of the
    // other kind would sleep beside an idle core.
    if (free_ > 0) wakeOne();
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
    std::lock_guard lock(mutex_);
    ++free_;
    wakeOne();
  }

 private:
  // Wakes the one waiter the freed core is for: a first one if any waits, else another. Each kind
  // sleeps on its own condition, so a release never wakes a thread that would only sleep again
  // (with one condition and notify_all, every waiter became runnable on each release while a
  // proxy waited: four accumulator threads queued for two cores). Called with mutex_ held.
  void wakeOne() {
    if (firstWaiting_ > 0)
      firstFreed_.notify_one();
    else if (waiting_ > 0)
      othersFreed_.notify_one();
  }

  std::mutex mutex_;
  std::condition_variable firstFreed_;   // waited on by the threads that go first
  std::condition_variable othersFreed_;  // by all the others
  int free_;                             // guarded by mutex_, like the count below
  int firstWaiting_ = 0;                 // threads waiting that go first
  int waiting_ = 0;                      // all threads waiting
};

}  // namespace voxflame::core
