#include "heap_diagnostics.h"

#include <chrono>

#include "view_direction_classification/common/heap_usage.h"

namespace vdc {

void addHeapUsage(diagnostic_updater::DiagnosticStatusWrapper& status,
                  const PeriodicHeapRelease& release) {
  const std::optional<HeapUsage> heap = heapUsage();
  if (heap) {
    status.addf("heap in use [MiB]", "%.1f", heap->in_use_mib);
    status.addf("heap held [MiB]", "%.1f", heap->held_mib);
  } else {
    status.add("heap", "not counted here");
  }
  status.add("heap releases", release.releases());
  const std::optional<double> released = release.last_released_mib();
  if (released) {
    status.addf("heap given back by the last release [MiB]", "%.1f", *released);
  } else if (release.releases() > 0) {
    status.add("heap given back by the last release [MiB]", "not released here");
  }
}

double monotonicSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace vdc
