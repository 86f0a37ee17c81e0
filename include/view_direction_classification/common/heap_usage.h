#pragma once

// What the process's heap holds, as the C library's allocator counts it: the node's diagnostics
// report it beside the resident memory the soak reads from /proc, because the two answer
// different questions. Memory in use that keeps rising is a leak; resident memory that rises
// while memory in use stays level is the allocator keeping freed pages for later
// (doc/performance.md, "Patrol soak").

#include <optional>

namespace vdc {

struct HeapUsage {
  double in_use_mib = 0.0;  // allocated and not yet freed, mmap'ed blocks included
  double held_mib = 0.0;    // obtained from the system for the heap, free parts included
};

// The allocator's count now; nullopt where the C library cannot tell (not glibc 2.33 or later,
// or a sanitizer's allocator in its place).
// Walks every arena under its lock: cheap enough once a second, not per point.
std::optional<HeapUsage> heapUsage();

}  // namespace vdc
