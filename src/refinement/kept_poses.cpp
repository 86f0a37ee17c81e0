#include "kept_poses.h"

#include <algorithm>

#include "roll_sector.h"
#include "view_direction_classification/common/rotation_error.h"

namespace vdc {

namespace {

// The poses of `tried` that `eligible` admits, best first.
template <typename Eligible>
std::vector<RefinedPose> bestFirst(const std::vector<RefinedPose>& tried, Eligible eligible) {
  std::vector<RefinedPose> poses;
  for (const RefinedPose& pose : tried) {
    if (eligible(pose)) poses.push_back(pose);
  }
  std::stable_sort(poses.begin(), poses.end(), [](const RefinedPose& a, const RefinedPose& b) {
    return a.score.score() > b.score.score();
  });
  return poses;
}

bool sameAsAny(const RefinedPose& pose, const std::vector<RefinedPose>& others,
               const RefinementParameters& parameters) {
  return std::any_of(others.begin(), others.end(),
                     [&](const RefinedPose& other) { return samePose(pose, other, parameters); });
}

}  // namespace

bool samePose(const RefinedPose& a, const RefinedPose& b, const RefinementParameters& parameters) {
  return rotationErrorDeg(a.orientation, b.orientation) < parameters.duplicate_angle_deg &&
         (a.world_from_object.translation() - b.world_from_object.translation()).norm() <
             parameters.duplicate_distance;
}

bool onARollSectorOf(const RefinedPose& pose, const std::vector<RefinedPose>& poses,
                     const RefinementParameters& parameters) {
  return std::any_of(poses.begin(), poses.end(), [&](const RefinedPose& other) {
    return onRollSector(other, pose, parameters.duplicate_angle_deg);
  });
}

std::vector<RefinedPose> keptPoses(const std::vector<RefinedPose>& tried,
                                   const RefinementParameters& parameters) {
  const std::vector<RefinedPose> accepted =
      bestFirst(tried, [](const RefinedPose& pose) { return pose.accepted; });
  std::vector<RefinedPose> kept;
  for (const RefinedPose& pose : accepted) {
    if (pose.score.score() < accepted.front().score.score() - parameters.keep_score_margin) break;
    if (!sameAsAny(pose, kept, parameters)) kept.push_back(pose);
  }
  return kept;
}

std::vector<RefinedPose> verifiedAlternatives(const std::vector<RefinedPose>& tried,
                                              const std::vector<RefinedPose>& kept,
                                              const RefinementParameters& parameters) {
  std::vector<RefinedPose> alternatives;
  if (kept.empty()) return alternatives;
  const double floor = kept.front().score.score() - parameters.measurement_score_margin;
  const auto verified = [&](const RefinedPose& pose) {
    return pose.screened_in && pose.converged && pose.score.score() >= floor;
  };
  for (const RefinedPose& pose : bestFirst(tried, verified)) {
    if (static_cast<int>(alternatives.size()) >= parameters.max_alternatives) break;
    if (onARollSectorOf(pose, kept, parameters) || sameAsAny(pose, kept, parameters) ||
        sameAsAny(pose, alternatives, parameters)) {
      continue;
    }
    alternatives.push_back(pose);
  }
  return alternatives;
}

}  // namespace vdc
