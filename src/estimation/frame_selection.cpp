#include "view_direction_classification/estimation/frame_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void requireFinite(double value, const char* name) {
  if (!std::isfinite(value))
    throw Error(std::string("frame selection: ") + name + " is not finite");
}

void requireNonNegative(double value, const char* name) {
  requireFinite(value, name);
  if (value < 0.0) {
    throw Error(std::string("frame selection: ") + name + " must not be negative, got " +
                std::to_string(value));
  }
}

}  // namespace

void checkFrameSelectionParameters(const FrameSelectionParameters& p) {
  requireFinite(p.min_view_separation, "min_view_separation");
  requireNonNegative(p.min_information_gain, "min_information_gain");
  requireFinite(p.independent_view_separation, "independent_view_separation");
  requireNonNegative(p.max_camera_speed, "max_camera_speed");
  requireNonNegative(p.max_camera_turn_rate, "max_camera_turn_rate");
}

void FusedViews::add(const Eigen::Vector3d& direction) {
  const double length = direction.norm();
  if (!(length > 1e-12) || !std::isfinite(length)) {
    throw Error("a fused view's direction must be a finite non-zero vector");
  }
  directions_.push_back(direction / length);
}

double FusedViews::separationFrom(const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d unit = direction.normalized();
  double best = -1.0;
  for (const Eigen::Vector3d& fused : directions_) best = std::max(best, fused.dot(unit));
  return directions_.empty() ? M_PI : std::acos(std::clamp(best, -1.0, 1.0));
}

double likelihoodExponent(double separation, double independent_separation) {
  if (independent_separation <= 0.0) return 1.0;
  return std::clamp(separation / independent_separation, 0.0, 1.0);
}

std::optional<std::string> cameraJumpReason(const StampedPose& previous, const StampedPose& current,
                                            const FrameSelectionParameters& parameters) {
  const double dt = current.time - previous.time;
  if (!(dt > 0.0)) return std::nullopt;
  const double moved =
      (current.world_from_camera.translation() - previous.world_from_camera.translation()).norm();
  const double turned = Eigen::AngleAxisd(previous.world_from_camera.linear().transpose() *
                                          current.world_from_camera.linear())
                            .angle();
  const bool too_fast =
      parameters.max_camera_speed > 0.0 && moved > parameters.max_camera_speed * dt;
  const bool turned_too_fast =
      parameters.max_camera_turn_rate > 0.0 && turned > parameters.max_camera_turn_rate * dt;
  if (!too_fast && !turned_too_fast) return std::nullopt;
  char text[256];
  std::snprintf(text, sizeof(text),
                "the camera pose jumped %.3f m and %.1f deg within %.3f s (faster than "
                "max_camera_speed %.2f m/s or max_camera_turn_rate %.2f rad/s): a tf jump, not "
                "a motion",
                moved, turned * 180.0 / M_PI, dt, parameters.max_camera_speed,
                parameters.max_camera_turn_rate);
  return std::string(text);
}

}  // namespace vdc
