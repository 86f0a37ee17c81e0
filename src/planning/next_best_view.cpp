#include "view_direction_classification/planning/next_best_view.h"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "position_check.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc {

std::vector<RankedCandidate> rankCandidates(const ViewUtilityScorer& scorer,
                                            const std::vector<Eigen::Vector3d>& camera_positions,
                                            ViewUtility utility, const PlanningScene& scene,
                                            const NextBestViewOptions& options) {
  if (camera_positions.empty()) throw Error("There are no candidate camera positions to rank.");
  checkFinitePosition(scene.object_position, "object position");
  checkUnitQuaternion(scene.orientation, "the object orientation");
  const Eigen::Vector4d to_object = quaternionConjugate(scene.orientation);
  std::unique_ptr<OccluderCloud> occluder;
  if (!scene.occluder_world.empty() && utility == ViewUtility::kInformativeness) {
    std::vector<Eigen::Vector3d> occluder_object;
    occluder_object.reserve(scene.occluder_world.size());
    for (const auto& p : scene.occluder_world) {
      if (!p.allFinite()) throw Error("The occluder cloud contains a non-finite point.");
      occluder_object.push_back(rotateVector(to_object, p - scene.object_position));
    }
    occluder = std::make_unique<OccluderCloud>(std::move(occluder_object), scene.occluder_radius);
  }
  std::vector<OrientationHypothesis> hypotheses;
  if (utility == ViewUtility::kInformationGain) {
    hypotheses = beliefHypotheses(scene.belief, options.samples_per_component, options.seed);
  }
  std::vector<RankedCandidate> ranked(camera_positions.size());
  for (std::size_t i = 0; i < camera_positions.size(); ++i) {
    const Eigen::Vector3d& c = camera_positions[i];
    checkFinitePosition(c, "candidate camera position");
    const Eigen::Vector3d camera_object = rotateVector(to_object, c - scene.object_position);
    if (!(camera_object.norm() > 0.0)) {
      throw Error("Candidate " + std::to_string(i) +
                  " sits at the object's position, so it has no viewing direction.");
    }
    ranked[i].index = static_cast<int>(i);
    ranked[i].view = scorer.nearestView(camera_object);
    ranked[i].utility = utility == ViewUtility::kInformativeness
                            ? scorer.informativeness(camera_object, occluder.get())
                            : scorer.informationGain(c, scene.object_position, hypotheses);
  }
  std::stable_sort(
      ranked.begin(), ranked.end(),
      [](const RankedCandidate& a, const RankedCandidate& b) { return a.utility > b.utility; });
  return ranked;
}

std::vector<Eigen::Isometry3d> sampleCandidatePoses(int count, double distance,
                                                    const Eigen::Vector3d& object_position) {
  // The sphere's construction grows with the square of the count: 10000 held the server for
  // seconds (32 s under the fuzzer's sanitizers); 1000, ten times the default, a hundredth of that.
  if (count < 2 || count > kMaxSampledCandidates) {
    throw Error("The number of sampled candidate views must be between 2 and " +
                std::to_string(kMaxSampledCandidates) + ", got " + std::to_string(count) + ".");
  }
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw Error("The candidate camera distance must be positive and finite, got " +
                std::to_string(distance) + " m.");
  }
  checkFinitePosition(object_position, "object position");
  const ViewSphere sphere(count);
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(count);
  for (const auto& d : sphere.directions()) {
    // cameraFromObject looks at the origin of a frame with the fixed frame's axes; moving that
    // frame to the object's position gives T_WC.
    poses.push_back(Eigen::Translation3d(object_position) *
                    cameraFromObject(d, distance, 0.0).inverse());
  }
  return poses;
}

}  // namespace vdc
