#include "view_direction_classification/estimation/belief_spread.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

double quantile(std::vector<double> values, double q) {
  const std::size_t k =
      std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(q * values.size())) - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

BeliefSpread beliefSpread(const BinghamMixture& belief, const Eigen::Vector4d& map, int samples,
                          std::uint64_t seed) {
  if (samples < 10) {
    throw Error("the belief's spread needs at least 10 samples, got " + std::to_string(samples));
  }
  if (!isUnitQuaternion(map)) {
    throw Error("the belief's spread needs a unit MAP quaternion");
  }
  std::mt19937_64 generator(seed);
  const std::vector<Eigen::Vector4d> drawn = belief.sample(samples, generator);
  std::vector<double> angles;
  angles.reserve(drawn.size());
  BeliefSpread spread;
  spread.covariance.setZero();
  const Eigen::Vector4d map_inverse = quaternionConjugate(map);
  for (const Eigen::Vector4d& q : drawn) {
    Eigen::Vector4d delta = quaternionMultiply(q, map_inverse);
    if (delta(0) < 0) delta = -delta;
    const double sine = delta.tail<3>().norm();
    const double angle = 2.0 * std::atan2(sine, delta(0));
    angles.push_back(angle);
    const Eigen::Vector3d rotation_vector = sine > 1e-12
                                                ? Eigen::Vector3d(delta.tail<3>() / sine * angle)
                                                : Eigen::Vector3d(2.0 * delta.tail<3>());
    spread.covariance += rotation_vector * rotation_vector.transpose();
  }
  spread.covariance /= static_cast<double>(drawn.size());
  spread.cone50 = quantile(angles, 0.5);
  spread.cone90 = quantile(angles, 0.9);
  return spread;
}

}  // namespace vdc
