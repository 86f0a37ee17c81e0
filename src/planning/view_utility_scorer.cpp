#include "view_direction_classification/planning/view_utility_scorer.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "position_check.h"
#include "view_direction_classification/bingham/bingham_sampler.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/informativeness/informativeness.h"

namespace vdc {

ViewUtility parseViewUtility(const std::string& name) {
  if (name == "informativeness") return ViewUtility::kInformativeness;
  if (name == "information_gain") return ViewUtility::kInformationGain;
  throw Error("Unknown next-best-view utility \"" + name +
              "\": use \"informativeness\" or \"information_gain\".");
}

std::string viewUtilityName(ViewUtility utility) {
  return utility == ViewUtility::kInformativeness ? "informativeness" : "information_gain";
}

std::vector<OrientationHypothesis> beliefHypotheses(const BinghamMixture& belief,
                                                    int samples_per_component, std::uint64_t seed) {
  if (samples_per_component < 0) {
    throw Error("The number of hypothesis samples per belief component must be >= 0, got " +
                std::to_string(samples_per_component) + ".");
  }
  std::mt19937_64 generator(seed);
  std::vector<OrientationHypothesis> hypotheses;
  hypotheses.reserve(belief.size() * static_cast<std::size_t>(1 + samples_per_component));
  const double share = 1.0 / (1.0 + samples_per_component);
  for (std::size_t k = 0; k < belief.size(); ++k) {
    const double weight = belief.weight(k) * share;
    hypotheses.push_back({belief.component(k).mode(), weight});
    if (samples_per_component == 0) continue;
    const BinghamSampler sampler(belief.component(k));
    for (int s = 0; s < samples_per_component; ++s) {
      hypotheses.push_back({sampler(generator).normalized(), weight});
    }
  }
  return hypotheses;
}

double mutualInformation(const Eigen::MatrixXd& confusion, const std::vector<int>& predicted_views,
                         const std::vector<double>& weights) {
  if (predicted_views.empty()) throw Error("The information gain needs at least one hypothesis.");
  if (predicted_views.size() != weights.size()) {
    throw Error("The information gain got " + std::to_string(predicted_views.size()) +
                " predicted views but " + std::to_string(weights.size()) + " weights.");
  }
  if (confusion.rows() != confusion.cols() || confusion.rows() == 0) {
    throw Error("The confusion matrix must be square and non-empty.");
  }
  const int views = static_cast<int>(confusion.rows());
  double weight_sum = 0.0;
  for (double w : weights) {
    if (!(w >= 0.0) || !std::isfinite(w)) {
      throw Error("A hypothesis weight is negative or not finite (" + std::to_string(w) + ").");
    }
    weight_sum += w;
  }
  if (!(weight_sum > 0.0)) throw Error("The hypothesis weights sum to zero.");

  // Normalised measurement distribution of each hypothesis, and their mixture p(m).
  Eigen::MatrixXd rows(predicted_views.size(), views);
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    const int v = predicted_views[h];
    if (v < 0 || v >= views) {
      throw Error("Predicted view " + std::to_string(v) + " is outside the " +
                  std::to_string(views) + " training views.");
    }
    const Eigen::RowVectorXd row = confusion.row(v);
    if (!row.allFinite() || (row.array() < 0.0).any() || !(row.sum() > 0.0)) {
      throw Error("Row " + std::to_string(v) +
                  " of the confusion matrix is negative, non-finite or all zero.");
    }
    rows.row(h) = row / row.sum();
  }
  Eigen::RowVectorXd marginal = Eigen::RowVectorXd::Zero(views);
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    marginal += (weights[h] / weight_sum) * rows.row(h);
  }
  double information = 0.0;
  for (std::size_t h = 0; h < predicted_views.size(); ++h) {
    const double w = weights[h] / weight_sum;
    if (w == 0.0) continue;
    for (int m = 0; m < views; ++m) {
      const double p = rows(h, m);
      // p > 0 implies marginal(m) >= w p > 0.
      if (p > 0.0) information += w * p * std::log(p / marginal(m));
    }
  }
  // Rounding can leave a tiny negative sum for identical predictions; I >= 0 exactly.
  return std::max(0.0, information);
}

