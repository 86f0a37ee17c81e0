#include "view_direction_classification/common/heap_usage.h"

#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "sanitizer_allocator.h"

namespace vdc {
namespace {

constexpr double kBytesPerMib = 1024.0 * 1024.0;

}  // namespace

std::optional<HeapUsage> heapUsage() {
#if defined(__GLIBC__) && !defined(VDC_SANITIZER_ALLOCATOR) && \
    (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  // mallinfo2, not mallinfo: the older one's int fields wrap above 2 GiB.
  const struct mallinfo2 info = mallinfo2();
  HeapUsage usage;
  // uordblks: in use in the arenas; hblkhd: large blocks given their own mapping.
  usage.in_use_mib = static_cast<double>(info.uordblks + info.hblkhd) / kBytesPerMib;
  // arena: the pages of every thread's arena, summed.
  usage.held_mib = static_cast<double>(info.arena + info.hblkhd) / kBytesPerMib;
  return usage;
#else
  return std::nullopt;
#endif
}

}  // namespace vdc
