// A CoreBudget is cores that several busy threads share: the workers of the explorer's grid and of
// its proxy, and their snapshot packs. Each holds a core while it works (a batch, a pack) and waits
// for one, asleep, otherwise, so together they keep no more threads runnable than the budget.
//
// Not std::counting_semaphore: libstdc++'s release() wakes every waiter, and on a busy machine
// all of them then queue for a core just to find the one token taken. Here a release hands the
// core to one waiter, which wakes owning it: a thread that goes first (the proxy's, whose burst is
// what the next frame shows) if one waits; otherwise one of the others.
#pragma once

#include <pthread.h>
#include <sched.h>

#include <condition_variable>
#include <deque>
#include <mutex>

namespace voxflame::core {

class CoreBudget {
 public:
  explicit CoreBudget(int cores) : free_(cores > 0 ? cores : 1) {}
  // `first`: this thread's work is wanted sooner than the others' (the proxy's burst).
  void acquire(bool first = false) {
    std::unique_lock lock(mutex_);
    // A free core means nobody waits (a release hands its core to a waiter instead of freeing it).
    if (free_ > 0) {
      --free_;
      return;
    }
    waitForHandOff(lock, first);
  }
  // Between two pieces of work of a thread holding a core: the core goes to a waiter that goes
  // before this thread (one that goes first, or any waiter when this one does not), and this thread
  // waits in line for a core handed on. Otherwise it keeps its core and returns at once, so a thread
  // that goes first keeps the cores through its burst.
  void passOn(bool first = false) {
    std::unique_lock lock(mutex_);
    if (firstWaiting_.empty() && (first || othersWaiting_.empty())) return;
    handOn();
    waitForHandOff(lock, first);
  }
  // Threads in acquire() or passOn() now, waiting for a core (for tests).
  int waiting() {
    std::lock_guard lock(mutex_);
    return static_cast<int>(firstWaiting_.size() + othersWaiting_.size());
  }
  bool try_acquire() {
    std::lock_guard lock(mutex_);
    if (free_ == 0) return false;
    --free_;
    return true;
  }
  void release() {
    std::lock_guard lock(mutex_);
    handOn();
  }

 private:
  struct Waiter {
    std::condition_variable handedOn;
    bool hasCore = false;  // guarded by mutex_
  };
  // Gives the core being let go to the longest waiter (one that goes first before the others), or
  // frees it when nobody waits. Handed on, not freed: a freed core would go to whichever thread
  // asks next, most often the releasing thread itself coming back for its next batch before the
  // woken waiter runs; the waiter would then wake only to sleep again, and while it queued for a
  // core it counted as one more runnable thread. Each waiter sleeps on a condition of its own, so
  // only the thread the core is for wakes. Called with mutex_ held.
  void handOn() {
    std::deque<Waiter*>& line = !firstWaiting_.empty() ? firstWaiting_ : othersWaiting_;
    if (line.empty()) {
      ++free_;
      return;
    }
    Waiter* next = line.front();
    line.pop_front();
    next->hasCore = true;
    next->handedOn.notify_one();
  }
  void waitForHandOff(std::unique_lock<std::mutex>& lock, bool first) {
    Waiter self;
    (first ? firstWaiting_ : othersWaiting_).push_back(&self);
    self.handedOn.wait(lock, [&] { return self.hasCore; });
  }

  std::mutex mutex_;
  int free_;                           // guarded by mutex_, like the lines below
  std::deque<Waiter*> firstWaiting_;   // threads that go first, in the order they came
  std::deque<Waiter*> othersWaiting_;  // all the others
};

// Marks the calling thread as batch work (SCHED_BATCH, which needs no privilege): the refinement's
// workers and packs. A batch thread that wakes does not preempt the thread running on its core.
// Handing a core on wakes the next holder, and as a normal thread it preempted the hand-giver
// before that one reached its wait: on a busy machine the giver then queued for milliseconds only
// to go to sleep, one more runnable thread than the budget. Batch threads also leave the frame's
// thread, woken by the GL driver, to preempt them rather than queue behind them.
inline void markBatchThread() {
  sched_param param{};
  param.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_BATCH, &param);  // best effort: a refusal changes nothing
}

// A core of a budget held for a scope (none without a budget).
class HeldCore {
 public:
  HeldCore(CoreBudget* cores, bool first) : cores_(cores) {
    if (cores_) cores_->acquire(first);
  }
  ~HeldCore() {
    if (cores_) cores_->release();
  }
  HeldCore(const HeldCore&) = delete;
  HeldCore& operator=(const HeldCore&) = delete;

 private:
  CoreBudget* cores_;
};

}  // namespace voxflame::core
