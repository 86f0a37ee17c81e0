#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/estimation/belief_check.h"
#include "view_direction_classification/estimation/belief_spread.h"
#include "view_direction_classification/estimation/estimator_snapshot.h"
#include "view_direction_classification/estimation/frame_selection.h"
#include "view_direction_classification/estimation/object_segmentation.h"
#include "view_direction_classification/estimation/object_tracking.h"
#include "view_direction_classification/estimation/orientation_filter.h"
#include "view_direction_classification/estimation/refined_measurement.h"
#include "view_direction_classification/estimation/refinement_mode.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/planning/view_utility_scorer.h"
#include "view_direction_classification/refinement/pose_refiner.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// Online settings of the estimator (config/estimator.yaml). Feature settings are not here: they
// come from the model bundle, so online features match the training ones.
struct EstimatorParameters {
  int n_feat = 0;      // most certain features summed per view; <= 0: the bundle's value
  double kappa = 0.0;  // girdle concentration; <= 0: defaultViewConcentration(view spacing)
  // K_max of the belief. The first value was 200; on the evaluation (10 x 12 views, all and r_vis
  // 5 cm) 50 gives the same median errors at a quarter of the fusion time (doc/method.md,
  // "Defaults").
  int max_components = 50;
  int min_features = 10;     // a view with fewer features is skipped (no update)
  double min_weight = 1e-3;  // measurement components below this p_sum are dropped
  // Exponent on the classifier's summed distribution before it weights the girdles
  // (sharpenedDistribution: p_sum^gamma renormalised; kappa unchanged). 1 leaves p_sum as it is;
  // above 1 narrows a belief that the flat p_sum makes too wide (doc/evaluation.md, calibration).
  double psum_exponent = 1.0;
  // Belief components lighter than this fraction of the heaviest are dropped after each fusion
  // (and their products never computed). 1e-3 gave the same median errors on the evaluation but
  // no faster updates in the estimator benchmark (fewer merges, more refits), so it stays 1e-6.
  double belief_weight_floor = 1e-6;
  // A product of two belief components one of which is at least this many times more
  // concentrated than the other keeps the sharper one's mode and shape, weighted by the other's
  // density there (0: every product exact). A verified pose (sigma 0.6-4 degrees) is 20-1000
  // times sharper than a view's girdle (concentration about 18 for 42 directions), whose slope
  // across it is the 30-degree view grid's artefact: exact products moved the MAP off the fitted
  // pose by a median 0.005 degrees, as much as the fit's own error (doc/method.md section 9).
  double sharpness_ratio = 10.0;
  // Segmentation of each cloud. Its roi_centre is a point of the fixed frame (where an object
  // stands still while the camera moves); update() moves it into each cloud's frame.
  SegmentationParameters segmentation;
  // Which frames of a stream are featurised and how much nearby views count.
  FrameSelectionParameters selection;
  // [m] The object's observed centroid jumping further than this from where it was tracked means
  // the object was moved: the belief is reset. Smaller moves are followed. 0: twice the largest
  // centroid offset of the model's views plus 2 cm (their centroids differ by up to that much).
  double max_object_shift = 0.0;
  // Geometric refinement after each fused view, on by default (doc/evaluation.md, "Refinement:
  // none against icp"). The estimator's hypotheses: the 2 heaviest
  // components, girdles every 30 degrees (ICP's basin of the roll is about +-45 degrees), the 3
  // best-screened starts of each aligned (max_refined 3): since the restarts about the axis of
  // near symmetry, the same medians as aligning every start on the mug and three untuned objects
  // at half the cost (doc/evaluation.md, "Refinement: none against icp").
  RefinementMode refinement = RefinementMode::kIcp;
  RefinementParameters refinement_parameters = [] {
    RefinementParameters p;
    p.hypotheses.max_components = 2;
    p.hypotheses.girdle_step_deg = 30.0;
    p.max_refined = 3;
    return p;
  }();
  RefinedFusionParameters refined_fusion;
  // Views refinement aligns and verifies together: this one and the latest refinement_views - 1
  // fused before it (their object points, voxel-filtered), in the fixed frame (>= 1). Each kept
  // pose's covariance still comes from this view's own fit. 1: this view alone; 3 was better by
  // some medians and worse by others at 60 % more refinement time (doc/evaluation.md).
  int refinement_views = 1;
  // What happens when a view's geometry contradicts the belief (belief_check.h): a search beyond
  // the belief's hypotheses and, where it finds a clearly better pose, the belief rebuilt.
  BeliefCheckParameters belief_check;
};

