#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace vdc::tools {

// A one-line progress bar on stderr for long stages. On a terminal it redraws in place; in a
// log (CI, a pipe) it prints a line at every 10 % so logs stay short.
class ProgressBar {
 public:
  void operator()(const std::string& stage, std::size_t done, std::size_t total);

 private:
  std::string stage_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point stage_start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace vdc::tools
