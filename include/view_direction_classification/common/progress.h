#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace vdc {

// Reports progress of a long stage: (stage name, items done, items total). The core calls it
// from one thread at a time; the CLI draws a bar, tests pass nothing.
using ProgressCallback =
    std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

inline void reportProgress(const ProgressCallback& progress, const std::string& stage,
                           std::size_t done, std::size_t total) {
  if (progress) progress(stage, done, total);
}

}  // namespace vdc