// Wall-clock time of each stage of one update [ms].
struct UpdateTiming {
  // selection: the tf-jump check, following the object and the novelty test (all a frame costs
  // that is not a new view).
  double selection = 0, segmentation = 0, features = 0, classification = 0, measurement = 0,
         fusion = 0, refinement = 0, total = 0;

  // Stage-wise sums and means over many updates (benchmarks, the evaluation).
  UpdateTiming& operator+=(const UpdateTiming& other) {
    selection += other.selection;
    segmentation += other.segmentation;
    features += other.features;
    classification += other.classification;
    measurement += other.measurement;
    fusion += other.fusion;
    refinement += other.refinement;
    total += other.total;
    return *this;
  }
  UpdateTiming& operator/=(double count) {
    selection /= count;
    segmentation /= count;
    features /= count;
    classification /= count;
    measurement /= count;
    fusion /= count;
    refinement /= count;
    total /= count;
    return *this;
  }
};

// What became of one frame.
enum class FrameOutcome {
  kFused,     // a new view: featurised and fused
  kNotNovel,  // a view already in the belief: not featurised, the belief is unchanged
  kSkipped,   // bad or unusable input (skip_reason says why), the belief is unchanged
};

// What one frame did.
struct ViewUpdate {
  FrameOutcome outcome = FrameOutcome::kSkipped;
  bool updated = false;     // outcome == kFused
  std::string skip_reason;  // why it was skipped (one sentence), empty otherwise
  // Non-empty when the estimator reset itself before this frame (the object was moved); the
  // frame was then treated as the first view.
  std::string reset_reason;
  int object_points = 0;  // points left after segmentation (0 when not segmented)
  int features = 0;
  // [rad] From the nearest fused view (pi for the first view; not computed for skipped frames
  // before the object was found) and the likelihood exponent that separation gave.
  double view_separation = M_PI;
  double likelihood_exponent = 1.0;
  Eigen::VectorXd p_sum;  // M, the view's summed distribution (when updated)
  Eigen::Vector3d observed_centroid_world = Eigen::Vector3d::Zero();
  // With refinement: the verified poses fused after this view (0: none verified, or skipped,
  // refinement_skip_reason then says why when the input was bad).
  int refined_poses = 0;
  // The best fused pose's verification score on this view (refined_poses > 0), in [-1, 1]: how
  // well the model explains the object's points and the scene around them.
  std::optional<double> verified_score;
  // The same pose's VerificationScore::identityScore (only samples on the side the camera sees
  // explain points): what the scene layer compares between models.
  std::optional<double> identity_score;
  // bestFittedIdentityScore of this view's refinement: whether the model fits the
  // view at all, also when the belief refused every pose. What the scene layer weighs an
  // instance's identity by after its first view: a belief that settled on a wrong orientation is
  // no evidence that the object is another.
  std::optional<double> fitted_identity_score;
  // That pose (world_from_object): where the model fits this view best, accepted or not.
  std::optional<Eigen::Isometry3d> fitted_pose;
  std::string refinement_skip_reason;
  // The belief's best pose fitted this view poorly, so a search beyond its hypotheses ran
  // (belief_check.h); rebuild_reason non-empty: the search's pose fitted the latest views clearly
  // better, and the belief was rebuilt from this view (says by how much).
  bool searched = false;
  std::string rebuild_reason;
  // Updated with BeliefSearch::kDeferred: the search was due and waits for completeSearch();
  // refinement's own poses are not fused yet, and verified_score and identity_score are theirs.
  bool search_pending = false;
  UpdateTiming timing;
};

