#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/recognition/model_library.h"

namespace vdc {

struct IdentificationParameters {
  // A candidate fits a model when its size does (ModelLibrary::fitting).
  double extent_tolerance = 0.15;
  // Each fitting model's best verified pose on the view scores s_m in [-1, 1], its identity
  // score (ViewUpdate::identity_score: points explained only by the model's sides the camera
  // sees; none verified: not a candidate model). "Unknown" scores unknown_score, refinement's
  // acceptance: a model that explains the candidate barely as well as that is as likely as no
  // model. The probabilities are a softmax of the scores over `temperature`: 0.05 makes a 0.05
  // better score e times as likely.
  double unknown_score = 0.8;
  double temperature = 0.05;
  // An instance is reported (identified) while its identity probability is at least
  // min_probability. A candidate becomes an instance already when its most probable model reaches
  // track_probability (or min_probability, if that is lower), else it is unknown: a tentative
  // instance fuses the next views, whose evidence (identityEvidence) confirms it or drops it. One
  // view of a small piece can make a wrong model about as probable as a right one on a whole
  // object (0.5-0.85 against 0.9-0.98 in the scene evaluation, doc/evaluation.md), and the next
  // views tell them apart.
  double min_probability = 0.8;
  double track_probability = 0.5;
  // After identification each fused view of an instance adds its evidence (identityEvidence);
  // an instance whose probability falls below this is dropped: one view can make a box look
  // like a mug's side, the next ones do not.
  double drop_probability = 0.2;
  // [log-odds] The most one view can add or take: no single view decides alone.
  double max_view_evidence = 3.0;
  // Fitting models tried on a candidate at once, each on its own thread (each model's refinement
  // runs its own threads beside them). Their results do not depend on it.
  int threads = 2;
};

// Throws vdc::Error naming the first bad parameter.
void checkIdentificationParameters(const IdentificationParameters& parameters);

// Softmax of the models' scores (nullopt: no verified pose, probability 0) and unknown_score;
// the last entry is "unknown". Sums to 1.
std::vector<double> identityProbabilities(const std::vector<std::optional<double>>& scores,
                                          const IdentificationParameters& parameters);

// One fused view's evidence for an instance's model against "unknown", in log-odds: (s -
// unknown_score) / temperature for the view's best pose's identity score s, capped at
// +-max_view_evidence; a view on which no pose verified counts as s = unknown_score - 0.1.
double identityEvidence(std::optional<double> identity_score,
                        const IdentificationParameters& parameters);

// What one candidate is.
struct Identification {
  std::vector<double> probabilities;  // per library model, "unknown" last
  // Per library model, after its penalty (nullopt: not fitting or none verified).
  std::vector<std::optional<double>> scores;
  int model = -1;            // the identified model, -1: unknown
  double probability = 0.0;  // of `model` (of unknown when -1)
  // The identified model's estimator, which has fused this view (null when unknown).
  std::unique_ptr<OrientationEstimator> estimator;
  ViewUpdate update;   // that estimator's update
  std::string reason;  // why the candidate is unknown (empty when identified)
  // Per library model: whether its search beyond the belief ran (belief_check.h).
  std::vector<bool> searched;
  // How often the candidate's features were computed: once per distinct feature setting among
  // the models tried.
  int feature_passes = 0;
};

// Identifies one candidate: a fresh estimator of each model whose size fits (instance settings,
// segmentation `none`) fuses and refines the candidate's points, verified against `scene`
// (occluders explain hidden parts, free space contradicts); the identity scores give the
// probabilities, each lowered by its entry of score_penalties (per library model, empty: none;
// ShapeAlternative). points and scene in the camera frame. allowed (per library model; empty:
// all) leaves the other models untried: a detector's class names the one model it may be.
// The models' searches beyond their beliefs (belief_check.h) run only when no model's own
// belief gave a pose verifying at the search's threshold (search_below_score): on known objects
// the others' searches never beat a model that explains the candidate at once
// (doc/evaluation.md), and they are most of the cost. Nor does a model search where its penalty
// says a simple shape explains the candidate at that threshold (unknown_score + penalty >=
// search_below_score): a box or a can, as surely as a model's pose must explain a candidate.
Identification identifyCandidate(
    const ModelLibrary& library, const EstimatorParameters& instance_parameters,
    const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector3d& candidate_sides,
    const SceneDepth& scene, const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
    const IdentificationParameters& parameters, const std::vector<double>& score_penalties = {},
    const std::vector<bool>& allowed = {});

// Judges `identification` again with each model's penalty `used` (what its scores carry, as
// given to identifyCandidate) lowered to `lowered` where that is less: the scores regain the
// difference and the probabilities follow. Returns false and changes nothing when its model
// would then no longer be the most probable (the identification holds that model's estimator).
bool lowerPenalties(const std::vector<double>& used, const std::vector<double>& lowered,
                    const IdentificationParameters& parameters, Identification* identification);

}  // namespace vdc
