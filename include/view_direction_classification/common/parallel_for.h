#pragma once

// A parallel loop over independent work items on plain threads, joined before it returns:
// refinement's ICP starts and the features' per-point work. Not OpenMP on the estimator's path:
// libgomp's workers spin after each parallel region, and on a robot's few cores a spinning
// worker between the many short feature regions took a third of a scene's identification time
// from the refinement threads (doc/performance.md).

#include <cstddef>
#include <functional>

namespace vdc {

// Calls work(worker, i) for every i in [0, count), on min(workers, count) threads (the caller's
// among them); worker in [0, workers) names the thread, so that each can own what is not
// thread-safe. Items are handed out one at a time, in order. Rethrows the first exception a call
// threw, after every thread has stopped. workers < 1 counts as 1.
void parallelFor(std::size_t count, int workers,
                 const std::function<void(int worker, std::size_t i)>& work);

// The machine's hardware threads (at least 1).
int hardwareThreads();

}  // namespace vdc
