#include "view_direction_classification/visualisation/heatmap_colours.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vdc {
namespace {

std::vector<float> validValues(const Eigen::VectorXf& values) {
  std::vector<float> valid;
  valid.reserve(static_cast<std::size_t>(values.size()));
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (values(i) >= 0.0f && std::isfinite(values(i))) valid.push_back(values(i));
  }
  return valid;
}

}  // namespace

double medianOfValid(const Eigen::VectorXf& values) {
  std::vector<float> valid = validValues(values);
  if (valid.empty()) return 0.0;
  const std::size_t half = valid.size() / 2;
  std::nth_element(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(half), valid.end());
  const double upper = valid[half];
  if (valid.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(half));
  return 0.5 * (lower + upper);
}

double maximumOfValid(const Eigen::VectorXf& values) {
  const std::vector<float> valid = validValues(values);
  return valid.empty() ? 0.0 : *std::max_element(valid.begin(), valid.end());
}

std::array<std::uint8_t, 3> heatmapColour(double value, double black_at) {
  if (!(value >= 0.0)) return kUnobservableColour;  // also NaN
  double darkness;
  if (black_at > 0.0 && std::isfinite(black_at)) {
    darkness = std::min(1.0, value / black_at);
  } else {
    darkness = value > 0.0 ? 1.0 : 0.0;
  }
  const auto grey = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - darkness)));
  return {grey, grey, grey};
}

}  // namespace vdc
