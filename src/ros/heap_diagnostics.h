#pragma once

// The heap's count (common/heap_usage.h) and its periodic release (common/heap_release.h) as
// values of a node's diagnostic status, and the release's period in the nodes.

#include <diagnostic_updater/diagnostic_updater.h>

#include "view_direction_classification/common/heap_release.h"

namespace vdc {

// Each estimator node gives its heap's free pages back at most this often, after a cloud: a
// segmented frame's peak is given back within 10 s, and the page faults of reusing them cost
// the node a release's worth every 10 s rather than every frame (doc/performance.md).
constexpr double kNodeHeapReleasePeriodSeconds = 10.0;

// Adds "heap in use [MiB]" and "heap held [MiB]", or "heap" = "not counted here" where the C
// library cannot tell; then "heap releases" and "heap given back by the last release [MiB]".
void addHeapUsage(diagnostic_updater::DiagnosticStatusWrapper& status,
                  const PeriodicHeapRelease& release);

// The monotonic clock's time [s], for PeriodicHeapRelease::afterFrame.
double monotonicSeconds();

}  // namespace vdc
