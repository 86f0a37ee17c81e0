#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/refinement/model_surface.h"
#include "view_direction_classification/refinement/pose_hypotheses.h"
#include "view_direction_classification/refinement/pose_verification.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// Settings of the geometric refinement (doc/method.md, "Refinement").
struct RefinementParameters {
  HypothesisParameters hypotheses;
  VerificationParameters verification;
  double model_spacing = 0.004;  // [m] the bundle's surface set thinned to this for ICP and scores
  double scene_voxel = 0.004;    // [m] the observed points are voxel-filtered to this for ICP
  int min_points = 50;           // fewer finite observed points: refinement is skipped
  // Screening: every start is first scored by the mean distance of about screening_points of the
  // observed points to the model's surface (truncated at max_correspondence_distance), and only
  // the max_refined best of each belief component are aligned by ICP and verified (<= 0: every
  // start). ICP is the cost
  // (milliseconds per start), screening a fraction of a millisecond per start.
  int max_refined = 3;
  // false: the max_refined best starts over all components together (a search over many
  // equally likely girdles, where per component would align dozens).
  bool screen_per_component = true;
  int screening_points = 200;
  // A piece of an object (its observed points spread less than piece_spread_ratio of the model's
  // visible part, by RMS radius: cut off at a concave edge, or the rest hidden) is also placed
  // with its centroid at up to piece_placements patches of the visible part, each screened as a
  // start of its own (0: at the visible part's centroid only).
  int piece_placements = 4;
  double piece_spread_ratio = 0.9;
  // An observation whose bounding box diagonal exceeds this many model diagonals is not (only)
  // the object: skipped.
  double max_extent_ratio = 2.0;
  // Point-to-plane ICP (PCL), about icp_points of the observed points (voxel-filtered, then every
  // k-th; <= 0: all of them) against the model's surface. Its cost grows with them; a few hundred
  // well-spread points pin down six degrees of freedom as well as thousands.
  int icp_points = 400;
  int max_iterations = 100;  // not converged within these: refused
  // A start's ICP still moving after restart_screening_iterations whose pose then verifies below
  // continue_min_score is abandoned (refused) there: it has not brought a third of the points
  // onto the surface and crawls on (59 iterations, a quarter of a mug's first view) to a pose
  // verification refuses. It costs one verification more per start not converged by then.
  double continue_min_score = 0.3;
  // Screened once more after late_screening_iterations (<= restart_screening_iterations: not):
  // an ICP still moving then whose pose verifies below late_continue_min_score is abandoned too.
  // Such ICPs crawl on to the iteration limit or to a pose verification refuses.
  int late_screening_iterations = 30;
  double late_continue_min_score = 0.45;
  double max_correspondence_distance = 0.015;  // [m]
  // Converged when a step moves the pose by less than both of these.
  double convergence_translation = 1e-4;  // [m]
  double convergence_rotation_deg = 0.05;
  // ICP moving the pose further than this from its start has left the hypothesis: refused. A
  // piece's starts are placed on a few patches of the visible part, which on a mug seen around
  // its handle leaves the right one 3-5 cm from the truth (3 cm refused right poses verifying
  // best of all, and the belief kept their twins alone).
  double max_translation_step = 0.06;   // [m]
  double max_rotation_step_deg = 45.0;  // [deg]
  // Acceptance: the verification score (inliers minus violations) at least min_score and not
  // more than keep_score_margin lower than the start's, and the belief's log density at the refined
  // orientation at most max_log_density_drop below the start's (the result stays in the belief's
  // credible region: ln 1000 by default).
  double min_score = 0.8;
  double max_log_density_drop = 6.9;
  // Restarts (doc/method.md, "Refinement"): ICP on a nearly symmetric object converges to the
  // right body in the wrong turn (a mug's handle on the wrong side), which no other start may
  // reach. The restart_seeds best-scoring distinct converged poses are each turned about the
  // model's axis of near symmetry (model_surface.h) by every multiple of restart_step_deg and by
  // half a turn about its other two axes; each turned pose is aligned by a short ICP of
  // restart_screening_iterations and verified (as it stands the body's misfit hides the handle),
  // and the restart_refined best of each seed aligned in full and verified like any start
  // (restart_seeds 0: no restarts). A turn the belief finds more than
  // restart_max_log_density_drop less likely than its seed's start is not tried: it could only
  // be accepted back on the seed (ln 1e30 by default: every turn of a first view's girdles is
  // tried, none once verified poses have made the belief sharp). Of the restart_refined best
  // turns, one still verifying more than restart_score_margin below its seed after the short ICP
  // is not aligned further. The half turns are about the lines half_turn_axes.h finds. With
  // restart_rounds 2, a restart that beats every seed is turned once more by its half turns (a seed
  // a few degrees off the truth turns onto the twin exactly, and only the twin's turn lands on
  // the truth); 1: the seeds' restarts only.
  int restart_seeds = 1;
  int restart_rounds = 2;
  double restart_step_deg = 30.0;
  int restart_screening_iterations = 10;
  int restart_refined = 2;
  double restart_max_log_density_drop = 69.0;
  double restart_score_margin = 0.1;
  // Only a converged pose verifying at least restart_min_score seeds restarts: a pose explaining
  // less than half of the points is mostly another model's misfit, not the truth turned (on the
  // five-model scene command 3 of 474 such restarts reached min_score; skipping them saves a
  // fifth of a scene's CPU and cost one spool in 538 identifications, doc/performance.md).
  double restart_min_score = 0.5;
  // Threads that align starts (each ICP is independent; the result does not depend on them).
  int threads = 2;
  // Accepted poses scoring within keep_score_margin of the best are kept; poses within
  // duplicate_angle_deg and duplicate_distance of a better one are the same pose.
  double keep_score_margin = 0.03;
  // Roll sectors (doc/method.md, "Refinement"): each kept pose is turned about the model's axis
  // of near symmetry by multiples of restart_step_deg, without ICP, while the turns still score
  // within keep_score_margin; how far they do is the pose's roll sector, which its measurement
  // leaves free (a spool's every turn, a mug seen from behind its handle). false: every kept pose
  // is a sharp pose, however symmetric the object.
  bool roll_sectors = true;
  double duplicate_angle_deg = 5.0;
  double duplicate_distance = 0.005;  // [m]
  // Alternatives (doc/method.md, "Refinement"): up to max_alternatives distinct converged poses
  // verifying within measurement_score_margin of the best kept one, neither kept nor on a kept
  // pose's roll sector, enter the view's measurement beside the kept ones, whatever refused them
  // (a score just below min_score, a long ICP step, the credible region), weighted by their
  // verification like them; they are not reported or polished. A pose 0.04 behind is then
  // e^-0.8 as likely (refined_measurement.h), not excluded: seen around its handle, a mug's
  // upside-down twin verifies a few hundredths better or worse from view to view, and the view
  // that left the truth out made the belief sure of the twin. 0 alternatives: the kept alone.
  double measurement_score_margin = 0.1;
  int max_alternatives = 4;
  // A kept pose's translation covariance (fit_covariance.h) has principal standard deviations in
  // [min_position_sigma, max_position_sigma]: the fit's matches are not independent, so below
  // about a quarter of the model's 4 mm sample spacing its own figure would be over-confident.
  double min_position_sigma = 0.001;  // [m]
  double max_position_sigma = 0.05;   // [m]
  // The same for its orientation (fit_covariance.h), principal standard deviations of a turn in
  // [floor, max_rotation_sigma_deg], the floor being min_rotation_sigma_deg or min_position_sigma
  // over the matched points' spread, whichever is larger (a 5 cm patch: about 4 degrees, a whole
  // mug view about 1.5); 4.05 degrees is a Bingham concentration of 400, what every kept pose
  // was given before the fit's covariance was used.
  double min_rotation_sigma_deg = 1.0;
  double max_rotation_sigma_deg = 4.05;
  // Polish: each kept pose is aligned once more on every observed point voxel-filtered to
  // polish_scene_voxel (not about icp_points of them at scene_voxel) against the bundle's samples
  // at polish_model_spacing (the PoseRefiner built from a bundle; from a ModelSurface, that
  // surface), with correspondences within polish_correspondence_distance. The polished pose
  // replaces it when ICP converged within duplicate_angle_deg and duplicate_distance of it and
  // it verifies no more than polish_score_tolerance worse: a more precise fit moves points by a
  // fraction of a millimetre, which tips a few across the inlier tolerance either way (0.005
  // of the score is about 5 of a 4 mm view's ~1000 points). 0 iterations: no polish.
  int polish_iterations = 20;
  double polish_correspondence_distance = 0.005;  // [m]
  double polish_model_spacing = 0.002;            // [m]
  double polish_scene_voxel = 0.002;              // [m]
  double polish_score_tolerance = 0.005;
};

