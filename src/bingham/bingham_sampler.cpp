#include "view_direction_classification/bingham/bingham_sampler.h"

#include "view_direction_classification/common/error.h"

#include <cmath>

namespace vdc {

BinghamSampler::BinghamSampler(const BinghamDistribution& distribution)
    : basis_(distribution.basis()) {
  lambda_ << -distribution.concentrations(), 0.0;
  // sum_i 1/(b + 2 lambda_i) - 1 falls monotonically in b; it is >= 0 at b = 1 (the mode's term
  // alone is 1/b) and <= 0 at b = 4, so bisection on [1, 4] finds the root to machine precision.
  const auto excess = [&](double b) { return (1.0 / (b + 2.0 * lambda_.array())).sum() - 1.0; };
  double lower = 1.0, upper = 4.0;
  for (int i = 0; i < 200 && upper - lower > 1e-15; ++i) {
    const double middle = 0.5 * (lower + upper);
    (excess(middle) > 0.0 ? lower : upper) = middle;
  }
  b_ = 0.5 * (lower + upper);
  const Eigen::Vector4d omega = (1.0 + 2.0 * lambda_.array() / b_).matrix();
  proposal_std_dev_ = omega.cwiseSqrt().cwiseInverse();
  log_bound_ = -(4.0 - b_) / 2.0 + 2.0 * std::log(4.0 / b_);
}

Eigen::Vector4d BinghamSampler::operator()(std::mt19937_64& generator) const {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int attempt = 0; attempt < 100000; ++attempt) {
    Eigen::Vector4d y;
    for (int i = 0; i < 4; ++i) y(i) = proposal_std_dev_(i) * normal(generator);
    const double norm = y.norm();
    if (norm == 0.0) continue;
    const Eigen::Vector4d x = y / norm;
    const double w = x.dot(lambda_.cwiseProduct(x));  // x^T Lambda x
    const double log_ratio = -w + 2.0 * std::log1p(2.0 * w / b_) - log_bound_;
    if (std::log(uniform(generator)) < log_ratio) return basis_ * x;
  }
  // Unreachable in practice: the acceptance rate is at least 28 %.
  throw Error("The Bingham sampler rejected 100000 proposals in a row.");
}

std::vector<Eigen::Vector4d> BinghamSampler::sample(int count, std::mt19937_64& generator) const {
  if (count < 0) throw Error("The number of Bingham samples must be >= 0.");
  std::vector<Eigen::Vector4d> samples;
  samples.reserve(count);
  for (int i = 0; i < count; ++i) samples.push_back((*this)(generator));
  return samples;
}

}  // namespace vdc
