#pragma once

// A parallel loop over independent work items (private to refinement): the starts' ICPs are
// independent and each costs milliseconds, so two cores halve a refinement's latency.

#include <cstddef>
#include <functional>

namespace vdc {

// Calls work(worker, i) for every i in [0, count), on min(workers, count) threads (the caller's
// among them); worker in [0, workers) names the thread, so that each can own what is not
// thread-safe. Items are handed out one at a time, in order. Rethrows the first exception a call
// threw, after every thread has stopped. workers < 1 counts as 1.
void parallelFor(std::size_t count, int workers,
                 const std::function<void(int worker, std::size_t i)>& work);

}  // namespace vdc