// One hypothesis and what refinement made of it.
struct RefinedPose {
  Eigen::Vector4d start_orientation = Eigen::Vector4d(1, 0, 0, 0);  // q_WO, from the belief
  int component = 0;                                                // its belief component
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();          // world_from_object before ICP
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();  // after ICP
  Eigen::Vector4d orientation = Eigen::Vector4d(1, 0, 0, 0);  // q_WO of world_from_object, w >= 0
  VerificationScore start_score, score;                       // (only for screened-in starts)
  // [m] The start's screening distance: the observed points' mean truncated distance to the model.
  double screening_distance = 0.0;
  bool screened_in = false;  // among its component's max_refined best: aligned and verified
  // The index in RefinementResult::tried of the converged pose this start was turned from (a
  // restart); -1 for the belief's own starts.
  int restarted_from = -1;
  bool converged = false;  // ICP converged (and was not degenerate)
  double fitness = 0.0;    // [m^2] ICP's mean squared correspondence distance
  int icp_iterations = 0;
  // [m^2, fixed frame] Covariance of world_from_object's translation from the fit (kept poses
  // only; zero otherwise).
  Eigen::Matrix3d position_covariance = Eigen::Matrix3d::Zero();
  // [rad^2, object frame] Covariance of its orientation from the fit, as a turn t applied as
  // world_from_object * exp(t) (kept poses only; zero otherwise).
  Eigen::Matrix3d rotation_covariance = Eigen::Matrix3d::Zero();
  // [deg] Kept poses only: turns about sector_axis (object frame: the model's axis of near
  // symmetry) up to this verify as well as the pose itself, so geometry leaves them open; 0: it
  // fixes the roll, 180: any turn.
  double roll_sector_deg = 0.0;
  Eigen::Vector3d sector_axis = Eigen::Vector3d::UnitZ();
  bool accepted = false;
  std::string rejection;  // why it was refused (one sentence), empty when accepted
};

