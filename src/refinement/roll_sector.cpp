#include "roll_sector.h"

#include <algorithm>
#include <cmath>

#include "turned_starts.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {

namespace {

constexpr double kDegrees = 180.0 / M_PI;

// Turns of k * step_deg on one side (sign +1 or -1) that keep scoring within margin.
double sideSectorDeg(const ModelSurface& surface, const PoseVerifier& verifier,
                     const RefinedPose& pose, double step_deg, double margin, double sign) {
  const auto& axis = surface.symmetryAxes().front();
  const double floor = pose.score.score() - margin;
  double sector = 0.0;
  for (double turn = step_deg; turn <= 180.0 + 1e-9; turn += step_deg) {
    const Eigen::Isometry3d turned =
        turnedAbout(pose.world_from_object, axis, sign * turn / kDegrees);
    if (verifier.score(turned).score() < floor) break;
    sector = turn;
  }
  return sector;
}

}  // namespace

double verifiedRollSectorDeg(const ModelSurface& surface, const PoseVerifier& verifier,
                             const RefinedPose& pose, double step_deg, double margin) {
  if (surface.symmetryAxes().empty()) return 0.0;
  const double up = sideSectorDeg(surface, verifier, pose, step_deg, margin, 1.0);
  // All the way round on one side: the other side holds no more.
  if (up >= 180.0 - 1e-9) return 180.0;
  // The wider side: an honest sector errs wide.
  return std::max(up, sideSectorDeg(surface, verifier, pose, step_deg, margin, -1.0));
}

bool onRollSector(const RefinedPose& pose, const RefinedPose& other, double tolerance_deg) {
  if (!(pose.roll_sector_deg > 0.0)) return false;
  // The circle q(t) = q0 (cos t/2, sin t/2 a): its plane in R^4 is spanned by q0 and q0 (0, a).
  const Eigen::Vector4d& q0 = pose.orientation;
  const Eigen::Vector3d a = pose.sector_axis.normalized();
  const Eigen::Vector4d along = quaternionMultiply(q0, Eigen::Vector4d(0.0, a.x(), a.y(), a.z()));
  const double c = other.orientation.dot(q0), s = other.orientation.dot(along);
  const double in_plane = std::min(1.0, std::hypot(c, s));
  const double off_circle_deg = 2.0 * std::acos(in_plane) * kDegrees;
  // The turn along the circle, q and -q alike.
  const double turn_deg = 2.0 * std::atan2(std::abs(s), std::abs(c)) * kDegrees;
  return off_circle_deg <= tolerance_deg && turn_deg <= pose.roll_sector_deg + tolerance_deg;
}

}  // namespace vdc
