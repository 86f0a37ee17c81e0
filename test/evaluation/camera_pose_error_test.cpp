#include "view_direction_classification/evaluation/camera_pose_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

double angleDeg(const Eigen::Isometry3d& pose) {
  return Eigen::AngleAxisd(pose.linear()).angle() * kRadToDeg;
}
double shiftMm(const Eigen::Isometry3d& pose) { return 1000.0 * pose.translation().norm(); }

Eigen::Isometry3d somePose() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.1, -0.4, 0.5);
  return pose;
}

TEST(CameraPoseErrorTest, NoErrorGivesTheTruePoseBitForBit) {
  const Eigen::Isometry3d truth = somePose();
  const Eigen::Isometry3d believed = believedWorldFromCamera(truth, CameraPoseError{}, 1, 3, 4);
  EXPECT_EQ(believed.matrix(), truth.matrix());
}

TEST(CameraPoseErrorTest, NoiseHasTheRequestedRmsAngleAndShift) {
  CameraPoseError error;
  error.noise_deg = 1.0;
  error.noise_mm = 5.0;
  double angle_squares = 0.0, shift_squares = 0.0;
  const int sequences = 50, views = 40;
  for (int s = 0; s < sequences; ++s) {
    for (int v = 0; v < views; ++v) {
      const Eigen::Isometry3d noise = cameraPoseNoise(error, 9, s, v);
      angle_squares += std::pow(angleDeg(noise), 2);
      shift_squares += std::pow(shiftMm(noise), 2);
    }
  }
  const double n = sequences * views;
  // 2000 draws of a chi-square with 3 degrees of freedom: the RMS is within 3 % of the truth
  // (its relative standard error is about 0.9 %).
  EXPECT_NEAR(std::sqrt(angle_squares / n), 1.0, 0.03);
  EXPECT_NEAR(std::sqrt(shift_squares / n), 5.0, 0.15);
}

TEST(CameraPoseErrorTest, NoiseIsDeterministicPerSeedSequenceAndViewAndDiffersBetweenViews) {
  CameraPoseError error;
  error.noise_deg = 2.0;
  error.noise_mm = 3.0;
  const Eigen::Isometry3d a = cameraPoseNoise(error, 1, 0, 0);
  EXPECT_EQ(a.matrix(), cameraPoseNoise(error, 1, 0, 0).matrix());
  EXPECT_NE(a.matrix(), cameraPoseNoise(error, 1, 0, 1).matrix());
  EXPECT_NE(a.matrix(), cameraPoseNoise(error, 1, 1, 0).matrix());
  EXPECT_NE(a.matrix(), cameraPoseNoise(error, 2, 0, 0).matrix());
}

TEST(CameraPoseErrorTest,
     TheBiasHasExactlyTheRequestedSizeIsConstantInASequenceAndDrawnPerSequence) {
  CameraPoseError error;
  error.bias_deg = 2.0;
  error.bias_mm = 5.0;
  const Eigen::Isometry3d truth = somePose();
  // Without noise every view of a sequence gets the same believed pose error: the bias.
  const Eigen::Isometry3d first = truth.inverse() * believedWorldFromCamera(truth, error, 4, 7, 0);
  EXPECT_NEAR(angleDeg(first), 2.0, 1e-9);
  EXPECT_NEAR(shiftMm(first), 5.0, 1e-9);
  for (int v = 1; v < 10; ++v) {
    const Eigen::Isometry3d later =
        truth.inverse() * believedWorldFromCamera(truth, error, 4, 7, v);
    EXPECT_TRUE(later.isApprox(first, 1e-12)) << "view " << v;
  }
  const Eigen::Isometry3d other = handEyeBias(error, 4, 8);
  EXPECT_NEAR(angleDeg(other), 2.0, 1e-9);
  EXPECT_FALSE(other.isApprox(first, 1e-6));
}

TEST(CameraPoseErrorTest, BiasAndNoiseTogetherMoveTheBelievedPoseByBoth) {
  CameraPoseError error;
  error.noise_deg = 1.0;
  error.bias_deg = 2.0;
  error.bias_mm = 5.0;
  const Eigen::Isometry3d truth = somePose();
  const Eigen::Isometry3d expected =
      truth * handEyeBias(error, 4, 7) * cameraPoseNoise(error, 4, 7, 3);
  EXPECT_TRUE(believedWorldFromCamera(truth, error, 4, 7, 3).isApprox(expected, 1e-12));
  EXPECT_FALSE(believedWorldFromCamera(truth, error, 4, 7, 3)
                   .isApprox(believedWorldFromCamera(truth, error, 4, 7, 2), 1e-9));
}

TEST(CameraPoseErrorTest, NegativeOrNonFiniteValuesAreRefusedWithTheirName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto expectRefused = [](const CameraPoseError& error, const std::string& words) {
    try {
      checkCameraPoseError(error);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expectRefused({-1.0, 0.0, 0.0, 0.0}, "noise angle");
  expectRefused({0.0, nan, 0.0, 0.0}, "noise shift");
  expectRefused({0.0, 0.0, inf, 0.0}, "bias angle");
  expectRefused({0.0, 0.0, 0.0, -0.1}, "bias shift");
  expectRefused({0.0, 0.0, 1e300, 0.0}, "bias angle");
  expectRefused({0.0, 2000.0, 0.0, 0.0}, "noise shift");
  EXPECT_NO_THROW(checkCameraPoseError({1.0, 5.0, 2.0, 5.0}));
}

}  // namespace
}  // namespace vdc
