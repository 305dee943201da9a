// The explorer's job model: a result is taken without waiting, a stop request reaches the work,
// and a search that would run for minutes ends as soon as its job is cancelled or destroyed.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "background_job.h"
#include "core/flame/search.h"
#include "core/lyapunov.h"
#include "wait_for.h"

using namespace voxflame;

namespace {

template <class Result>
std::optional<Result> waitForResult(app::BackgroundJob<Result>& job) {
  EXPECT_TRUE(job.waitUntilReady(test::kEventTimeout)) << "the work never finished";
  return job.take();
}

TEST(BackgroundJob, TheResultIsTakenOnceWhenReady) {
  app::BackgroundJob<int> job;
  EXPECT_FALSE(job.busy());
  EXPECT_FALSE(job.take().has_value()) << "nothing started, nothing to take";
  std::atomic<bool> release{false};
  job.start([&release](std::stop_token) {
    while (!release) std::this_thread::yield();
    return 42;
  });
  EXPECT_TRUE(job.busy());
  EXPECT_FALSE(job.ready());
  EXPECT_FALSE(job.take().has_value()) << "take never waits for the work";
  release = true;
  const auto result = waitForResult(job);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(*result, 42);
  EXPECT_FALSE(job.busy()) << "taken: the job is free for the next start";
}

TEST(BackgroundJob, WhatTheWorkThrowsComesOutOfTake) {
  app::BackgroundJob<int> job;
  job.start([](std::stop_token) -> int { throw std::runtime_error("no luck"); });
  ASSERT_TRUE(job.waitUntilReady(test::kEventTimeout));
  EXPECT_THROW(job.take(), std::runtime_error);
  EXPECT_FALSE(job.busy());
}

TEST(BackgroundJob, CancellingStopsTheWorkAndDropsItsResult) {
  std::atomic<bool> sawStop{false};
  {
    app::BackgroundJob<int> job;
    job.start([&sawStop](std::stop_token stop) {
      while (!stop.stop_requested()) std::this_thread::yield();  // runs until asked to stop
      sawStop = true;
      return 1;
    });
    job.cancel();
    EXPECT_TRUE(sawStop);
    EXPECT_FALSE(job.busy());
    EXPECT_FALSE(job.take().has_value());
    // Starting again while one runs replaces it the same way.
    sawStop = false;
    job.start([&sawStop](std::stop_token stop) {
      while (!stop.stop_requested()) std::this_thread::yield();
      sawStop = true;
      return 2;
    });
    job.start([](std::stop_token) { return 3; });
    EXPECT_TRUE(sawStop) << "the first job was stopped before the second started";
    EXPECT_EQ(waitForResult(job).value_or(0), 3);
    job.start([&sawStop](std::stop_token stop) {
      while (!stop.stop_requested()) std::this_thread::yield();
      return 4;
    });
  }  // destroying a running job (quitting the explorer) stops it too; otherwise this never returns
}

// Searches that would try thousands of candidates stop at their job's stop request.
TEST(BackgroundJob, SearchesEndWhenTheirJobIsCancelled) {
  // Each search says when it is under way, so the cancel below stops a running search.
  std::atomic<int> started{0};
  core::ProgressSignal startedSignal;
  const auto starting = [&] {
    ++started;
    startedSignal.notify();
  };
  app::BackgroundJob<std::size_t> flames;
  flames.start([starting](std::stop_token stop) {
    starting();
    core::FlameSearchOptions options;
    options.maxCandidates = 1'000'000;
    options.count = 1'000;
    options.fill.minOccupancy = 2.0;  // impossible: it would never finish on its own
    options.stop = stop;
    return core::searchFlames(std::nullopt, options).size();
  });
  app::BackgroundJob<std::size_t> attractors;
  attractors.start([starting](std::stop_token stop) {
    starting();
    core::SearchOptions options;
    options.maxCandidates = 100'000'000;
    options.count = 10'000;
    options.minExtentRatio = 2.0;  // impossible
    options.stop = stop;
    return core::searchChaos(core::defaultOrbitSpec(core::attractorOrThrow("lorenz")), options).size();
  });
  ASSERT_TRUE(test::waitFor(startedSignal, [&] { return started.load() == 2; }));
  flames.cancel();
  attractors.cancel();
  EXPECT_FALSE(flames.busy());
  EXPECT_FALSE(attractors.busy());
}

}  // namespace
