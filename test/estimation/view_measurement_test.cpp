#include "view_direction_classification/estimation/view_measurement.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vdc {
namespace {

const Eigen::Vector3d kCameraMinusZ(0, 0, -1);

TEST(ViewMeasurement, OrientationSeenFromMapsTheDirectionOntoTheCameraMinusZ) {
  for (const Eigen::Vector3d& d :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1),
        Eigen::Vector3d(1, 2, -3).normalized()}) {
    EXPECT_TRUE(rotateVector(orientationSeenFrom(d), d).isApprox(kCameraMinusZ, 1e-12))
        << d.transpose();
  }
  EXPECT_THROW(orientationSeenFrom(Eigen::Vector3d(1, 1, 0)), Error);
}

TEST(ViewMeasurement, EveryOrientationOnTheGirdleCircleShowsTheSameDirection) {
  const Eigen::Vector3d d = Eigen::Vector3d(-2, 1, 1).normalized();
  const BinghamDistribution girdle = viewGirdle(d, 30.0);
  for (double t = 0.0; t < 2.0 * M_PI; t += 0.7) {
    const Eigen::Vector4d q = std::cos(t / 2) * girdle.mode() + std::sin(t / 2) * girdle.axis(2);
    EXPECT_TRUE(rotateVector(q, d).isApprox(kCameraMinusZ, 1e-12)) << t;
    EXPECT_NEAR(girdle.logDensity(q), girdle.logDensity(girdle.mode()), 1e-12);
  }
}

TEST(ViewMeasurement, DefaultKappaKeepsOneOverRootTwoOfThePeakAtHalfTheSpacing) {
  const double spacing = 30.0 * M_PI / 180.0;
  const double kappa = defaultViewConcentration(spacing);
  const Eigen::Vector3d d(0, 0, 1);
  const BinghamDistribution girdle = viewGirdle(d, kappa);
  // Tilt the object by half the spacing about an axis perpendicular to the optical axis.
  const Eigen::Vector4d tilted = quaternionMultiply(
      quaternionFromAxisAngle(Eigen::Vector3d(1, 0, 0), spacing / 2), girdle.mode());
  EXPECT_NEAR(girdle.density(tilted) / girdle.density(girdle.mode()), std::sqrt(0.5), 1e-12);
  EXPECT_THROW(defaultViewConcentration(0.0), Error);
  EXPECT_THROW(defaultViewConcentration(NAN), Error);
}

TEST(ViewMeasurement, MixtureDropsDirectionsBelowTheThresholdAndRenormalises) {
  const std::vector<Eigen::Vector3d> directions{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                                Eigen::Vector3d(0, 0, 1)};
  Eigen::VectorXd p(3);
  p << 0.7, 0.2995, 0.0005;
  const BinghamMixture mixture = viewMeasurement(p, directions, 20.0);
  ASSERT_EQ(mixture.size(), 2u);
  EXPECT_NEAR(mixture.weight(0), 0.7 / 0.9995, 1e-12);
}

TEST(ViewMeasurement, SharpenedDistributionRaisesEachProbabilityToTheExponentAndRenormalises) {
  Eigen::VectorXd p(3);
  p << 0.6, 0.3, 0.1;
  const Eigen::VectorXd unchanged = sharpenedDistribution(p, 1.0);
  EXPECT_TRUE(unchanged.isApprox(p, 1e-15));
  // Squared: 0.36, 0.09, 0.01 over 0.46.
  const Eigen::VectorXd squared = sharpenedDistribution(p, 2.0);
  EXPECT_NEAR(squared(0), 0.36 / 0.46, 1e-12);
  EXPECT_NEAR(squared(1), 0.09 / 0.46, 1e-12);
  EXPECT_NEAR(squared(2), 0.01 / 0.46, 1e-12);
  // A large exponent keeps the most probable direction instead of underflowing to 0/0.
  const Eigen::VectorXd steep = sharpenedDistribution(p, 2000.0);
  ASSERT_TRUE(steep.allFinite());
  EXPECT_NEAR(steep(0), 1.0, 1e-12);
  // Below 1 it flattens: the ratio of the first two falls from 2 to sqrt(2).
  const Eigen::VectorXd flat = sharpenedDistribution(p, 0.5);
  EXPECT_NEAR(flat(0) / flat(1), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(flat.sum(), 1.0, 1e-12);
  EXPECT_THROW(sharpenedDistribution(p, 0.0), Error);
  EXPECT_THROW(sharpenedDistribution(p, NAN), Error);
  EXPECT_THROW(sharpenedDistribution(Eigen::VectorXd(0), 2.0), Error);
  EXPECT_THROW(sharpenedDistribution(Eigen::Vector2d(0.5, -0.5), 2.0), Error);
}

TEST(ViewMeasurement, FixedFrameMixtureIsTheCameraOneRotatedByTheCameraPose) {
  const std::vector<Eigen::Vector3d> directions{Eigen::Vector3d(0, 1, 0)};
  const BinghamMixture camera = viewMeasurement(Eigen::VectorXd::Ones(1), directions, 20.0);
  const Eigen::Vector4d q_WC = quaternionFromAxisAngle(Eigen::Vector3d(1, 1, 0), 0.8);
  const BinghamMixture fixed = cameraToFixedFrame(camera, q_WC);
  const Eigen::Vector4d q_CO = camera.component(0).mode();
  EXPECT_NEAR(fixed.logDensity(quaternionMultiply(q_WC, q_CO)), camera.logDensity(q_CO), 1e-10);
  EXPECT_THROW(cameraToFixedFrame(camera, Eigen::Vector4d(1, 1, 1, 1)), Error);
}

TEST(ViewMeasurement, RejectsInconsistentOrInvalidInput) {
  const std::vector<Eigen::Vector3d> directions{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  EXPECT_THROW(viewMeasurement(Eigen::VectorXd::Ones(1), directions, 20.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::VectorXd(0), {}, 20.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(0.7, 0.7), directions, 20.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(1.5, -0.5), directions, 20.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(NAN, 0.5), directions, 20.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(0.5, 0.5), directions, 0.0), Error);
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(0.5, 0.5), directions, 20.0, -1.0), Error);
  const std::vector<Eigen::Vector3d> not_unit{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 2, 0)};
  EXPECT_THROW(viewMeasurement(Eigen::Vector2d(0.5, 0.5), not_unit, 20.0), Error);
}

}  // namespace
}  // namespace vdc
