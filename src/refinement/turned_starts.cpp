#include "turned_starts.h"

#include <cmath>

namespace vdc {

Eigen::Isometry3d turnedAbout(const Eigen::Isometry3d& world_from_object,
                              const Eigen::ParametrizedLine<double, 3>& axis, double angle) {
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(angle, axis.direction()).toRotationMatrix();
  turn.translation() = axis.origin() - turn.linear() * axis.origin();
  return world_from_object * turn;
}

std::vector<Eigen::Isometry3d> turnedStarts(const ModelSurface& surface,
                                            const Eigen::Isometry3d& world_from_object,
                                            double step_deg) {
  const auto& axes = surface.symmetryAxes();
  std::vector<Eigen::Isometry3d> starts;
  const int turns = static_cast<int>(std::lround(360.0 / step_deg));
  for (int k = 1; k < turns; ++k) {
    starts.push_back(turnedAbout(world_from_object, axes[0], k * 2.0 * M_PI / turns));
  }
  for (const Eigen::Isometry3d& start : halfTurnStarts(surface, world_from_object)) {
    starts.push_back(start);
  }
  return starts;
}

std::vector<Eigen::Isometry3d> halfTurnStarts(const ModelSurface& surface,
                                              const Eigen::Isometry3d& world_from_object) {
  const auto& axes = surface.symmetryAxes();
  return {turnedAbout(world_from_object, axes[1], M_PI),
          turnedAbout(world_from_object, axes[2], M_PI)};
}

}  // namespace vdc
