#pragma once

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/learning/log_loss.h"

namespace vdc {

// View and surface informativeness (doc/method.md sections 6-7, the paper's sections III-IV).

// The paper's eq. (2): d_KL(p* || p_sum) = -ln p_sum(true_view), p* one-hot at true_view, floored
// at kKlProbabilityFloor (learning/log_loss.h).
// Throws vdc::Error if true_view is outside p_sum or p_sum(true_view) is negative or not finite.
double viewKlDivergence(const Eigen::VectorXd& p_sum, int true_view);

// One training cloud: its true direction and its summed distribution p_sum (length M).
struct CloudPrediction {
  int true_view;
  Eigen::VectorXd p_sum;
};

struct ViewInformativeness {
  Eigen::VectorXd view_scores;  // v(m): mean d_KL over m's clouds; -1 where m had no cloud
  std::vector<int> ranking;     // views with data, by ascending score (most informative first)
  Eigen::MatrixXd confusion;    // C[m', m] = mean p_sum(m) over clouds of m' (no cloud: uniform)
};

// View scores, ranking (ties by lower index) and confusion matrix over M = num_views directions.
// Throws vdc::Error for num_views < 1, a true_view out of range or a p_sum of the wrong length.
ViewInformativeness computeViewInformativeness(const std::vector<CloudPrediction>& clouds,
                                               int num_views);

// The training features as the surface scoring needs them: keypoint in the object frame, true
// view, and d_KL = -ln p(D = view | f) of the feature alone (use featureKlDivergences).
struct LabelledFeatureScores {
  std::vector<Eigen::Vector3f> positions;  // object frame
  Eigen::VectorXi views;
  Eigen::VectorXf kl;
};

// Score matrix K (N x M), the paper's eq. (3): K[i, m] = mean kl over the features of view m whose
// position lies within `radius` (inclusive) of surface point i; -1 where there is none.
// Throws vdc::Error for inconsistent sizes, a view out of range, non-finite or negative kl,
// non-finite positions or a non-positive radius.
Eigen::MatrixXf computeScoreMatrix(const std::vector<Eigen::Vector3f>& surface_points,
                                   const LabelledFeatureScores& features, int num_views,
                                   double radius = 0.005);

// Global score g_i = mean of K[i, m] over the m with K[i, m] >= 0; -1 where there is none.
Eigen::VectorXf globalScores(const Eigen::MatrixXf& K);

}  // namespace vdc
