#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/planning/view_utility_scorer.h"

namespace vdc {

// What a planner chooses the next view from (doc/method.md section 10): candidate camera poses
// around the object and their ranking by a view utility (view_utility_scorer.h scores one
// candidate; the planner, e.g. the server's ~next_best_view or planner_loop.py, takes the best).

struct NextBestViewOptions {
  // Hypotheses per belief component (see beliefHypotheses) for information_gain.
  int samples_per_component = 0;
  std::uint64_t seed = 1;
};

// What a planner needs besides the candidates: the object's position in the fixed frame, its
// belief over q_WO, the orientation under which informativeness is evaluated (normally the
// belief's MAP) and an optional occluder in the fixed frame.
struct PlanningScene {
  Eigen::Vector3d object_position = Eigen::Vector3d::Zero();
  BinghamMixture belief;
  Eigen::Vector4d orientation = Eigen::Vector4d(1, 0, 0, 0);
  std::vector<Eigen::Vector3d> occluder_world;  // empty: no occluder
  double occluder_radius = 0.005;
};

struct RankedCandidate {
  int index = 0;         // into the candidate list
  double utility = 0.0;  // higher is better
  int view = 0;          // m* under scene.orientation
};

// Scores every candidate camera centre (fixed frame) with the utility and sorts them by
// descending utility (ties by lower index). Throws vdc::Error for no candidates, a non-finite
// candidate or one at the object's position, a non-unit orientation or a bad occluder.
std::vector<RankedCandidate> rankCandidates(const ViewUtilityScorer& scorer,
                                            const std::vector<Eigen::Vector3d>& camera_positions,
                                            ViewUtility utility, const PlanningScene& scene,
                                            const NextBestViewOptions& options = {});

// `count` candidate camera poses T_WC (optical frame: z towards the object centre, the fixed
// frame's +z up in the image) at `distance` around `object_position`, near-uniform on the sphere
// (ViewSphere directions). Throws vdc::Error for count < 2 or > kMaxSampledCandidates, or a
// non-positive or non-finite distance.
constexpr int kMaxSampledCandidates = 1000;
std::vector<Eigen::Isometry3d> sampleCandidatePoses(int count, double distance,
                                                    const Eigen::Vector3d& object_position);

}  // namespace vdc
