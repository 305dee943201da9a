// A ProgressSignal is how a producer (the Accumulator) tells threads waiting for its progress
// (the snapshot publishers) that something happened: a batch landed, a pattern was set, a hold or a
// target changed. Waiters sleep on a condition variable with a predicate of their own, so a thread
// that follows an accumulator needs no timer, and one whose accumulator rests is never woken.
//
// notify() is called once per batch by every worker: with nobody waiting it is one atomic load;
// with a waiter, a lock and a notify_all.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stop_token>

namespace voxflame::core {

class ProgressSignal {
 public:
  // Wakes every waiter, who then checks its predicate again. Call it after making the change that
  // the predicates read (an atomic store). The fences on both sides order that store before the
  // count is read here, and a waiter's count before its predicate's reads: either the waiter sees
  // the change or this call sees the waiter (and then takes the mutex it waits under), so no
  // wake-up is lost.
  void notify() {
    std::atomic_thread_fence(std::memory_order_seq_cst);
    if (waiters_.load(std::memory_order_relaxed) == 0) return;
    std::lock_guard lock(mutex_);
    wake_.notify_all();
  }
  // Returns once `ready()` holds (true) or a stop was requested (false). ready() runs under the
  // signal's mutex and must only read atomics (what notify's callers changed).
  template <class Ready>
  bool wait(std::stop_token stop, Ready ready) {
    std::unique_lock lock(mutex_);
    waiters_.fetch_add(1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_seq_cst);
    const bool result = wake_.wait(lock, stop, ready);
    waiters_.fetch_sub(1, std::memory_order_relaxed);
    return result;
  }

 private:
  std::atomic<int> waiters_{0};
  std::mutex mutex_;
  std::condition_variable_any wake_;
};

}  // namespace voxflame::core
