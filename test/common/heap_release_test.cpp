#include "view_direction_classification/common/heap_release.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(HeapRelease, FreedPagesInsideTheHeapGoBackToTheSystem) {
  if (!releaseFreeHeap()) GTEST_SKIP() << "the C library cannot release its heap here";
  // 64 MiB of small blocks (below the mmap threshold, so from the heap), written to so that their
  // pages are resident, then freed but for the last: the free space lies below a block in use,
  // where freeing alone does not give it back.
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 4096; ++i) {
    blocks.push_back(std::make_unique<char[]>(16384));
    std::memset(blocks.back().get(), 1, 16384);
  }
  for (std::size_t i = 0; i + 1 < blocks.size(); ++i) blocks[i].reset();
  const std::optional<double> released = releaseFreeHeap();
  ASSERT_TRUE(released.has_value());
  EXPECT_GE(*released, 32.0);
  EXPECT_LT(*released, 1024.0);
}

TEST(HeapRelease, ReleasesAtTheFirstFrameThenOncePerPeriod) {
  PeriodicHeapRelease release(10.0);
  EXPECT_TRUE(release.afterFrame(100.0));
  EXPECT_FALSE(release.afterFrame(100.1));
  EXPECT_FALSE(release.afterFrame(109.9));
  EXPECT_TRUE(release.afterFrame(110.0));
  EXPECT_FALSE(release.afterFrame(115.0));
  EXPECT_EQ(release.releases(), 2);
  EXPECT_EQ(release.last_released_mib().has_value(), releaseFreeHeap().has_value());
}

TEST(HeapRelease, AClockThatWentBackRestartsThePeriod) {
  PeriodicHeapRelease release(10.0);
  EXPECT_TRUE(release.afterFrame(100.0));
  EXPECT_TRUE(release.afterFrame(50.0));
  EXPECT_FALSE(release.afterFrame(55.0));
}

TEST(HeapRelease, AZeroPeriodReleasesAfterEveryFrameAndANegativeOneIsRefused) {
  PeriodicHeapRelease every_frame(0.0);
  EXPECT_TRUE(every_frame.afterFrame(1.0));
  EXPECT_TRUE(every_frame.afterFrame(1.0));
  // Braces: with parentheses a compiler may read the NaN case as a declaration.
  EXPECT_THROW(PeriodicHeapRelease{-1.0}, Error);
  EXPECT_THROW(PeriodicHeapRelease{std::numeric_limits<double>::quiet_NaN()}, Error);
}

}  // namespace
}  // namespace vdc