// When update() runs a search beyond the belief that is due (belief_check.h).
enum class BeliefSearch {
  kWhenDue,  // at once, within update()
  // Left pending for completeSearch(): the scene layer tries a candidate against every model
  // that fits it and searches beyond their beliefs only when none explains it at once.
  kDeferred,
};

// What a caller that segmented the scene itself may give an update besides the cloud (the scene
// layer, whose candidates are the objects: segmentation `none`).
struct ViewContext {
  // What else the camera saw (camera frame): refinement verifies against it
  // (RefinementView::scene). Empty: the scene segmentation leaves (verificationScene).
  SceneDepth verification_scene;
  BeliefSearch search = BeliefSearch::kWhenDue;
  // The cloud's features, computed by the caller with the model's feature settings
  // (computeFeatures(cloud, featureParametersOf(model.parameters), origin)): a candidate tried
  // against several models with the same settings is described once. Only with segmentation
  // `none` (update() throws vdc::Error otherwise: the object's points would differ). Null: the
  // update computes them.
  std::shared_ptr<const FeatureSet> features;
};

// The paper's online estimator without ROS (doc/method.md sections 5, 8-10): one depth cloud of the
// object and the camera pose in the fixed frame in, the fused Bingham mixture over q_WO out.
class OrientationEstimator {
 public:
  // Throws vdc::Error for invalid parameters.
  OrientationEstimator(std::shared_ptr<const ModelBundle> model, EstimatorParameters parameters);

