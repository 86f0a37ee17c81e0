#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/common/progress.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/evaluation/camera_pose_error.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mesh_perturbation.h"
#include "view_direction_classification/geometry/triangle_mesh.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// The visibility "radius" of the unoccluded setting: every point is kept (no crop).
constexpr double kAllVisible = std::numeric_limits<double>::infinity();

// The paper's figure-4 protocol (doc/method.md section 11) and its extensions.
struct EvaluationSettings {
  int sequences = 20;
  int views = 20;  // views fused per sequence
  // Occlusion settings: radii [m] of the visible region around the anchors; kAllVisible keeps the
  // whole cloud. Empty: the unoccluded setting alone.
  std::vector<double> visibility_radii;
  std::uint32_t seed = 1;  // of every random choice: object orientations, views, sensor noise
  double distance = 0.6;   // camera to object origin [m]
  bool noise = true;       // Kinect axial noise on every rendered view
  // The depth camera imitated when noise is on (sensor_model.h).
  DepthSensor sensor = DepthSensor::kKinectGaussian;
  // Random camera poses per sequence the planners choose from (>= views). The random planner
  // takes the first `views` of them in order, so every planner starts from the same first view
  // and sees the same candidates.
  int candidates = 60;
  // Hypotheses per belief component for information_gain (see beliefHypotheses).
  int samples_per_component = 4;
  int threads = 0;  // OpenMP threads; <= 0: all cores
  EstimatorParameters estimator;
  // Camera streams (evaluation/stream_evaluation.h): frames per second of each sequence's
  // stream; 0: no stream, one cloud per view only.
  double stream_rate_hz = 0.0;
  double stream_dwell_s = 2.0;  // [s] the stream's camera stays this long at each view
  // The camera pose the estimator is given (camera_pose_error.h): the true one by default. The
  // views are always rendered from the true pose, and the errors measured against the truth.
  // The noise of a view is drawn per (seed, sequence, candidate view).
  CameraPoseError camera_pose_error;
  // The object the views are rendered from (mesh_perturbation.h), while the model comes from the
  // clean mesh: the given mesh by default. Its seed is replaced by `seed`: one perturbed object
  // per run, the same in every sequence.
  MeshPerturbation mesh_perturbation;
};

// Throws vdc::Error naming the first bad setting.
void checkEvaluationSettings(const EvaluationSettings& settings);

// The mesh the views are rendered from: `mesh` perturbed by settings.mesh_perturbation (with
// settings.seed), or `mesh` itself when the perturbation is the identity.
TriangleMesh renderedObjectMesh(const TriangleMesh& mesh, const EvaluationSettings& settings);

// The radii of the visibility settings: settings.visibility_radii, {kAllVisible} when empty.
std::vector<double> visibilityRadii(const EvaluationSettings& settings);
// Throws vdc::Error when a cropped setting has no anchors or an anchor is not finite.
void checkVisibilityAnchors(const std::vector<Eigen::Vector3d>& anchors,
                            const EvaluationSettings& settings);

// How the views after the first are chosen.
enum class EvaluationPlanner {
  kRandom,           // the paper's protocol: the sequence's random views in order
  kInformativeness,  // next_best_view.h utility 1 (the paper's proposal) over the candidates
  kInformationGain,  // next_best_view.h utility 2 over the candidates
};
// "random", "informativeness" or "information_gain": the name of the planner's results.
std::string evaluationPlannerName(EvaluationPlanner planner);

// One random view sequence: the object's fixed true orientation q_WO (the object sits at the
// world origin) and the candidate camera poses T_CO, each looking at the object origin from a
// direction uniform on the whole sphere, with uniform random roll, at the settings' distance.
struct EvaluationSequence {
  Eigen::Vector4d world_from_object = Eigen::Vector4d(1, 0, 0, 0);  // q_WO (w, x, y, z)
  std::vector<Eigen::Isometry3d> camera_from_object;                // settings.candidates poses
  Eigen::Isometry3d worldFromObject() const;
};
// Deterministic in (settings.seed, sequence) alone, so any subset of sequences can be rerun.
EvaluationSequence makeEvaluationSequence(const EvaluationSettings& settings, int sequence);

// The cloud of one view: rendered in the camera frame with the noise of (seed, sequence,
// candidate), so every planner and setting that picks this view sees the same noise, then
// cropped to the points within `radius` of any anchor (object frame) unless radius is
// kAllVisible.
pcl::PointCloud<pcl::PointXYZ> renderEvaluationView(const DepthRenderer& renderer,
                                                    const EvaluationSettings& settings,
                                                    int sequence, int candidate,
                                                    const Eigen::Isometry3d& camera_from_object,
                                                    const std::vector<Eigen::Vector3d>& anchors,
                                                    double radius);

