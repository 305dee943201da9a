// The process's one task scheduler for short parallel loops (the image finishing pass, the points
// renderer, the inside mask): oneTBB's parallel_for inside one process-wide task_arena.
//
// Why one: each of those loops used to start and join a std::jthread per hardware thread on every
// call, dozens of times a second in the explorer, and each pool ran beside the accumulator's
// workers, so the runnable threads could reach several times the cores. TBB keeps one set of
// worker threads for the process, parked when idle, and the arena caps how many of them (the
// calling thread included) a loop may use at once.
#pragma once

#include <cstddef>
#include <functional>

namespace voxflame::core {

// Runs fn(begin, end) over disjoint ranges covering [0, count) on the shared arena; the calling
// thread takes part and the call returns when every range is done. `grain` is the fewest items
// worth a hand-off to another thread: ranges are split no finer than about half of it, and a
// count of at most `grain` runs on the caller alone. Ranges go to threads as they become free, so
// uneven work still keeps every thread busy. fn must be safe to call concurrently; an exception
// it throws reaches the caller.
void parallelFor(std::size_t count, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& fn);

// The most threads (the caller included) one parallelFor uses at once; 0 restores the default,
// one per hardware thread. Loops running when it changes finish on the arena they started on.
void setTaskConcurrency(int threads);
int taskConcurrency();

}  // namespace voxflame::core