  // cloud: in the camera frame (any frame whose pose is world_from_camera; need not be optical,
  // need not be organised; NaN points allowed); time [s]: the frame's stamp, for the tf-jump
  // check (none: not checked). First selects (doc/method.md section 12): a camera pose that
  // jumped is skipped; the object is looked for where it was tracked (moved: the belief is reset;
  // not in view: skipped); a frame whose viewing direction is within min_view_separation of a
  // fused view is not novel and ends here. A new view is segmented (the region of interest
  // moved from the fixed frame into the cloud's frame with world_from_camera), featurised,
  // classified, the n_feat most certain features summed, its measurement built along the actual
  // line of sight to the object, tempered by its separation from the fused views, moved into the
  // fixed frame and fused. Never throws for cloud content: empty, NaN or too small clouds are
  // skipped with a reason. Throws vdc::Error for a non-finite pose.
  // context (ViewContext): when `cloud` is already the object (segmentation `none`, one
  // candidate of a scene), the scene it verifies against and its features; and whether a due
  // search runs at once. BeliefSearch::kDeferred leaves it pending (ViewUpdate::search_pending)
  // for completeSearch(); the next update() completes it first, reset() drops it.
  ViewUpdate update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                    const Eigen::Isometry3d& world_from_camera,
                    std::optional<double> time = std::nullopt, const ViewContext& context = {});
  // Runs the search an update() with BeliefSearch::kDeferred left pending and then fuses what
  // refinement kept, as update() would have: `update` (that update's result) comes back
  // completed (searched, rebuild_reason, refined_poses, the scores and the refinement time).
  // Without a pending search it comes back as it was.
  ViewUpdate completeSearch(ViewUpdate update);
  // Back to the uniform prior (forgets the fused views, the position and the track too).
  void reset();
  // New settings for the frames to come (a live reconfigure): checked as the constructor checks
  // them; a refused value throws vdc::Error and leaves every setting as it was. The belief, the
  // fused views and the track are kept: the next update() selects, measures and reduces with
  // the new settings. Not thread-safe with update(): the caller serialises them (the ROS node
  // calls both under one mutex, so a change lands between two frames).
  void setParameters(EstimatorParameters parameters);
  // The state a restart needs back (estimator_snapshot.h says what is left out), and the
  // estimator set to one: restore() throws vdc::Error for a snapshot that is not finite, whose
  // views or covariance are malformed or whose update_count is negative, and then changes
  // nothing. The camera's last pose and the latest views' points are cleared.
  EstimatorSnapshot snapshot() const;
  void restore(const EstimatorSnapshot& snapshot);

  const BinghamMixture& belief() const { return filter_.belief(); }
  // Measurements fused since the last reset: each view's, and its verified poses' when
  // refinement keeps any (so two for a refined view); viewsFused() counts the views.
  int updateCount() const { return filter_.updateCount(); }
  // Distinct views in the belief: the frames fused since the last reset.
  int viewsFused() const { return fused_views_.size(); }
  const FusedViews& fusedViews() const { return fused_views_; }
  Eigen::Vector4d mapOrientation() const;  // q_WO (w, x, y, z), w >= 0
  double entropy() const;
  // Object origin in the fixed frame: with refinement, the best verified pose's translation of
  // the last view that had one; else the last observed centroid minus R_WO times the stored
  // centroid offset of the training direction the camera sees it from under the MAP
  // orientation. Empty before the first update.
  std::optional<Eigen::Vector3d> positionEstimate() const;
  // [m^2, fixed frame] The position estimate's covariance from the refinement's fit (the best
  // verified pose's, PoseRefiner); empty when the position is not a refined one.
  std::optional<Eigen::Matrix3d> positionCovariance() const { return refined_position_covariance_; }
  // How far the belief spreads around its MAP (the 90 % cone and the covariance of the ROS
  // pose, from the same 1000 fixed-seed samples); computed once per belief.
  const BeliefSpread& spread() const;
  // 3 x 3 covariance of the orientation's rotation vector [rad^2] (world frame): spread().
  Eigen::Matrix3d orientationCovariance() const { return spread().covariance; }

  const ModelBundle& model() const { return *model_; }
  const EstimatorParameters& parameters() const { return parameters_; }
  double kappa() const { return kappa_; }

 private:
  // The selection stage of update(); false when the frame ends there (result says why).
  bool selectFrame(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                   const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                   ViewUpdate* result, bool* search_whole_view);
  // Whether a frame `separation` from the fused views is a new view.
  bool isNewView(const Eigen::Vector3d& camera_position, double separation) const;
  // Resets and says why in result->reset_reason.
  void resetForMovedObject(double shift, ViewUpdate* result);
  // The refinement after a fused view: verified poses fused as a measurement (the belief is
  // unchanged when none is verified or the input is bad), after a search beyond the belief where
  // its best pose fits the view poorly, which may rebuild the belief (belief_check.h).
  // measurement: the view's, in the fixed frame (a rebuilt belief starts from it);
  // line_of_sight: q_CL, the camera frame's turn onto the ray to the object.
  // `scene`: what else the camera saw (verificationScene; null: the object's points alone).
  // search: BeliefSearch::kDeferred leaves a due search and the fusion after it pending.
  void refineAfterFusion(const pcl::PointCloud<pcl::PointXYZ>& object_points,
                         const SceneDepth& scene, const Eigen::Isometry3d& world_from_camera,
                         const BinghamMixture& measurement, const Eigen::Vector4d& line_of_sight,
                         BeliefSearch search, ViewUpdate* result);
  // A search beyond the belief that is due: everything searchBeyondBelief needs.
  struct DueSearch {
    std::vector<RefinementView> views;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Isometry3d belief_pose = Eigen::Isometry3d::Identity();
    double belief_score = 0.0;
    BinghamMixture measurement;
    Eigen::Vector4d line_of_sight = Eigen::Vector4d(1, 0, 0, 0);
    RefinementResult refinement;  // the belief's own, replaced by the search's when it wins
  };
  // Keeps `view` (thinned) among the latest check_views and, where the belief's best pose
  // (refinement's, or without one the MAP at `position`) verifies below searchThreshold() on
  // it, returns the search that is due (belief_check.h).
  std::optional<DueSearch> searchDueOnView(const RefinementView& view,
                                           const std::vector<RefinementView>& views,
                                           const Eigen::Vector3d& position,
                                           const RefinementResult& refinement);
  // The view's kept poses fused as a measurement; the position estimate and the scores follow.
  // camera_position: the fixed frame's camera of the view refined (camera_pose_covariance.h).
  void fuseRefinement(const RefinementResult& refinement, const Eigen::Vector3d& camera_position,
                      ViewUpdate* result);
  // search_below_score, or lower once a search on this camera's views found nothing better
  // than a belief pose that verified at confirmed_fit_score_: rebuild_margin below that.
  double searchThreshold() const;
  // The search after the belief's best pose (refinement's, or its MAP) fitted poorly, verifying
  // at belief_score on this view (belief_check.h): replaces *refinement with the search's result
  // and rebuilds the belief from `measurement` when the geometry contradicts the belief.
  void searchBeyondBelief(const std::vector<RefinementView>& views, const Eigen::Vector3d& position,
                          const Eigen::Isometry3d& belief_pose, double belief_score,
                          const BinghamMixture& measurement, const Eigen::Vector4d& line_of_sight,
                          RefinementResult* refinement, ViewUpdate* result);
  // The search's hypotheses: every training direction's girdle along the line of sight, equally
  // weighted, in the fixed frame.
  BinghamMixture searchBelief(const Eigen::Vector4d& line_of_sight,
                              const Eigen::Isometry3d& world_from_camera) const;
  // Keeps the view (thinned) among the refinement_views - 1 latest for the next refinements.
  void rememberRefinedView(const RefinementView& view);
  // Fixed-frame point the viewing directions are measured from: the position estimate, or the
  // tracked centroid before the first view.
  Eigen::Vector3d viewingReference() const;

  std::shared_ptr<const ModelBundle> model_;
  EstimatorParameters parameters_;
  double kappa_;
  ObjectExtent extent_;
  double min_view_separation_, independent_view_separation_, max_object_shift_;
  SightingParameters sighting_;
  OrientationFilter filter_;
  FusedViews fused_views_;
  std::optional<ObjectTrack> track_;
  std::optional<StampedPose> last_pose_;
  std::optional<Eigen::Vector3d> last_centroid_world_, last_camera_position_world_;
  std::shared_ptr<const PoseRefiner> refiner_;  // only with RefinementMode::kIcp
  std::optional<Eigen::Vector3d> refined_position_;
  std::optional<Eigen::Matrix3d> refined_position_covariance_;
  std::deque<RefinementView> refined_views_;  // latest first, object points voxel-filtered
  // With belief_check.search_below_score > 0: the search's refiner (the same surfaces), and
  // the latest belief_check.check_views views (this one first, voxel-filtered) both poses are
  // judged on.
  std::shared_ptr<const PoseRefiner> search_refiner_;
  std::deque<RefinementView> check_views_;
  // The score (at least refinement's min_score) the belief's best pose reached on the latest
  // view a search confirmed it on (the search found no clearly better pose): what a right pose
  // reaches with this camera, whose noise may keep it below search_below_score on every view (a
  // stereo camera: 0.90). Later views search only when they fit clearly worse. Cleared with the
  // belief.
  std::optional<double> confirmed_fit_score_;
  // Left by update() with BeliefSearch::kDeferred until completeSearch().
  std::optional<DueSearch> pending_search_;
  // Only when selection.min_information_gain > 0.
  std::shared_ptr<const ViewUtilityScorer> gain_scorer_;
  // The MAP costs a search over every component: computed once per belief, on first request;
  // the spread and the information-gain hypotheses likewise.
  mutable std::optional<Eigen::Vector4d> map_cache_;
  mutable std::optional<BeliefSpread> spread_cache_;
  mutable std::optional<std::vector<OrientationHypothesis>> hypotheses_cache_;
};

}  // namespace vdc
