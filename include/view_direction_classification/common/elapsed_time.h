#pragma once

#include <chrono>

namespace vdc {

// Milliseconds of the steady clock since `start`: the stage times the estimators report and the
// evaluations record.
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace vdc
