#include "view_direction_classification/refinement/pose_hypotheses.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

void checkParameters(const HypothesisParameters& p) {
  if (p.max_components < 1) {
    throw Error("refinement must use at least one belief component, got max_components " +
                std::to_string(p.max_components));
  }
  if (!(p.min_relative_weight >= 0.0 && p.min_relative_weight < 1.0)) {
    throw Error("refinement's min_relative_weight must be in [0, 1), got " +
                std::to_string(p.min_relative_weight));
  }
  if (!(p.girdle_concentration >= 0.0) || !std::isfinite(p.girdle_concentration)) {
    throw Error("refinement's girdle_concentration must be >= 0 and finite, got " +
                std::to_string(p.girdle_concentration));
  }
  if (!(p.girdle_step_deg > 0.0 && p.girdle_step_deg <= 180.0)) {
    throw Error("refinement's girdle_step_deg must be in (0, 180], got " +
                std::to_string(p.girdle_step_deg));
  }
}

}  // namespace

std::vector<OrientationStart> orientationHypotheses(const BinghamMixture& belief,
                                                    const HypothesisParameters& parameters) {
  checkParameters(parameters);
  std::vector<std::size_t> order(belief.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return belief.weight(a) > belief.weight(b);
  });
  const double heaviest = belief.weight(order.front());
  const std::size_t used = std::min<std::size_t>(order.size(), parameters.max_components);

  // A quaternion and its negative are one rotation: t in [0, pi) covers the circle once.
  const double step = parameters.girdle_step_deg * M_PI / 180.0 / 2.0;
  const int girdle_points = std::max(1, static_cast<int>(std::ceil(M_PI / step - 1e-9)));
  std::vector<OrientationStart> starts;
  for (std::size_t i = 0; i < used; ++i) {
    const std::size_t k = order[i];
    if (belief.weight(k) < parameters.min_relative_weight * heaviest) break;
    const BinghamDistribution& component = belief.component(k);
    const Eigen::Vector4d mode = component.mode();
    if (component.concentrations()(2) > -parameters.girdle_concentration) {
      const Eigen::Vector4d loosest = component.axis(2);
      for (int j = 0; j < girdle_points; ++j) {
        const double t = j * M_PI / girdle_points;
        starts.push_back(
            {(std::cos(t) * mode + std::sin(t) * loosest).normalized(), static_cast<int>(k)});
      }
    } else {
      starts.push_back({mode, static_cast<int>(k)});
    }
  }
  return starts;
}

}  // namespace vdc
