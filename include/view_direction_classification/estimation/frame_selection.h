#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace vdc {

// Passive frame selection (doc/method.md section 12): a camera stream shows the same view many
// times over, and noisy copies of one view are not independent evidence. A frame is featurised
// and fused only when it shows the object from a new direction; views near fused ones count
// less (their likelihood is tempered).
struct FrameSelectionParameters {
  // [rad] A frame is a new view when its viewing direction of the object (fixed frame, from the
  // object's position estimate to the camera) is at least this far from every fused view.
  // Negative: half the model's view spacing (15.9 deg for 42 directions); 0: every frame is new.
  double min_view_separation = -1.0;
  // [nats] Optionally also a new view when the information it is predicted to add (the
  // information_gain view utility (planning/view_utility_scorer.h) under the current belief, times
  // the likelihood exponent below) reaches this; 0: off.
  double min_information_gain = 0.0;
  // [rad] A view this far from every fused one is independent evidence (likelihood exponent 1);
  // a nearer one is tempered with exponent separation / independent_view_separation.
  // Negative: the model's view spacing; 0: no tempering.
  double independent_view_separation = -1.0;
  // Camera motion between consecutive frames faster than this is a jump of its pose (tf
  // teleport, a relocalisation): the frame is skipped. [m/s] and [rad/s]; 0: no check.
  double max_camera_speed = 2.0;
  double max_camera_turn_rate = 3.14;
};

// Throws vdc::Error naming the first bad (non-finite or, for the rates, negative) parameter.
void checkFrameSelectionParameters(const FrameSelectionParameters& parameters);

// The viewing directions fused into a belief: fixed-frame unit vectors from the object to the
// camera.
class FusedViews {
 public:
  // Throws vdc::Error for a zero or non-finite direction (it is normalised).
  void add(const Eigen::Vector3d& direction);
  void clear() { directions_.clear(); }
  int size() const { return static_cast<int>(directions_.size()); }
  const std::vector<Eigen::Vector3d>& directions() const { return directions_; }
  // Angle [rad] between `direction` (any non-zero length) and the nearest fused view; pi when
  // none is fused yet.
  double separationFrom(const Eigen::Vector3d& direction) const;

 private:
  std::vector<Eigen::Vector3d> directions_;
};

// The likelihood exponent of a view `separation` [rad] from the nearest fused view:
// min(1, separation / independent_separation), 1 when independent_separation <= 0.
double likelihoodExponent(double separation, double independent_separation);

// A camera pose at a time [s].
struct StampedPose {
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  double time = 0.0;
};

// Why the camera cannot have moved from `previous` to `current` (faster than max_camera_speed or
// max_camera_turn_rate; a later frame at an earlier time is no motion and not judged here), or
// nothing when it can.
std::optional<std::string> cameraJumpReason(const StampedPose& previous, const StampedPose& current,
                                            const FrameSelectionParameters& parameters);

}  // namespace vdc
