#include "view_direction_classification/evaluation/ppf_baseline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/evaluation/ppf_angle_step.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

// Training the detector takes seconds: once for the whole suite.
class PpfBaselineTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mesh_ = new TriangleMesh(makeMug());
    baseline_ = new PpfBaseline(*mesh_);
  }
  static void TearDownTestSuite() {
    delete baseline_;
    delete mesh_;
    baseline_ = nullptr;
    mesh_ = nullptr;
  }
  static pcl::PointCloud<pcl::PointXYZ> render(const Eigen::Isometry3d& camera_from_object) {
    return DepthRenderer(*mesh_).render(camera_from_object);
  }
  static double orientationErrorDeg(const Eigen::Isometry3d& estimate,
                                    const Eigen::Isometry3d& truth) {
    // The angle of the relative rotation (what rotationErrorDeg computes from quaternions; this
    // binary links the baseline library alone).
    const Eigen::AngleAxisd relative(estimate.linear().transpose() * truth.linear());
    return relative.angle() * 180.0 / M_PI;
  }

  static TriangleMesh* mesh_;
  static PpfBaseline* baseline_;
};
TriangleMesh* PpfBaselineTest::mesh_ = nullptr;
PpfBaseline* PpfBaselineTest::baseline_ = nullptr;

TEST_F(PpfBaselineTest, LocatesTheMugAndMostlyItsAxisInNoiseFreeViews) {
  // Oblique views from above and below, handle visible. Measured with the 12.41 degree step:
  // position within 8 mm in every view; the body axis within 3 degrees in 4 of the 6 views and
  // upside down (178-179 degrees) in the first and the fourth, both from above (with the unsafe
  // 12 degree step the first three views all had the axis within 2 degrees: which views flip
  // depends on the quantisation); the rotation about the axis off by 7-120 degrees where the
  // axis is right (the rotationally symmetric body outvotes the handle). So the full orientation
  // error is not bounded here, the axis in at least half of the views, the position in all.
  const Eigen::Vector3d directions[] = {{1.0, 0.4, 0.8},  {0.2, -1.0, 0.3},  {-0.5, 0.6, -0.7},
                                        {0.7, -0.2, 0.9}, {-1.0, -0.3, 0.2}, {0.3, 0.8, -0.6}};
  int axes_found = 0;
  for (const auto& direction : directions) {
    const Eigen::Isometry3d truth = cameraFromObject(direction, 0.6, 0.3);
    const PpfMatch match = baseline_->match(render(truth));
    ASSERT_TRUE(match.found);
    const Eigen::Vector3d axis_estimate =
        match.camera_from_object.linear() * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d axis_truth = truth.linear() * Eigen::Vector3d::UnitZ();
    const double axis_error = std::acos(std::min(1.0, axis_estimate.dot(axis_truth))) * 180 / M_PI;
    const double position_error =
        (match.camera_from_object.translation() - truth.translation()).norm();
    std::printf(
        "PPF: orientation error %.1f deg, axis error %.1f deg, position error %.1f mm, %.0f ms\n",
        orientationErrorDeg(match.camera_from_object, truth), axis_error, 1e3 * position_error,
        match.milliseconds);
    EXPECT_LT(position_error, 0.015);
    if (axis_error < 10.0) ++axes_found;
  }
  EXPECT_GE(axes_found, 3);
}

TEST_F(PpfBaselineTest, ReturnsAFiniteRigidPoseAndIsDeterministic) {
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(-0.3, 1.0, -0.5), 0.6, 2.0);
  const auto cloud = render(pose);
  const PpfMatch first = baseline_->match(cloud);
  const PpfMatch second = baseline_->match(cloud);
  ASSERT_TRUE(first.found);
  ASSERT_TRUE(second.found);
  EXPECT_TRUE(first.camera_from_object.matrix().allFinite());
  const Eigen::Matrix3d r = first.camera_from_object.linear();
  EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-9);
  EXPECT_TRUE(first.camera_from_object.matrix().isApprox(second.camera_from_object.matrix(), 0));
}

TEST_F(PpfBaselineTest, UsesTheSafeAngleStepNearestTheRequestedOne) {
  // The default 12 degrees would overflow PCL's vote accumulator (ppf_angle_step.h).
  EXPECT_EQ(baseline_->parameters().angle_step_deg, 12.0);
  EXPECT_NEAR(baseline_->angleStepDeg(), 360.0 / 29.0, 1e-5);
  EXPECT_TRUE(isSafePpfAngleStep(static_cast<float>(baseline_->angleStepDeg() * M_PI / 180.0)));
}

TEST_F(PpfBaselineTest, EmptyAllNanAndTinyCloudsGiveNoPose) {
  pcl::PointCloud<pcl::PointXYZ> empty;
  EXPECT_FALSE(baseline_->match(empty).found);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> nans(20, 20, pcl::PointXYZ(nan, nan, nan));
  EXPECT_FALSE(baseline_->match(nans).found);
  pcl::PointCloud<pcl::PointXYZ> three;
  for (int i = 0; i < 3; ++i) three.push_back(pcl::PointXYZ(0.01f * i, 0.0f, 0.6f));
  EXPECT_FALSE(baseline_->match(three).found);
  EXPECT_FALSE(baseline_->matchScene(nullptr).found);
}

TEST(PpfBaselineParametersTest, InvalidParametersAndEmptyMeshesAreRefused) {
  PpfParameters bad;
  bad.model_spacing = 0.0;
  EXPECT_THROW(PpfBaseline(makeMug(), bad), Error);
  bad = PpfParameters{};
  bad.reference_sampling_rate = 0;
  EXPECT_THROW(PpfBaseline(makeMug(), bad), Error);
  bad = PpfParameters{};
  bad.normal_radius = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PpfBaseline(makeMug(), bad), Error);
  EXPECT_THROW(PpfBaseline(TriangleMesh{}), Error);
}

}  // namespace
}  // namespace vdc