struct RefinementResult {
  std::string skip_reason;  // non-empty: bad input, nothing was tried
  // Every hypothesis, in the order they were made; those screened out have a rejection saying so.
  std::vector<RefinedPose> tried;
  // The distinct accepted poses within keep_score_margin of the best, best first, each with its
  // roll sector; a pose on a better one's sector is not distinct. Empty when skipped or nothing
  // was accepted; several where geometry cannot tell them apart.
  std::vector<RefinedPose> kept;
  // Distinct poses beside the kept ones that still enter the measurement (measurement_score_margin
  // above), best first; their covariances are not computed (zero).
  std::vector<RefinedPose> alternatives;
  double milliseconds = 0.0;
  bool skipped() const { return !skip_reason.empty(); }
};

// The best VerificationScore::identityScore of the poses ICP aligned and verified, accepted or
// not: how well the model explains the view whatever the belief says of its orientation (a pose
// refused for leaving the belief's credible region may explain it well). Nothing when no pose
// was aligned.
std::optional<double> bestFittedIdentityScore(const RefinementResult& refinement);
// That pose (null when no pose was aligned): where the model fits best, whatever the belief says.
const RefinedPose* bestFittedPose(const RefinementResult& refinement);

// The view's points voxel-filtered to `voxel` [m] (PCL's VoxelGrid, one centroid per occupied
// cell), the same camera pose: what refinement scores and aligns (a 640 x 480 view of the mug
// has ~10 000 points, a few hundred at 4 mm). Kept views are stored this way.
RefinementView thinnedView(const RefinementView& view, double voxel);

// Hypothesis refinement after fusion (doc/method.md, "Refinement"): the belief's leading
// orientations (pose_hypotheses.h) are each placed so that the model's camera-facing centroid
// meets the observed centroid and screened; the best are aligned to the observed points by
// point-to-plane ICP against the model's surface samples, and verified (pose_verification.h).
// No ROS; refine() is const.
class PoseRefiner {
 public:
  // Throws vdc::Error for invalid parameters.
  PoseRefiner(std::shared_ptr<const ModelSurface> surface, RefinementParameters parameters = {});
  // The bundle's surface set S (with its normals and extent) thinned to model_spacing.
  PoseRefiner(const ModelBundle& model, RefinementParameters parameters = {});
  // other's surfaces (shared, not copied) with other settings: the same model_spacing, and the
  // same polish_model_spacing unless these do not polish. Throws vdc::Error for invalid
  // parameters or other spacings.
  PoseRefiner(const PoseRefiner& other, RefinementParameters parameters);

  // belief: over q_WO (fixed frame). position: the current estimate of the object origin in the
  // fixed frame. views: the object's points (camera frames) with their camera poses; several
  // views are aligned together in the fixed frame. Never throws for input content: too few
  // finite points, a non-finite position or camera pose, or points spread far beyond the
  // model's size give skip_reason and no poses.
  RefinementResult refine(const BinghamMixture& belief, const Eigen::Vector3d& position,
                          const std::vector<RefinementView>& views) const;

  const RefinementParameters& parameters() const { return parameters_; }
  const ModelSurface& surface() const { return *surface_; }
  const std::shared_ptr<const ModelSurface>& sharedSurface() const { return surface_; }

 private:
  std::shared_ptr<const ModelSurface> surface_;
  std::shared_ptr<const ModelSurface> polish_surface_;  // the polish's target (finer)
  RefinementParameters parameters_;
};

}  // namespace vdc
