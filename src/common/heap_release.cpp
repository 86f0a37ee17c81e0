#include "view_direction_classification/common/heap_release.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "view_direction_classification/common/error.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "sanitizer_allocator.h"

namespace vdc {
namespace {

constexpr double kBytesPerMib = 1024.0 * 1024.0;

// The process's resident memory [MiB] from /proc/self/statm (its second field, in pages); nullopt
// where it cannot be read.
[[maybe_unused]] std::optional<double> residentMib() {
  std::ifstream statm("/proc/self/statm");
  long size_pages = 0;
  long resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return std::nullopt;
  return static_cast<double>(resident_pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
         kBytesPerMib;
}

}  // namespace

std::optional<double> releaseFreeHeap() {
#if defined(__GLIBC__) && !defined(VDC_SANITIZER_ALLOCATOR)
  const std::optional<double> before = residentMib();
  malloc_trim(0);
  const std::optional<double> after = residentMib();
  if (!before || !after) return 0.0;
  return std::max(0.0, *before - *after);
#else
  return std::nullopt;
#endif
}

PeriodicHeapRelease::PeriodicHeapRelease(double period_seconds) : period_seconds_(period_seconds) {
  if (!(period_seconds >= 0.0) || !std::isfinite(period_seconds)) {
    throw Error("the heap release period must be a finite number >= 0, got " +
                std::to_string(period_seconds));
  }
}

bool PeriodicHeapRelease::afterFrame(double now_seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  // A clock that went back (it should not: monotonic) restarts the period rather than stopping it.
  if (last_release_seconds_ && now_seconds >= *last_release_seconds_ &&
      now_seconds - *last_release_seconds_ < period_seconds_) {
    return false;
  }
  last_release_seconds_ = now_seconds;
  ++releases_;
  last_released_mib_ = releaseFreeHeap();
  return true;
}

int PeriodicHeapRelease::releases() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return releases_;
}

std::optional<double> PeriodicHeapRelease::last_released_mib() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_released_mib_;
}

}  // namespace vdc
