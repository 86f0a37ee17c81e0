#include "view_direction_classification/evaluation/scene_metrics.h"

#include <algorithm>
#include <tuple>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"

namespace vdc {
namespace {

// A possible match: an estimate of the right model near a known object.
struct Candidate {
  double distance;
  int truth;
  int estimate;
};

std::vector<Candidate> candidatesWithin(const ViewTruth& truth,
                                        const std::vector<InstanceEstimate>& estimates,
                                        double match_distance) {
  std::vector<Candidate> candidates;
  for (std::size_t t = 0; t < truth.known.size(); ++t) {
    for (std::size_t e = 0; e < estimates.size(); ++e) {
      if (estimates[e].model != truth.known[t].model) continue;
      const double distance = (estimates[e].world_from_object.translation() -
                               truth.known[t].world_from_object.translation())
                                  .norm();
      if (distance <= match_distance) {
        candidates.push_back({distance, static_cast<int>(t), static_cast<int>(e)});
      }
    }
  }
  // Nearest first; ties in index order, so the result does not depend on the sort.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(a.distance, a.truth, a.estimate) < std::tie(b.distance, b.truth, b.estimate);
  });
  return candidates;
}

Eigen::Vector4d orientationOf(const Eigen::Isometry3d& pose) {
  return quaternionFromRotationMatrix(pose.linear());
}

IdentifiedInstance identified(const KnownObjectTruth& truth, const InstanceEstimate& estimate,
                              const Candidate& match) {
  IdentifiedInstance instance;
  instance.truth = match.truth;
  instance.estimate = match.estimate;
  instance.rotation_error_deg = rotationErrorDeg(orientationOf(estimate.world_from_object),
                                                 orientationOf(truth.world_from_object));
  instance.position_error = match.distance;
  instance.inside_cone90 = instance.rotation_error_deg <= estimate.cone90_deg;
  return instance;
}

bool onDistractor(const ViewTruth& truth, const InstanceEstimate& estimate, double match_distance) {
  return std::any_of(truth.distractors.begin(), truth.distractors.end(), [&](const auto& d) {
    const Eigen::Vector3d local =
        d.world_from_object.inverse() * estimate.world_from_object.translation();
    return d.bounds.exteriorDistance(local) <= match_distance;
  });
}

}  // namespace

ViewTruth viewTruth(const TableScene& scene, const SceneView& view) {
  if (view.known_visible_fraction.size() != scene.known.size()) {
    throw Error("the view's visible fractions do not belong to the scene's known objects");
  }
  ViewTruth truth;
  for (std::size_t i = 0; i < scene.known.size(); ++i) {
    truth.known.push_back({scene.known[i].model, scene.known[i].part.world_from_part,
                           view.known_visible_fraction[i]});
  }
  for (const ScenePart& part : scene.distractors) {
    truth.distractors.push_back({part.world_from_part, part.mesh.bounds().cast<double>()});
  }
  return truth;
}

SceneViewMetrics sceneViewMetrics(const ViewTruth& truth,
                                  const std::vector<InstanceEstimate>& estimates,
                                  const SceneMetricSettings& settings) {
  if (!(settings.visible_fraction >= 0.0) || !(settings.match_distance >= 0.0)) {
    throw Error("the scene metrics need a visible fraction and a match distance >= 0");
  }
  auto visible = [&](int t) { return truth.known[t].visible_fraction > settings.visible_fraction; };
  SceneViewMetrics metrics;
  for (std::size_t t = 0; t < truth.known.size(); ++t) {
    if (visible(static_cast<int>(t))) ++metrics.visible_known;
  }
  std::vector<bool> truth_taken(truth.known.size(), false);
  std::vector<bool> estimate_taken(estimates.size(), false);
  for (const Candidate& c : candidatesWithin(truth, estimates, settings.match_distance)) {
    if (truth_taken[c.truth] || estimate_taken[c.estimate]) continue;
    truth_taken[c.truth] = estimate_taken[c.estimate] = true;
    if (visible(c.truth)) {
      metrics.identified.push_back(identified(truth.known[c.truth], estimates[c.estimate], c));
    } else {
      ++metrics.matched_hidden;
    }
  }
  for (std::size_t e = 0; e < estimates.size(); ++e) {
    if (estimate_taken[e]) continue;
    metrics.false_identifications.push_back(
        {static_cast<int>(e), onDistractor(truth, estimates[e], settings.match_distance)});
  }
  return metrics;
}

}  // namespace vdc
