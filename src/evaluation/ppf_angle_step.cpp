#include "view_direction_classification/evaluation/ppf_angle_step.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Bin counts searched on either side of 2 pi / requested: the lead's scan found a safe step for
// 10 of the counts 17..59, at most 6 apart.
constexpr int kBinCountSearch = 16;

// The bins PCL allocates and the bin of the largest angle, in PCL's own expressions (the float
// step promoted to double, as in ppf_registration.hpp).
double binCount(float step) { return std::floor(2 * M_PI / step); }
double largestBin(float step) { return std::floor((kLargestPpfAngle + M_PI) / step); }

// The safe step of bin count `bins` nearest to `requested` (NaN: none): every float from the
// top of the interval, 2 pi / bins, down while floor(2 pi / s) stays `bins`.
float nearestSafeStepWithBins(int bins, double requested) {
  float best = std::numeric_limits<float>::quiet_NaN();
  float step = static_cast<float>(2 * M_PI / bins);
  while (binCount(step) > bins) step = std::nextafter(step, 0.0f);  // rounded up past the top
  for (; binCount(step) == bins; step = std::nextafter(step, 0.0f)) {
    if (isSafePpfAngleStep(step) &&
        (std::isnan(best) || std::abs(step - requested) < std::abs(best - requested))) {
      best = step;
    }
  }
  return best;
}

}  // namespace

bool isSafePpfAngleStep(float step_rad) {
  if (!(step_rad > 0.0f) || !std::isfinite(step_rad)) return false;
  return largestBin(step_rad) < binCount(step_rad);
}

float safePpfAngleStep(double requested_rad) {
  if (!(requested_rad > 0.0) || !std::isfinite(requested_rad) || requested_rad > M_PI / 2) {
    throw Error("the PPF angle step must be in (0, 90] degrees, got " +
                std::to_string(requested_rad * 180.0 / M_PI) + " degrees");
  }
  const int centre = static_cast<int>(std::lround(2 * M_PI / requested_rad));
  float best = std::numeric_limits<float>::quiet_NaN();
  for (int offset = 0; offset <= kBinCountSearch; ++offset) {
    for (const int bins : {centre - offset, centre + offset}) {
      if (bins < 4) continue;
      const float step = nearestSafeStepWithBins(bins, requested_rad);
      if (!std::isnan(step) &&
          (std::isnan(best) || std::abs(step - requested_rad) < std::abs(best - requested_rad))) {
        best = step;
      }
    }
  }
  if (std::isnan(best)) {
    throw Error("no PPF angle step near " + std::to_string(requested_rad * 180.0 / M_PI) +
                " degrees keeps PCL's voting inside its accumulator");
  }
  return best;
}

}  // namespace vdc
