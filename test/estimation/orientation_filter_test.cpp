#include "view_direction_classification/estimation/orientation_filter.h"
#include "support/random_unit_quaternions.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/view_measurement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace vdc {
namespace {

// A Fibonacci lattice of viewing directions (the geometry area's view sphere is not linked here).
std::vector<Eigen::Vector3d> fibonacciDirections(int count) {
  std::vector<Eigen::Vector3d> directions;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(1.0 - z * z);
    directions.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return directions;
}

double meanNeighbourAngle(const std::vector<Eigen::Vector3d>& directions) {
  double sum = 0.0;
  for (const Eigen::Vector3d& a : directions) {
    double nearest = M_PI;
    for (const Eigen::Vector3d& b : directions) {
      if (&a != &b) nearest = std::min(nearest, std::acos(std::min(1.0, a.dot(b))));
    }
    sum += nearest;
  }
  return sum / directions.size();
}

// A simulated view of an object at q_WO from a camera at q_WC: the classifier's p_sum is a soft
// bump around the true viewing direction (d_true = R_CO^T (0,0,-1)), optionally with a share of
// its mass on a wrong direction; returned as the fixed-frame measurement mixture.
struct SimulatedViews {
  std::vector<Eigen::Vector3d> directions = fibonacciDirections(42);
  double kappa = defaultViewConcentration(meanNeighbourAngle(directions));

  BinghamMixture measure(const Eigen::Vector4d& q_WO, const Eigen::Vector4d& q_WC,
                         double wrong_share, std::mt19937_64& generator) const {
    const Eigen::Vector4d q_CO = quaternionMultiply(quaternionConjugate(q_WC), q_WO);
    const Eigen::Vector3d seen =
        quaternionToRotationMatrix(q_CO).transpose() * Eigen::Vector3d(0, 0, -1);
    Eigen::VectorXd p(directions.size());
    for (std::size_t m = 0; m < directions.size(); ++m) {
      p(m) = std::exp(12.0 * (directions[m].dot(seen) - 1.0));
    }
    p /= p.sum();
    if (wrong_share > 0.0) {
      std::uniform_int_distribution<int> pick(0, static_cast<int>(directions.size()) - 1);
      p *= 1.0 - wrong_share;
      p(pick(generator)) += wrong_share;
    }
    return cameraToFixedFrame(viewMeasurement(p, directions, kappa), q_WC);
  }
};

TEST(OrientationFilter, StartsUniformAndResetsToUniform) {
  OrientationFilter filter;
  EXPECT_EQ(filter.belief().size(), 1u);
  EXPECT_NEAR(filter.belief().component(0).normalizer(), 2.0 * M_PI * M_PI, 1e-12);
  EXPECT_NEAR(filter.entropy(), std::log(2.0 * M_PI * M_PI), 1e-12);
  const SimulatedViews views;
  std::mt19937_64 generator(1);
  filter.update(
      views.measure(Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(1, 0, 0, 0), 0.0, generator));
  EXPECT_EQ(filter.updateCount(), 1);
  filter.reset();
  EXPECT_EQ(filter.updateCount(), 0);
  EXPECT_EQ(filter.belief().size(), 1u);
  EXPECT_EQ(filter.belief().component(0).concentrations(), Eigen::Vector3d::Zero());
}

TEST(OrientationFilter, OneViewLeavesTheRollFreeAndTwoViewsPinTheOrientation) {
  // Exact girdles (one direction, p = 1): the belief after one view is a circle through the
  // truth; a second view from another direction intersects it at the truth.
  const Eigen::Vector4d q_WO = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 0.5), 1.2);
  OrientationFilter filter;
  for (const Eigen::Vector4d& q_WC : {quaternionFromAxisAngle(Eigen::Vector3d(0, 1, 0), 0.3),
                                      quaternionFromAxisAngle(Eigen::Vector3d(1, 0, 0), 1.4)}) {
    const Eigen::Vector4d q_CO = quaternionMultiply(quaternionConjugate(q_WC), q_WO);
    const Eigen::Vector3d seen =
        quaternionToRotationMatrix(q_CO).transpose() * Eigen::Vector3d(0, 0, -1);
    filter.update(
        cameraToFixedFrame(viewMeasurement(Eigen::VectorXd::Ones(1), {seen}, 100.0), q_WC));
    if (filter.updateCount() == 1) {
      const BinghamDistribution& circle = filter.belief().component(0);
      EXPECT_NEAR(circle.concentrations()(2), 0.0, 1e-9);  // roll unconstrained
      EXPECT_NEAR(circle.logDensity(q_WO), circle.logDensity(circle.mode()), 1e-9);
    }
  }
  EXPECT_LT(rotationErrorDeg(filter.mapEstimate(), q_WO), 1e-4);
  EXPECT_LT(filter.entropy(), std::log(2.0 * M_PI * M_PI) - 5.0);
}

TEST(OrientationFilter, ConvergesFromRollAmbiguousViewsAroundAKnownOrientation) {
  // Every view is a mixture of girdles (roll free); only their intersections across views pin
  // the orientation. With 42 directions (spacing ~ 30 deg) the estimate settles within about a
  // third of the spacing after ten random views.
  const SimulatedViews views;
  std::mt19937_64 generator(2024);
  for (int trial = 0; trial < 2; ++trial) {
    const Eigen::Vector4d q_WO = test::randomUnitQuaternion(generator);
    OrientationFilter filter;
    double first_error = 0.0;
    for (int view = 0; view < 10; ++view) {
      filter.update(views.measure(q_WO, test::randomUnitQuaternion(generator), 0.0, generator));
      if (view == 0) first_error = rotationErrorDeg(filter.mapEstimate(), q_WO);
    }
    const double final_error = rotationErrorDeg(filter.mapEstimate(), q_WO);
    EXPECT_LT(final_error, 12.0) << "trial " << trial;
    EXPECT_LT(final_error, first_error) << "trial " << trial;
    // Much more certain than the uniform prior (log(2 pi^2) = 2.98 nats).
    EXPECT_LT(filter.entropy(), 0.0) << "trial " << trial;
  }
}

TEST(OrientationFilter, ConvergesDespiteAThirdOfEveryViewsMassOnAWrongDirection) {
  const SimulatedViews views;
  std::mt19937_64 generator(77);
  const Eigen::Vector4d q_WO = test::randomUnitQuaternion(generator);
  OrientationFilter filter;
  for (int view = 0; view < 10; ++view) {
    filter.update(views.measure(q_WO, test::randomUnitQuaternion(generator), 0.33, generator));
    EXPECT_LE(filter.belief().size(), 200u);
  }
  EXPECT_LT(rotationErrorDeg(filter.mapEstimate(), q_WO), 12.0);
}

}  // namespace
}  // namespace vdc
