#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// Next-best-view utilities over candidate camera positions (doc/method.md section 10). A candidate is
// scored by where its camera centre is relative to the object; the camera is assumed to look at
// the object (its roll does not matter: FPFH and the score matrix are roll-invariant).
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

// An occluder point cloud in the object frame (e.g. the clutter around the object). A surface
// point s is hidden from a camera at c if an occluder point lies within `radius` of the segment
// from s to c; the first 2 * radius of the segment next to s are left out, so occluder points on
// the object's own surface (or touching it) do not hide the point they lie on.
// Per candidate the occluder points in front of the camera are projected onto its image plane
// and put in a kd-tree (pcl::KdTreeFLANN); a surface point's neighbours within a conservative
// image radius are then tested exactly (point-to-segment distance), so the test is exact and
// costs O(log n) per surface point.
class OccluderCloud {
 public:
  // Throws vdc::Error for an empty cloud, a non-finite point or a non-positive radius.
  explicit OccluderCloud(std::vector<Eigen::Vector3d> points_object, double radius = 0.005);
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  double radius() const { return radius_; }

  // For each query point, whether it is hidden from the camera centre camera_object (object
  // frame). Throws vdc::Error for a non-finite camera position.
  std::vector<bool> hidden(const Eigen::Vector3d& camera_object,
                           const std::vector<Eigen::Vector3d>& surface_points) const;

 private:
  std::vector<Eigen::Vector3d> points_;
  double radius_;
};

struct NextBestViewOptions {
  // Hypotheses per belief component (see beliefHypotheses) for information_gain.
  int samples_per_component = 0;
  std::uint64_t seed = 1;
};

// The utilities on one model bundle. Stateless after construction and const, so one planner may
// serve several threads.
class NextBestViewPlanner {
 public:
  // Throws vdc::Error if the bundle's view directions, confusion matrix, view scores, surface
  // points, normals and score matrix do not agree in size.
  explicit NextBestViewPlanner(std::shared_ptr<const ModelBundle> model);

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
std::vector<RankedCandidate> rankCandidates(const NextBestViewPlanner& planner,
                                            const std::vector<Eigen::Vector3d>& camera_positions,
                                            ViewUtility utility, const PlanningScene& scene,
                                            const NextBestViewOptions& options = {});

// `count` candidate camera poses T_WC (optical frame: z towards the object centre, the fixed
// frame's +z up in the image) at `distance` around `object_position`, near-uniform on the sphere
// (ViewSphere directions). Throws vdc::Error for count < 2 or > 10000, or a non-positive or
// non-finite distance.
std::vector<Eigen::Isometry3d> sampleCandidatePoses(int count, double distance,
                                                    const Eigen::Vector3d& object_position);

}  // namespace vdc
