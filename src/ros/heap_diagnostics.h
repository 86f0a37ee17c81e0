#pragma once

// The heap's count (common/heap_usage.h) as two values of a node's diagnostic status.

#include <diagnostic_updater/diagnostic_updater.h>

namespace vdc {

// Adds "heap in use [MiB]" and "heap held [MiB]", or "heap" = "not counted here" where the C
// library cannot tell.
void addHeapUsage(diagnostic_updater::DiagnosticStatusWrapper& status);

}  // namespace vdc
