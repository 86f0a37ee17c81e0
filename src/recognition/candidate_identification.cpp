#include "view_direction_classification/recognition/candidate_identification.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/training/model_training.h"

namespace vdc {

void checkIdentificationParameters(const IdentificationParameters& p) {
  if (!(p.extent_tolerance >= 0.0 && p.extent_tolerance < 1.0)) {
    throw Error("identification extent_tolerance must be in [0, 1), got " +
                std::to_string(p.extent_tolerance));
  }
  if (!(p.unknown_score >= -1.0 && p.unknown_score <= 1.0)) {
    throw Error("identification unknown_score must be in [-1, 1], got " +
                std::to_string(p.unknown_score));
  }
  if (!(p.temperature > 0.0) || !std::isfinite(p.temperature)) {
    throw Error("identification temperature must be a finite number > 0, got " +
                std::to_string(p.temperature));
  }
  if (!(p.min_probability >= 0.0 && p.min_probability <= 1.0)) {
    throw Error("identification min_probability must be in [0, 1], got " +
                std::to_string(p.min_probability));
  }
  if (!(p.track_probability >= 0.0 && p.track_probability <= 1.0)) {
    throw Error("identification track_probability must be in [0, 1], got " +
                std::to_string(p.track_probability));
  }
  if (!(p.drop_probability >= 0.0 &&
        p.drop_probability <= std::min(p.min_probability, p.track_probability))) {
    throw Error(
        "identification drop_probability must be in [0, min(min_probability, "
        "track_probability)], got " +
        std::to_string(p.drop_probability));
  }
  if (p.threads < 1) {
    throw Error("identification threads must be >= 1, got " + std::to_string(p.threads));
  }
  if (!(p.max_view_evidence > 0.0) || !std::isfinite(p.max_view_evidence)) {
    throw Error("identification max_view_evidence must be a finite number > 0, got " +
                std::to_string(p.max_view_evidence));
  }
}

std::vector<double> identityProbabilities(const std::vector<std::optional<double>>& scores,
                                          const IdentificationParameters& parameters) {
  std::vector<double> result(scores.size() + 1, 0.0);
  double best = parameters.unknown_score;
  for (const auto& score : scores) {
    if (score) best = std::max(best, *score);
  }
  // Shifted by the best score, so that no exponential overflows.
  double total = 0.0;
  for (std::size_t i = 0; i <= scores.size(); ++i) {
    const std::optional<double> score =
        i < scores.size() ? scores[i] : std::optional<double>(parameters.unknown_score);
    if (!score) continue;
    result[i] = std::exp((*score - best) / parameters.temperature);
    total += result[i];
  }
  for (double& probability : result) probability /= total;
  return result;
}

double identityEvidence(std::optional<double> identity_score,
                        const IdentificationParameters& parameters) {
  const double score = identity_score.value_or(parameters.unknown_score - 0.1);
  const double evidence = (score - parameters.unknown_score) / parameters.temperature;
  return std::clamp(evidence, -parameters.max_view_evidence, parameters.max_view_evidence);
}

namespace {

// The fitting models a candidate may be (allowed: per library model; empty: any).
std::vector<int> allowedFitting(const ModelLibrary& library, const Eigen::Vector3d& candidate_sides,
                                double extent_tolerance, const std::vector<bool>& allowed) {
  std::vector<int> fitting = library.fitting(candidate_sides, extent_tolerance);
  if (allowed.empty()) return fitting;
  fitting.erase(std::remove_if(fitting.begin(), fitting.end(),
                               [&](int m) {
                                 const auto k = static_cast<std::size_t>(m);
                                 return k >= allowed.size() || !allowed[k];
                               }),
                fitting.end());
  return fitting;
}

// Whether the simple shape behind model m's penalty (ShapeAlternative: unknown_score + the
// penalty is what the shape explains) explains the candidate at the search's threshold. Such a
// candidate is a box or a can as surely as a model's own pose must explain one to make the
// searches needless; searching for the model's pose anyway cost a box 2-3 times its
// identification and found nothing that could beat the shape (doc/evaluation.md). Models that
// are simple shapes themselves have no penalty, and search as before.
bool explainedByShape(const std::vector<double>& score_penalties, int m,
                      const IdentificationParameters& parameters, double search_below) {
  if (score_penalties.empty()) return false;
  const double penalty = score_penalties[static_cast<std::size_t>(m)];
  return penalty > 0.0 && parameters.unknown_score + penalty >= search_below;
}

// A candidate's features, computed once per feature setting among the models it is tried
// against (models trained with the defaults share them).
class SharedFeatures {
 public:
  explicit SharedFeatures(const pcl::PointCloud<pcl::PointXYZ>& points) : points_(points) {}
  std::shared_ptr<const FeatureSet> of(const FeatureParameters& parameters) {
    for (const auto& [settings, features] : computed_) {
      if (settings == parameters) return features;
    }
    computed_.emplace_back(parameters, std::make_shared<const FeatureSet>(computeFeatures(
                                           points_, parameters, Eigen::Vector3f::Zero())));
    return computed_.back().second;
  }
  int passes() const { return static_cast<int>(computed_.size()); }

