// The parallel loop the estimator's path uses instead of OpenMP: every item once, on at most the
// threads asked for, and an exception comes back to the caller.
#include "view_direction_classification/common/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace vdc {
namespace {

TEST(ParallelFor, RunsEveryItemOnceOnAtMostTheWorkersAsked) {
  std::vector<std::atomic<int>> calls(1000);
  std::mutex mutex;
  std::set<int> workers;
  std::set<std::thread::id> threads;
  parallelFor(calls.size(), 3, [&](int worker, std::size_t i) {
    ++calls[i];
    const std::lock_guard<std::mutex> lock(mutex);
    workers.insert(worker);
    threads.insert(std::this_thread::get_id());
  });
  for (const auto& count : calls) EXPECT_EQ(count.load(), 1);
  EXPECT_LE(workers.size(), 3u);
  EXPECT_LE(threads.size(), 3u);
  for (int worker : workers) EXPECT_TRUE(worker >= 0 && worker < 3) << worker;
}

TEST(ParallelFor, OneWorkerOrFewerRunsOnTheCallersThreadInOrder) {
  const std::thread::id caller = std::this_thread::get_id();
  for (int workers : {1, 0, -2}) {
    std::vector<std::size_t> order;
    parallelFor(5, workers, [&](int worker, std::size_t i) {
      EXPECT_EQ(worker, 0);
      EXPECT_EQ(std::this_thread::get_id(), caller);
      order.push_back(i);
    });
    EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4})) << workers;
  }
  int calls = 0;
  parallelFor(0, 4, [&](int, std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, RethrowsAnItemsExceptionAfterEveryThreadStopped) {
  std::atomic<int> running{0};
  EXPECT_THROW(parallelFor(200, 2,
                           [&](int, std::size_t i) {
                             ++running;
                             if (i == 17) {
                               --running;
                               throw std::runtime_error("item 17");
                             }
                             --running;
                           }),
               std::runtime_error);
  EXPECT_EQ(running.load(), 0);
}

TEST(ParallelFor, HardwareThreadsIsAtLeastOne) { EXPECT_GE(hardwareThreads(), 1); }

}  // namespace
}  // namespace vdc
