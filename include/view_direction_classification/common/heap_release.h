#pragma once

// Giving the heap's free pages back to the system. glibc keeps the pages a frame's peak took
// (70-96 MiB for a segmented frame) for later allocations, and a frame whose peak lands where the
// heap is fragmented takes new ones: over an hour's patrol the estimator's resident memory rose
// by 50 MiB while the memory it had allocated stayed level (doc/performance.md, "Patrol soak").
// A node that runs for hours beside others should not keep what it does not use.

#include <mutex>
#include <optional>

namespace vdc {

// Returns the whole free pages of every arena to the system (glibc's malloc_trim) and says how
// much resident memory that gave back [MiB]; nullopt where it cannot (not glibc, or a
// sanitizer's allocator in its place). It walks every arena under its lock: milliseconds.
std::optional<double> releaseFreeHeap();

// releaseFreeHeap at most once per period. Pages given back cost a page fault each when a later
// frame uses them again, so releasing after every frame would cost a segmented frame tens of
// milliseconds; once per period bounds resident memory by a frame's peak at the same cost spread
// over the period. Safe to call from several threads (a node's worker releases, its diagnostics
// read the counts).
class PeriodicHeapRelease {
 public:
  // period_seconds >= 0 (0: after every frame); throws vdc::Error otherwise.
  explicit PeriodicHeapRelease(double period_seconds);

  // After a frame's work, with a monotonic clock's time [s]: releases when the period has passed
  // since the last release, or at the first call. Returns whether it released.
  bool afterFrame(double now_seconds);

  int releases() const;
  // What the last release gave back [MiB]; nullopt before the first or where it cannot release.
  std::optional<double> last_released_mib() const;

 private:
  mutable std::mutex mutex_;
  double period_seconds_;
  std::optional<double> last_release_seconds_;
  int releases_ = 0;
  std::optional<double> last_released_mib_;
};

}  // namespace vdc
