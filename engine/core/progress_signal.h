// A ProgressSignal is how a producer (the Accumulator) tells threads waiting for its progress
// (the snapshot publishers) that something happened: a batch landed, a pattern was set, a hold or a
// target changed. Waiters sleep on a condition variable with a predicate of their own, so a thread
// that follows an accumulator needs no timer, and one whose accumulator rests is never woken.
//
// notify() is called once per batch by every worker: with nobody waiting it is one atomic load;
// with a waiter, a lock and a notify_all.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
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
  // The same with a deadline instead of a stop token: false when it passes before ready() holds.
  // For tests and scripted runs, whose waits must fail rather than hang.
  template <class Ready>
  bool waitUntil(std::chrono::steady_clock::time_point deadline, Ready ready) {
    std::unique_lock lock(mutex_);
    waiters_.fetch_add(1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_seq_cst);
    const bool result = wake_.wait_until(lock, deadline, ready);
    waiters_.fetch_sub(1, std::memory_order_relaxed);
    return result;
  }

 private:
  std::atomic<int> waiters_{0};
  std::mutex mutex_;
  std::condition_variable_any wake_;
};

// A ProgressSignal that counts its notifications, for waiters that have no predicate of their own:
// one remembers the count it saw, looks at what it waits for, and sleeps until something happens
// after that (tests and scripted runs waiting on a snapshot thread or a session, see
// SnapshotPublisher::setObserver).
class EventCounter {
 public:
  void notify() {
    count_.fetch_add(1, std::memory_order_seq_cst);
    signal_.notify();
  }
  std::uint64_t count() const { return count_.load(std::memory_order_seq_cst); }
  // Returns once the count differs from `seen` (true), or at `deadline` (false).
  bool waitPast(std::uint64_t seen, std::chrono::steady_clock::time_point deadline) {
    return signal_.waitUntil(deadline, [&] { return count() != seen; });
  }

 private:
  std::atomic<std::uint64_t> count_{0};
  ProgressSignal signal_;
};

}  // namespace voxflame::core
