#include "heap_diagnostics.h"

#include "view_direction_classification/common/heap_usage.h"

namespace vdc {

void addHeapUsage(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const std::optional<HeapUsage> heap = heapUsage();
  if (!heap) {
    status.add("heap", "not counted here");
    return;
  }
  status.addf("heap in use [MiB]", "%.1f", heap->in_use_mib);
  status.addf("heap held [MiB]", "%.1f", heap->held_mib);
}

}  // namespace vdc
