#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/planning/occluder_cloud.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// View utilities (doc/method.md section 10): a utility scores one candidate view, higher is
// better; choosing among the scored candidates is the planner's business (next_best_view.h). A
// candidate is scored by where its camera centre is relative to the object; the camera is assumed
// to look at the object (its roll does not matter: FPFH and the score matrix are roll-invariant).
// Higher utility = better view for both utilities.
enum class ViewUtility {
  kInformativeness,  // the paper's proposal: minus the mean surface score K of what is seen
  kInformationGain,  // beyond the paper: mutual information between hypothesis and measurement
};

// "informativeness" or "information_gain"; throws vdc::Error naming the accepted values.
ViewUtility parseViewUtility(const std::string& name);
std::string viewUtilityName(ViewUtility utility);

// One orientation hypothesis q_WO (w, x, y, z), unit, with its probability.
struct OrientationHypothesis {
  Eigen::Vector4d orientation;
  double weight = 0.0;
};

// The belief's components as hypotheses: each component's mode with its weight. A component's
// mode alone says nothing about how it spreads, so a diffuse component (the uniform prior, a
// girdle after one view) would collapse to one arbitrary orientation and every candidate would
// get zero information gain; `samples_per_component` > 0 adds that many fixed-seed samples of
// each component, sharing its weight with the mode. Throws vdc::Error for a negative count.
std::vector<OrientationHypothesis> beliefHypotheses(const BinghamMixture& belief,
                                                    int samples_per_component = 0,
                                                    std::uint64_t seed = 1);

// I(H; D) in nats for hypotheses h with weights w_h whose measurement distribution is row
// predicted_views[h] of the confusion matrix C (rows normalised here):
//   I = sum_h w_h sum_m C[v_h, m] ln(C[v_h, m] / p(m)),   p(m) = sum_h w_h C[v_h, m].
// Weights are normalised here. Throws vdc::Error for mismatched sizes, no hypotheses, a view out
// of range, negative or non-finite weights or weights summing to zero, or a confusion row that is
// negative, non-finite or sums to zero.
double mutualInformation(const Eigen::MatrixXd& confusion, const std::vector<int>& predicted_views,
                         const std::vector<double>& weights);

// Scores candidate views with the utilities of one model bundle; it chooses nothing (a planner
// ranks candidates with it, see next_best_view.h). Stateless after construction and const, so one
// scorer may serve several threads.
class ViewUtilityScorer {
 public:
  // Throws vdc::Error if the bundle's view directions, confusion matrix, view scores, surface
  // points, normals and score matrix do not agree in size.
  explicit ViewUtilityScorer(std::shared_ptr<const ModelBundle> model);

  const ModelBundle& model() const { return *model_; }
  int viewCount() const { return static_cast<int>(directions_.size()); }

  // Index of the training direction nearest to `direction` (object frame, any non-zero length).
  // Throws vdc::Error for a zero or non-finite vector.
  int nearestView(const Eigen::Vector3d& direction) const;

  // Utility 1 for a camera centre in the object frame (so its viewing direction is the
  // normalised camera_object, and m* its nearest training direction): minus the mean K[i, m*]
  // over the surface points facing the camera (n . (c - s) > 0), scored from m* (K != -1), and
  // not hidden by the occluder. If no surface point faces the camera with a valid score, the view
  // score falls back to -v(m*) (a view without training data, v = -1, scores worstUtility()). If
  // points qualify but the occluder hides all of them, the view shows nothing: worstUtility().
  // Throws vdc::Error for a zero or non-finite camera position.
  double informativeness(const Eigen::Vector3d& camera_object,
                         const OccluderCloud* occluder = nullptr) const;

  // Utility 2 for a camera centre in the fixed frame, the object's position in the fixed frame
  // and orientation hypotheses q_WO: hypothesis h sees the object from direction
  // R_h^T (c - p), i.e. training direction m*(h), and predicts the measurement C[m*(h), :];
  // the utility is their mutual information (nats, >= 0). Throws vdc::Error for non-finite input,
  // a camera at the object's position, or invalid hypotheses.
  double informationGain(const Eigen::Vector3d& camera_world, const Eigen::Vector3d& object_world,
                         const std::vector<OrientationHypothesis>& hypotheses) const;

  // The lowest informativeness: a view whose every feature is ruled out (-ln of the probability
  // floor of informativeness.h).
  static double worstUtility();

 private:
  std::shared_ptr<const ModelBundle> model_;
  std::vector<Eigen::Vector3d> directions_;
};

}  // namespace vdc