ViewUtilityScorer::ViewUtilityScorer(std::shared_ptr<const ModelBundle> model)
    : model_(std::move(model)) {
  if (!model_) throw Error("The view utility scorer needs a model bundle.");
  const ModelBundle& b = *model_;
  const Eigen::Index views = static_cast<Eigen::Index>(b.view_directions.size());
  const Eigen::Index points = static_cast<Eigen::Index>(b.surface_points.size());
  if (views == 0) throw Error("The model bundle has no view directions.");
  const auto& vi = b.view_informativeness;
  if (vi.confusion.rows() != views || vi.confusion.cols() != views ||
      vi.view_scores.size() != views) {
    throw Error("The model bundle's confusion matrix or view scores do not match its " +
                std::to_string(views) + " view directions.");
  }
  if (static_cast<Eigen::Index>(b.surface_normals.size()) != points ||
      b.score_matrix.rows() != points || b.score_matrix.cols() != views) {
    throw Error("The model bundle's surface normals or score matrix do not match its " +
                std::to_string(points) + " surface points and " + std::to_string(views) +
                " view directions.");
  }
  for (const auto& d : b.view_directions) {
    if (!d.allFinite() || !(d.norm() > 0.0)) {
      throw Error("The model bundle has a zero or non-finite view direction.");
    }
    directions_.push_back(d.normalized());
  }
}

int ViewUtilityScorer::nearestView(const Eigen::Vector3d& direction) const {
  const double length = direction.norm();
  if (!std::isfinite(length) || !(length > 0.0)) {
    throw Error("A viewing direction must be a non-zero finite vector.");
  }
  int best = 0;
  double best_dot = -2.0;
  for (int m = 0; m < viewCount(); ++m) {
    const double dot = directions_[m].dot(direction) / length;
    if (dot > best_dot) {  // strict: ties go to the lower index, as ViewSphere::nearest
      best_dot = dot;
      best = m;
    }
  }
  return best;
}

double ViewUtilityScorer::worstUtility() { return std::log(kKlProbabilityFloor); }

double ViewUtilityScorer::informativeness(const Eigen::Vector3d& camera_object,
                                          const OccluderCloud* occluder) const {
  checkFinitePosition(camera_object, "camera position");
  const int view = nearestView(camera_object);
  const ModelBundle& b = *model_;
  std::vector<Eigen::Vector3d> seen_points;
  std::vector<double> seen_scores;
  for (std::size_t i = 0; i < b.surface_points.size(); ++i) {
    const double score = b.score_matrix(static_cast<Eigen::Index>(i), view);
    if (score < 0.0) continue;  // -1: never observed from m*
    const Eigen::Vector3d s = b.surface_points[i].cast<double>();
    if (b.surface_normals[i].cast<double>().dot(camera_object - s) <= 0.0) continue;
    seen_points.push_back(s);
    seen_scores.push_back(score);
  }
  if (seen_points.empty()) {
    const double v = b.view_informativeness.view_scores(view);
    return v >= 0.0 ? -v : worstUtility();
  }
  std::vector<bool> hidden(seen_points.size(), false);
  if (occluder != nullptr) hidden = occluder->hidden(camera_object, seen_points);
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < seen_points.size(); ++i) {
    if (hidden[i]) continue;
    sum += seen_scores[i];
    ++count;
  }
  return count > 0 ? -sum / count : worstUtility();
}

double ViewUtilityScorer::informationGain(
    const Eigen::Vector3d& camera_world, const Eigen::Vector3d& object_world,
    const std::vector<OrientationHypothesis>& hypotheses) const {
  checkFinitePosition(camera_world, "camera position");
  checkFinitePosition(object_world, "object position");
  const Eigen::Vector3d line_of_sight = camera_world - object_world;
  if (!(line_of_sight.norm() > 0.0)) {
    throw Error(
        "A candidate camera sits at the object's position, so it has no viewing direction.");
  }
  std::vector<int> views;
  std::vector<double> weights;
  views.reserve(hypotheses.size());
  weights.reserve(hypotheses.size());
  for (const auto& h : hypotheses) {
    checkUnitQuaternion(h.orientation, "an orientation hypothesis");
    // R_WO^T (c - p): the line of sight in the object frame under this hypothesis.
    views.push_back(nearestView(rotateVector(quaternionConjugate(h.orientation), line_of_sight)));
    weights.push_back(h.weight);
  }
  return mutualInformation(model_->view_informativeness.confusion, views, weights);
}

}  // namespace vdc
