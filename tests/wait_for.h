// Waiting in a test for something another thread does: the wait sleeps on an event of the code
// under test (a core::ProgressSignal, an EventCounter, the explorer session's news) and returns as
// soon as what it waits for holds, so no test sleeps for a fixed time in the hope that the other
// thread was quick enough. The timeout only turns a thing that never happens into a failure
// instead of a hung test: it is generous (sanitizer builds on a loaded machine run many times
// slower), and a wait that succeeds never comes near it.
#pragma once

#include <chrono>
#include <cstdint>

#include "core/progress_signal.h"

namespace voxflame::test {

inline constexpr std::chrono::seconds kEventTimeout{60};

inline std::chrono::steady_clock::time_point deadlineAfter(std::chrono::duration<double> timeout) {
  return std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout);
}

// Sleeps on `signal` until `ready()` holds (true) or `timeout` passes (false). ready() runs under
// the signal's mutex and reads what the signal's notifiers change before they notify.
template <class Ready>
bool waitFor(core::ProgressSignal& signal, Ready ready, std::chrono::duration<double> timeout = kEventTimeout) {
  return signal.waitUntil(deadlineAfter(timeout), ready);
}

// Checks `ready()` again after every event `events` counts, until it holds (true) or `timeout`
// passes (false). The count is read before the check, so an event during the check is not missed.
template <class Ready>
bool waitFor(core::EventCounter& events, Ready ready, std::chrono::duration<double> timeout = kEventTimeout) {
  const auto deadline = deadlineAfter(timeout);
  for (;;) {
    const std::uint64_t seen = events.count();
    if (ready()) return true;
    if (!events.waitPast(seen, deadline)) return ready();
  }
}

// The same on an explorer session's news (app::ExplorerSession::news and waitForNews: its snapshot
// threads' looks and packs, posts applied, steers). A template, so tests without the explorer do
// not need its headers.
template <class Session, class Ready>
bool waitForSession(const Session& session, Ready ready, std::chrono::duration<double> timeout = kEventTimeout) {
  const auto deadline = deadlineAfter(timeout);
  for (;;) {
    const std::uint64_t seen = session.news();
    if (ready()) return true;
    const std::chrono::duration<double> left = deadline - std::chrono::steady_clock::now();
    if (left.count() <= 0.0 || !session.waitForNews(seen, left.count())) return ready();
  }
}

}  // namespace voxflame::test
