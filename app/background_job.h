// One job model for the explorer's background work (search, orbit analysis, shadow volumes): a
// std::jthread that runs a piece of work with a stop token and leaves its result in a slot. The
// frame loop only ever asks "is it ready?" and takes the result; it never blocks on the work.
// Cancelling (or destroying the job, as quitting does) requests a stop and joins: the work checks
// its token often enough that this takes milliseconds, never the rest of a search.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <pthread.h>
#include <stop_token>
#include <thread>
#include <utility>

namespace voxflame::app {

template <class Result>
class BackgroundJob {
 public:
  BackgroundJob() = default;
  ~BackgroundJob() { cancel(); }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Runs work(std::stop_token) -> Result on a new thread, cancelling any job still running. The
  // work must own what it reads (capture copies): it may outlive the caller's next frame.
  template <class Work>
  void start(Work work) {
    cancel();
    auto slot = std::make_shared<Slot>();
    slot_ = slot;
    thread_ = std::jthread([slot, work = std::move(work)](std::stop_token stop) mutable {
      pthread_setname_np(pthread_self(), "vf-job");  // for top, perf and bench explorer's thread count
      try {
        slot->result.emplace(work(stop));
      } catch (...) {
        slot->error = std::current_exception();
      }
      {
        std::lock_guard lock(slot->mutex);  // so waitUntilReady cannot miss the notification
        slot->ready.store(true, std::memory_order_release);
      }
      slot->finished.notify_all();
    });
  }

  // Started and its result not yet taken (it may be finished).
  bool busy() const { return slot_ != nullptr; }
  bool ready() const { return slot_ && slot_->ready.load(std::memory_order_acquire); }

  // Blocks until the work has finished (true; also when nothing was started) or `timeout` passes
  // (false). For tests and scripted runs: the frame loop never waits.
  bool waitUntilReady(std::chrono::duration<double> timeout) const {
    if (!slot_) return true;
    std::unique_lock lock(slot_->mutex);
    return slot_->finished.wait_for(lock, timeout, [&] { return slot_->ready.load(std::memory_order_acquire); });
  }

  // The result once the work has finished (rethrowing what it threw), else nothing. Never waits:
  // the thread has already returned when `ready` is set, so the join is immediate.
  std::optional<Result> take() {
    if (!ready()) return std::nullopt;
    thread_.join();
    const std::shared_ptr<Slot> slot = std::exchange(slot_, nullptr);
    if (slot->error) std::rethrow_exception(slot->error);
    return std::move(slot->result);
  }

  // Asks the work to stop and waits for its thread; the result, if any, is dropped.
  void cancel() {
    if (thread_.joinable()) {
      thread_.request_stop();
      thread_.join();
    }
    slot_.reset();
  }

 private:
  struct Slot {
    std::optional<Result> result;
    std::exception_ptr error;
    std::atomic<bool> ready{false};
    std::mutex mutex;  // only for waitUntilReady's wait
    std::condition_variable finished;
  };
  std::shared_ptr<Slot> slot_;
  std::jthread thread_;
};

}  // namespace voxflame::app