 private:
  const pcl::PointCloud<pcl::PointXYZ>& points_;
  std::vector<std::pair<FeatureParameters, std::shared_ptr<const FeatureSet>>> computed_;
};

}  // namespace

Identification identifyCandidate(
    const ModelLibrary& library, const EstimatorParameters& instance_parameters,
    const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector3d& candidate_sides,
    const SceneDepth& scene, const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
    const IdentificationParameters& parameters, const std::vector<double>& score_penalties,
    const std::vector<bool>& allowed) {
  if (!score_penalties.empty() && static_cast<int>(score_penalties.size()) != library.size()) {
    throw Error("identification needs one score penalty per library model or none");
  }
  Identification result;
  result.scores.assign(library.size(), std::nullopt);
  std::vector<std::unique_ptr<OrientationEstimator>> estimators(library.size());
  std::vector<ViewUpdate> updates(library.size());
  const std::vector<int> fitting =
      allowedFitting(library, candidate_sides, parameters.extent_tolerance, allowed);
  // Every fitting model first refines its own belief; the searches beyond the beliefs (the
  // larger part of a model's cost) run only when no model explained the candidate at once.
  // The features first (shared, so computed before the models run side by side); each model's
  // estimator is its own, so the models' updates and searches are independent of each other and
  // of the order they run in.
  SharedFeatures features(points);
  std::vector<std::shared_ptr<const FeatureSet>> model_features(library.size());
  for (int m : fitting) {
    model_features[m] = features.of(featureParametersOf(library.models()[m].bundle->parameters));
  }
  result.feature_passes = features.passes();
  parallelFor(fitting.size(), parameters.threads, [&](int, std::size_t k) {
    const int m = fitting[k];
    estimators[m] =
        std::make_unique<OrientationEstimator>(library.models()[m].bundle, instance_parameters);
    updates[m] = estimators[m]->update(points, world_from_camera, time,
                                       {scene, BeliefSearch::kDeferred, model_features[m]});
  });
  const double search_below = instance_parameters.belief_check.search_below_score;
  const bool explained_at_once = std::any_of(fitting.begin(), fitting.end(), [&](int m) {
    return !updates[m].search_pending && updates[m].verified_score &&
           *updates[m].verified_score >= search_below;
  });
  if (!explained_at_once) {
    std::vector<int> searching;
    for (int m : fitting) {
      if (updates[m].search_pending &&
          !explainedByShape(score_penalties, m, parameters, search_below)) {
        searching.push_back(m);
      }
    }
    parallelFor(searching.size(), parameters.threads, [&](int, std::size_t k) {
      const int m = searching[k];
      updates[m] = estimators[m]->completeSearch(std::move(updates[m]));
    });
  }
  result.searched.assign(library.size(), false);
  for (int m : fitting) {
    result.searched[m] = updates[m].searched;
    result.scores[m] = updates[m].identity_score;
    if (result.scores[m] && !score_penalties.empty()) *result.scores[m] -= score_penalties[m];
  }
  result.probabilities = identityProbabilities(result.scores, parameters);
  const auto best = std::max_element(result.probabilities.begin(), result.probabilities.end());
  const int index = static_cast<int>(best - result.probabilities.begin());
  result.probability = *best;
  if (fitting.empty()) {
    result.reason = "no model of the library fits its size";
  } else if (index == library.size()) {
    result.reason = "no model explains it better than unknown";
  } else if (*best < std::min(parameters.track_probability, parameters.min_probability)) {
    result.reason = "no model is probable enough";
  } else {
    result.model = index;
    result.estimator = std::move(estimators[index]);
    // Its state as after any update (a search skipped by the others' settling one runs now).
    result.update = result.estimator->completeSearch(std::move(updates[index]));
  }
  return result;
}

bool lowerPenalties(const std::vector<double>& used, const std::vector<double>& lowered,
                    const IdentificationParameters& parameters, Identification* identification) {
  if (used.size() != identification->scores.size() ||
      lowered.size() != identification->scores.size()) {
    throw Error("lowering penalties needs the used and the lowered penalty of every library model");
  }
  std::vector<std::optional<double>> scores = identification->scores;
  for (std::size_t m = 0; m < scores.size(); ++m) {
    if (scores[m]) *scores[m] += used[m] - std::min(used[m], lowered[m]);
  }
  const std::vector<double> probabilities = identityProbabilities(scores, parameters);
  const auto best = std::max_element(probabilities.begin(), probabilities.end());
  if (best - probabilities.begin() != identification->model) return false;
  identification->scores = std::move(scores);
  identification->probabilities = probabilities;
  identification->probability = *best;
  return true;
}

}  // namespace vdc