// Orientation errors of one visibility setting.
struct SettingErrors {
  double radius = kAllVisible;
  double visible_fraction = 1.0;  // of the surface within radius of the anchors
  Eigen::MatrixXd errors_deg;     // sequences x views: error after each view [deg], in [0, 180]
  // sequences x views: distance of the estimated object origin from the true one after each
  // view [mm]; NaN where there is no position estimate.
  Eigen::MatrixXd position_errors_mm;
  int skipped_views = 0;  // views without a result (estimator: no update; baseline: no pose)
  // The estimator's trust signals after each view (sequences x views; empty for a single-view
  // method): distinct views in the belief, and the radius [deg] around the MAP that holds 90 %
  // of its mass (BeliefSpread::cone90).
  Eigen::MatrixXi views_fused;
  Eigen::MatrixXd cone90_deg;
  // Median over sequences after each view (views entries).
  Eigen::VectorXd medianPerView() const;
  // The calibration figure: the fraction of sequences whose MAP error after each view is at most
  // its cone90_deg (views entries; empty without trust signals). An honest belief gives ~0.9.
  Eigen::VectorXd insideCone90PerView() const;
  // The failure calibration exists to prevent: the fraction of sequences whose MAP error after
  // each view is more than twice its cone90_deg (the truth outside the cone by more than the
  // cone's width) and more than min_error_deg (so that tenths of a degree against a cone of
  // hundredths, the renders' floor, do not count). Empty without trust signals.
  static constexpr double kConfidentlyWrongMinDeg = 5.0;
  Eigen::VectorXd confidentlyWrongPerView(double min_error_deg = kConfidentlyWrongMinDeg) const;
  // The same for the position errors, over the sequences that have one (NaN: none has).
  Eigen::VectorXd medianPositionPerView() const;
  // sequences x views: the position error's Mahalanobis distance under the position covariance
  // the estimator reports with it (OrientationEstimator::positionCovariance), sqrt(e^T C^-1 e);
  // NaN where there is no position or no covariance. Empty for a single-view method.
  Eigen::MatrixXd position_mahalanobis;
  // The position's calibration figure: the fraction of the sequences with a covariance whose
  // true position lies inside the covariance's 90 % ellipsoid after each view (distance^2 at
  // most kChiSquare3At90, the 0.9 quantile of chi-square with 3 degrees of freedom). An honest
  // covariance gives ~0.9; NaN where no sequence has one, empty without the matrix.
  static constexpr double kChiSquare3At90 = 6.2514;
  Eigen::VectorXd positionInsideEllipsoid90PerView() const;
};

// The median of the `count` values that are not NaN; NaN when none is.
double medianIgnoringNaN(const double* values, Eigen::Index count);

// The number of views after which the median error (medianPerView) falls under `threshold_deg`
// and stays under it to the end of the sequence (a dip that comes back up does not count);
// nullopt if the last view's median is not under it.
std::optional<int> viewsUntilMedianStaysBelow(const Eigen::VectorXd& median_per_view,
                                              double threshold_deg);

struct EvaluationResult {
  std::string planner;  // "random", ..., or the single-view method's name
  std::vector<SettingErrors> settings;
  double mean_update_ms = 0;    // per view: the estimator's update (or the single-view method)
  UpdateTiming mean_stage_ms;   // the estimator's update by stage, per view (estimator only)
  double mean_planning_ms = 0;  // per planned view (0 for random)
  double mean_map_ms = 0;       // per view: the MAP search after the update (estimator only)
};

// Runs the protocol for one planner with the online estimator: per sequence and setting a fresh
// OrientationEstimator fuses `views` views; after each the MAP error against the true q_WO is
// recorded (rotationErrorDeg), and the position estimate's distance from the object origin. The
// anchors (object frame) centre the visibility crop; any mesh works. The (sequence, setting) runs
// are spread over OpenMP threads; each has its own generators, so results do not depend on the
// thread count. Throws vdc::Error for bad settings, a mesh or anchors that do not fit, or an
// estimator error.
EvaluationResult evaluateEstimator(std::shared_ptr<const ModelBundle> model,
                                   const TriangleMesh& mesh,
                                   const std::vector<Eigen::Vector3d>& anchors,
                                   EvaluationPlanner planner, const EvaluationSettings& settings,
                                   const ProgressCallback& progress = {});

// A single-view orientation method: camera-frame cloud in, T_CO out (empty: no estimate).
using SingleViewMethod =
    std::function<std::optional<Eigen::Isometry3d>(const pcl::PointCloud<pcl::PointXYZ>&)>;

// The same views as the random planner's, each judged alone by `method` (e.g. the PPF baseline):
// error of its orientation R_WC R_CO against q_WO, and of its translation. A view without an
// estimate counts as 180 degrees (the worst), no position (NaN) and as skipped. Runs sequentially
// (methods need not be thread-safe); mean_update_ms is the method's mean wall time per view.
EvaluationResult evaluateSingleView(const SingleViewMethod& method, const std::string& name,
                                    const TriangleMesh& mesh, const CameraIntrinsics& intrinsics,
                                    const std::vector<Eigen::Vector3d>& anchors,
                                    const EvaluationSettings& settings,
                                    const ProgressCallback& progress = {});

}  // namespace vdc
