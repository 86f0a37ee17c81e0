#include "view_direction_classification/estimation/view_measurement.h"

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>

namespace vdc {
namespace {

void checkDirection(const Eigen::Vector3d& direction, std::size_t index) {
  if (!direction.allFinite() || std::abs(direction.norm() - 1.0) > 1e-6) {
    std::ostringstream message;
    message << "Viewing direction " << index << " (" << direction.transpose()
            << ") must be a finite unit vector.";
    throw Error(message.str());
  }
}

}  // namespace

Eigen::Vector4d orientationSeenFrom(const Eigen::Vector3d& direction) {
  checkDirection(direction, 0);
  const Eigen::Quaterniond q =
      Eigen::Quaterniond::FromTwoVectors(direction, Eigen::Vector3d(0.0, 0.0, -1.0));
  return fromEigenQuaternion(q.normalized());
}

BinghamDistribution viewGirdle(const Eigen::Vector3d& direction, double kappa,
                               double roll_concentration) {
  if (!std::isfinite(kappa) || kappa <= 0.0 || !std::isfinite(roll_concentration) ||
      roll_concentration < 0.0) {
    std::ostringstream message;
    message << "A view girdle needs a finite concentration kappa > 0 and a finite roll "
               "concentration >= 0, but got kappa = "
            << kappa << " and roll concentration = " << roll_concentration << ".";
    throw Error(message.str());
  }
  const Eigen::Vector4d seen = orientationSeenFrom(direction);
  BinghamDistribution::Axes axes;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector4d pure = Eigen::Vector4d::Zero();
    pure(i + 1) = 1.0;  // i, j, k: rotations about the camera's x, y, z (optical) axes
    axes.col(i) = quaternionMultiply(pure, seen);
  }
  return BinghamDistribution(Eigen::Vector3d(-kappa, -kappa, -roll_concentration), axes);
}

double defaultViewConcentration(double neighbour_spacing) {
  if (!(neighbour_spacing > 0.0) || !(neighbour_spacing <= M_PI)) {
    std::ostringstream message;
    message << "The spacing between neighbouring view directions must be in (0, pi] radians, but "
               "is "
            << neighbour_spacing << ".";
    throw Error(message.str());
  }
  return std::log(2.0) / (2.0 * std::pow(std::sin(neighbour_spacing / 4.0), 2));
}

Eigen::VectorXd sharpenedDistribution(const Eigen::VectorXd& p_sum, double exponent) {
  if (!(exponent > 0.0) || !std::isfinite(exponent)) {
    std::ostringstream message;
    message << "The exponent on the view distribution must be finite and positive, but is "
            << exponent << ".";
    throw Error(message.str());
  }
  if (p_sum.size() == 0 || !p_sum.allFinite() || (p_sum.array() < 0.0).any() ||
      !(p_sum.maxCoeff() > 0.0)) {
    throw Error("The view distribution to sharpen must be non-empty, finite and non-negative.");
  }
  if (exponent == 1.0) return p_sum;
  // Relative to the largest entry, so that a large exponent cannot underflow every weight.
  Eigen::VectorXd sharpened = (p_sum / p_sum.maxCoeff()).array().pow(exponent).matrix();
  return sharpened / sharpened.sum();
}

BinghamMixture viewMeasurement(const Eigen::VectorXd& p_sum,
                               const std::vector<Eigen::Vector3d>& directions, double kappa,
                               double roll_concentration, double min_weight) {
  if (p_sum.size() == 0 || static_cast<std::size_t>(p_sum.size()) != directions.size()) {
    std::ostringstream message;
    message << "A view measurement needs one probability per viewing direction, but got "
            << p_sum.size() << " probabilities for " << directions.size() << " directions.";
    throw Error(message.str());
  }
  if (!p_sum.allFinite() || (p_sum.array() < 0.0).any() || std::abs(p_sum.sum() - 1.0) > 1e-6) {
    std::ostringstream message;
    message << "The view distribution p_sum must be finite, non-negative and sum to 1, but sums to "
            << p_sum.sum() << ".";
    throw Error(message.str());
  }
  for (std::size_t m = 0; m < directions.size(); ++m) checkDirection(directions[m], m);
  std::vector<double> weights;
  std::vector<BinghamDistribution> components;
  Eigen::Index most_probable = 0;
  p_sum.maxCoeff(&most_probable);
  for (Eigen::Index m = 0; m < p_sum.size(); ++m) {
    if (p_sum(m) >= min_weight || m == most_probable) {
      weights.push_back(p_sum(m));
      components.push_back(viewGirdle(directions[m], kappa, roll_concentration));
    }
  }
  return BinghamMixture(std::move(weights), std::move(components));
}

BinghamMixture cameraToFixedFrame(const BinghamMixture& camera_frame, const Eigen::Vector4d& q_WC) {
  return camera_frame.rotated(q_WC);
}

}  // namespace vdc
