#include "view_direction_classification/common/heap_usage.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace vdc {
namespace {

constexpr std::size_t kBlockBytes = 64u << 20;  // well above glibc's mmap threshold
constexpr double kBlockMib = 64.0;

TEST(HeapUsage, MemoryInUseRisesByABlockWhileItIsHeldAndFallsWhenItIsFreed) {
  const std::optional<HeapUsage> before = heapUsage();
  if (!before) GTEST_SKIP() << "the C library gives no heap count here";
  auto block = std::make_unique<unsigned char[]>(kBlockBytes);
  block[0] = block[kBlockBytes - 1] = 1;  // used, so that it is not optimised away
  const HeapUsage holding = *heapUsage();
  EXPECT_GE(holding.in_use_mib - before->in_use_mib, kBlockMib - 1.0);
  EXPECT_GE(holding.held_mib, holding.in_use_mib);
  block.reset();
  const HeapUsage after = *heapUsage();
  EXPECT_LT(after.in_use_mib - before->in_use_mib, 1.0);
}

TEST(HeapUsage, SmallBlocksThatStayAllocatedCountAsInUse) {
  const std::optional<HeapUsage> before = heapUsage();
  if (!before) GTEST_SKIP() << "the C library gives no heap count here";
  // Below the mmap threshold: these come from an arena, the case a leak of small objects is.
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 4096; ++i) blocks.push_back(std::make_unique<char[]>(4096));
  const HeapUsage holding = *heapUsage();
  EXPECT_GE(holding.in_use_mib - before->in_use_mib, 15.0);  // 16 MiB allocated
  blocks.clear();
  EXPECT_LT(heapUsage()->in_use_mib - before->in_use_mib, 1.0);
}

}  // namespace
}  // namespace vdc
