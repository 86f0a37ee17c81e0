#pragma once

#include <Eigen/Core>

namespace vdc {

// Probabilities are floored at this value before taking -ln p, so a view the classifier rules out
// completely scores ln(1e12) ~ 27.6 instead of infinity (and means stay finite).
constexpr double kKlProbabilityFloor = 1e-12;

// -ln max(p, kKlProbabilityFloor).
double flooredNegativeLog(double p);

// -ln p(row i, labels(i)) for each row of an n x M probability matrix, floored: the per-feature
// log-loss of the classifier, and d_KL of one feature against its one-hot true view (the
// surface informativeness). Throws vdc::Error on size mismatch, a label out of range or an
// invalid probability.
Eigen::VectorXf featureKlDivergences(const Eigen::MatrixXf& probabilities,
                                     const Eigen::VectorXi& labels);

}  // namespace vdc
