// The shared task scheduler: every index once, no task too small, the caller taking part, a cap on the threads one
// loop uses, loops nested in loops, exceptions carried to the caller.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/core_budget.h"
#include "core/task_scheduler.h"

using voxflame::core::parallelFor;
using voxflame::core::setTaskConcurrency;
using voxflame::core::taskConcurrency;

TEST(TaskScheduler, VisitsEveryIndexOnceInRangesNoSmallerThanHalfTheGrain) {
  for (const std::size_t count :
       {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{1000}, std::size_t{100'003}}) {
    std::vector<std::atomic<int>> visits(count);
    std::atomic<std::size_t> smallest{count};
    parallelFor(count, 64, [&](std::size_t begin, std::size_t end) {
      ASSERT_LT(begin, end);
      std::size_t seen = smallest.load();
      while (end - begin < seen && !smallest.compare_exchange_weak(seen, end - begin)) {
      }
      for (std::size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
    });
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(visits[i].load(), 1) << "count " << count << " index " << i;
    EXPECT_GE(smallest.load(), std::min<std::size_t>(count, 32));
  }
}

TEST(TaskScheduler, ACapLimitsTheThreadsOfOneLoop) {
  setTaskConcurrency(2);
  EXPECT_EQ(taskConcurrency(), 2);
  std::atomic<int> running{0}, most{0};
  parallelFor(64, 1, [&](std::size_t, std::size_t) {
    const int now = running.fetch_add(1) + 1;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    // Work that takes a while (busy, not a wait for anything), so that a loop breaking its cap
    // would have more bodies running at once.
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(2);
    while (std::chrono::steady_clock::now() < until) {
    }
    running.fetch_sub(1);
  });
  EXPECT_LE(most.load(), 2);
  setTaskConcurrency(0);
  EXPECT_EQ(taskConcurrency(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
}

TEST(TaskScheduler, LoopsNestAndExceptionsReachTheCaller) {
  std::atomic<int> inner{0};
  parallelFor(8, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      parallelFor(100, 10, [&](std::size_t b, std::size_t e) { inner.fetch_add(static_cast<int>(e - b)); });
  });
  EXPECT_EQ(inner.load(), 800);
  EXPECT_THROW(parallelFor(100, 1,
                           [](std::size_t begin, std::size_t) {
                             if (begin == 42) throw std::runtime_error("task 42");
                           }),
               std::runtime_error);
}

// A core freed while a thread that goes first (the proxy's) and another wait is the first one's,
// whichever came first.
TEST(CoreBudget, AFreedCoreGoesToTheThreadThatGoesFirst) {
  voxflame::core::CoreBudget budget(1);
  budget.acquire();
  std::atomic<int> order{0};
  int normalTurn = 0, firstTurn = 0;
  std::jthread normal([&] {
    budget.acquire();
    normalTurn = ++order;
    budget.release();
  });
  while (budget.waiting() < 1) std::this_thread::yield();
  std::jthread first([&] {
    budget.acquire(true);
    firstTurn = ++order;
    budget.release();
  });
  while (budget.waiting() < 2) std::this_thread::yield();
  budget.release();
  normal.join();
  first.join();
  EXPECT_EQ(firstTurn, 1);
  EXPECT_EQ(normalTurn, 2);
}

// Two cores freed at once while a first thread and another wait: the first takes one and the other
// must be woken for the second (both releases may signal the first one before it runs), not sleep
// beside a free core.
TEST(CoreBudget, CoresFreedAtOnceReachEveryKindOfWaiter) {
  for (int round = 0; round < 200; ++round) {
    voxflame::core::CoreBudget budget(2);
    budget.acquire();
    budget.acquire();
    std::atomic<int> inside{0};
    std::jthread normal([&] {
      budget.acquire();
      ++inside;
    });
    std::jthread first([&] {
      budget.acquire(true);
      ++inside;
    });
    while (budget.waiting() < 2) std::this_thread::yield();
    budget.release();
    budget.release();
    normal.join();
    first.join();
    EXPECT_EQ(inside.load(), 2);
  }
}

// A thread that holds a core and passes it on between pieces of work keeps it while nobody that
// goes before it waits, and hands it over, then waits for the next one, when one does.
TEST(CoreBudget, PassingOnHandsTheCoreOnlyToAWaiterThatGoesBefore) {
  voxflame::core::CoreBudget budget(1);
  budget.acquire(true);
  budget.passOn(true);  // nobody waits: kept
  std::atomic<bool> normalIn{false};
  std::jthread normal([&] {
    budget.acquire();
    normalIn = true;
    budget.release();
  });
  while (budget.waiting() < 1) std::this_thread::yield();
  budget.passOn(true);  // only a thread that does not go first waits: kept
  EXPECT_FALSE(normalIn.load());
  std::atomic<bool> firstIn{false};
  std::jthread first([&] {
    budget.acquire(true);
    firstIn = true;
    budget.release();
  });
  while (budget.waiting() < 2) std::this_thread::yield();
  budget.passOn(true);  // handed to the waiting first thread; back once it releases
  first.join();
  EXPECT_TRUE(firstIn.load());
  EXPECT_FALSE(normalIn.load()) << "the first thread's release handed the core back to the passer";
  budget.passOn(false);  // a thread that does not go first hands over to any waiter
  normal.join();
  EXPECT_TRUE(normalIn.load());
  budget.release();
  EXPECT_TRUE(budget.try_acquire());
  EXPECT_FALSE(budget.try_acquire());
}
