#include "progress_bar.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace vdc::tools {

void ProgressBar::operator()(const std::string& stage, std::size_t done, std::size_t total) {
  const auto now = std::chrono::steady_clock::now();
  if (stage != stage_) {
    stage_ = stage;
    last_decile_ = -1;
    stage_start_ = now;
  }
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const double elapsed = std::chrono::duration<double>(now - stage_start_).count();
  static const bool terminal = isatty(STDERR_FILENO) != 0;
  if (terminal) {
    if (done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r%-22s [%s%s] %zu/%zu %.1fs", stage.c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), done, total,
                 elapsed);
    if (done >= total) std::fprintf(stderr, "\n");
  } else {
    const int decile = static_cast<int>(fraction * 10.0);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %zu/%zu (%.1fs)\n", stage.c_str(), done, total, elapsed);
  }
  std::fflush(stderr);
}

}  // namespace vdc::tools
