#include "view_direction_classification/estimation/orientation_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

// The mug stands at a fixed pose in the world; cameras look at it from given directions.
class OrientationEstimatorTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { renderer_ = new DepthRenderer(makeMug()); }
  static void TearDownTestSuite() { delete renderer_; }

  static Eigen::Isometry3d worldFromObject() {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = quaternionToRotationMatrix(
        quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3).normalized(), 0.7));
    pose.translation() = Eigen::Vector3d(0.4, -0.2, 0.8);
    return pose;
  }
  // Renders the mug from `direction` (object frame) and returns the cloud with the camera pose.
  static std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> view(
      const Eigen::Vector3d& direction, double roll, std::uint32_t seed) {
    const Eigen::Isometry3d camera_from_object = cameraFromObject(direction, 0.6, roll);
    std::mt19937 rng(seed);
    return {renderer_->render(camera_from_object, DepthNoiseModel{true}, &rng),
            worldFromObject() * camera_from_object.inverse()};
  }
  // The belief alone: the tests of fusion and its bookkeeping (refinement has its own, in
  // orientation_estimator_refinement_test.cpp).
  static EstimatorParameters withoutRefinement() {
    EstimatorParameters parameters;
    parameters.refinement = RefinementMode::kNone;
    return parameters;
  }
  static Eigen::Vector4d trueOrientation() {
    return fromEigenQuaternion(Eigen::Quaterniond(worldFromObject().linear()));
  }
  static DepthRenderer* renderer_;
};
DepthRenderer* OrientationEstimatorTest::renderer_ = nullptr;

TEST_F(OrientationEstimatorTest, SkipsEmptyAndAllNanCloudsWithoutTouchingTheBelief) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  pcl::PointCloud<pcl::PointXYZ> empty;
  ViewUpdate update = estimator.update(empty, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(update.updated);
  EXPECT_FALSE(update.skip_reason.empty());

  pcl::PointCloud<pcl::PointXYZ> nans(64, 48);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (auto& p : nans.points) p.x = p.y = p.z = nan;
  update = estimator.update(nans, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(update.updated);
  EXPECT_EQ(update.object_points, 0);

  pcl::PointCloud<pcl::PointXYZ> single;
  single.push_back(pcl::PointXYZ(0, 0, 0.6f));
  EXPECT_FALSE(estimator.update(single, Eigen::Isometry3d::Identity()).updated);

  EXPECT_EQ(estimator.updateCount(), 0);
  EXPECT_EQ(estimator.belief().size(), 1u);
  EXPECT_FALSE(estimator.positionEstimate().has_value());
}

// Finite but absurd coordinates (a broken driver's) near the float maximum: kd-trees split
// their ranges at (min + max) / 2, which overflows there, and FLANN aborts on an assertion.
TEST_F(OrientationEstimatorTest, PointsNearTheFloatMaximumNeitherAbortNorCountAsTheObject) {
  pcl::PointCloud<pcl::PointXYZ> far;
  for (int i = 0; i < 400; ++i) {
    far.push_back(pcl::PointXYZ(2e38f + 1e35f * static_cast<float>(i % 20),
                                -3e38f + 1e35f * static_cast<float>(i / 20), 2.5e38f));
  }
  for (const RefinementMode refinement : {RefinementMode::kNone, RefinementMode::kIcp}) {
    EstimatorParameters parameters;
    parameters.refinement = refinement;
    OrientationEstimator estimator(test::quickMugModel(), parameters);
    const ViewUpdate alone = estimator.update(far, Eigen::Isometry3d::Identity());
    EXPECT_FALSE(alone.updated);
    EXPECT_FALSE(alone.skip_reason.empty());

    auto [cloud, world_from_camera] = view(Eigen::Vector3d(1, 0, 0.4).normalized(), 0.3, 5);
    cloud += far;
    const ViewUpdate mixed = estimator.update(cloud, world_from_camera);
    EXPECT_TRUE(mixed.updated) << mixed.skip_reason;
  }
}

TEST_F(OrientationEstimatorTest, RefusesANonFiniteCameraPose) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(estimator.update(pcl::PointCloud<pcl::PointXYZ>(), pose), Error);
}

TEST_F(OrientationEstimatorTest, RefusesInvalidParameters) {
  EstimatorParameters parameters;
  parameters.max_components = 0;
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), parameters), Error);
  parameters = {};
  parameters.belief_weight_floor = 1.0;  // would drop every component but the heaviest's equal
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), parameters), Error);
  parameters.belief_weight_floor = -1e-6;
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), parameters), Error);
  parameters = {};
  parameters.sharpness_ratio = 0.5;  // would keep the wider factor's mode
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), parameters), Error);
  parameters = {};
  parameters.segmentation.roi_radius = -1;
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), parameters), Error);
  EXPECT_THROW(OrientationEstimator(nullptr, {}), Error);
}

TEST_F(OrientationEstimatorTest, UsesTheBundlesFeatureCountAndAGridWideKappaByDefault) {
  const OrientationEstimator estimator(test::quickMugModel(), {});
  EXPECT_EQ(estimator.parameters().n_feat, test::quickMugModel()->parameters.n_feat);
  // 12 icosahedron directions are 63.4 deg apart: kappa = ln 2 / (2 sin^2(15.9 deg)) ~ 4.6.
  EXPECT_NEAR(estimator.kappa(), std::log(2.0) / (2.0 * std::pow(std::sin(1.1071 / 4), 2)), 0.05);
}

TEST_F(OrientationEstimatorTest, NewParametersApplyToTheNextViewAndARefusedOneChangesNothing) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  const auto [cloud, world_from_camera] =
      view(Eigen::Vector3d(0.3, -0.5, 0.8).normalized(), 0.4, 1);
  ASSERT_TRUE(estimator.update(cloud, world_from_camera).updated);
  EstimatorParameters changed;
  changed.kappa = 18.4;
  changed.max_components = 1;
  estimator.setParameters(changed);
  EXPECT_EQ(estimator.kappa(), 18.4);
  EXPECT_EQ(estimator.viewsFused(), 1) << "the belief is kept";
  EstimatorParameters refused = changed;
  refused.kappa = 5.0;
  refused.min_weight = 1.0;
  EXPECT_THROW(estimator.setParameters(refused), Error);
  EXPECT_EQ(estimator.kappa(), 18.4);
  EXPECT_EQ(estimator.parameters().min_weight, changed.min_weight);
  // The next fusion reduces with the new K_max.
  const auto [second, world_from_second] =
      view(Eigen::Vector3d(-0.6, 0.2, 0.5).normalized(), 0.4, 2);
  estimator.update(second, world_from_second);
  EXPECT_EQ(estimator.belief().size(), 1u);
}

TEST_F(OrientationEstimatorTest, OneViewFusesAMeasurementThatNarrowsTheBelief) {
  OrientationEstimator estimator(test::quickMugModel(), withoutRefinement());
  const auto [cloud, world_from_camera] =
      view(Eigen::Vector3d(0.3, -0.5, 0.8).normalized(), 0.4, 1);
  const ViewUpdate update = estimator.update(cloud, world_from_camera);
  ASSERT_TRUE(update.updated) << update.skip_reason;
  EXPECT_GT(update.features, 100);
  EXPECT_NEAR(update.p_sum.sum(), 1.0, 1e-9);
  EXPECT_EQ(estimator.updateCount(), 1);
  EXPECT_GT(update.timing.total, 0.0);
  EXPECT_NEAR(update.timing.total,
              update.timing.segmentation + update.timing.features + update.timing.classification +
                  update.timing.measurement + update.timing.fusion,
              1.0);
  // After one view the belief is a mixture of girdles, less spread than the uniform prior, whose
  // entropy is log(2 pi^2) = 2.98 nats (the 12-direction model's girdles are broad: ~2.6).
  EXPECT_LT(estimator.entropy(), std::log(2.0 * M_PI * M_PI) - 0.25);
  EXPECT_TRUE(estimator.positionEstimate().has_value());
}

TEST_F(OrientationEstimatorTest, EstimateFollowsARotationOfTheFixedFrame) {
  // The same clouds with every camera pose expressed in a rotated fixed frame G must give the
  // MAP G q: the fusion has no preferred world orientation. (Refinement is left out: its girdle
  // starts begin at each girdle's numerically arbitrary mode, so ICP may settle a few degrees
  // apart in the two frames.)
  const Eigen::Isometry3d G(Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.2, -1, 0.4).normalized()));
  OrientationEstimator plain(test::quickMugModel(), withoutRefinement());
  OrientationEstimator rotated(test::quickMugModel(), withoutRefinement());
  for (int v = 0; v < 3; ++v) {
    const Eigen::Vector3d direction =
        Eigen::Vector3d(std::cos(2.1 * v), std::sin(2.1 * v), 0.5 - 0.4 * v).normalized();
    const auto [cloud, world_from_camera] = view(direction, 0.3 * v, 40 + v);
    plain.update(cloud, world_from_camera);
    rotated.update(cloud, G * world_from_camera);
  }
  const Eigen::Vector4d expected = quaternionMultiply(
      fromEigenQuaternion(Eigen::Quaterniond(G.linear())), plain.mapOrientation());
  EXPECT_LT(rotationErrorDeg(rotated.mapOrientation(), expected), 0.5);
}

TEST_F(OrientationEstimatorTest, RegionOfInterestIsAFixedFramePointMovedIntoEachCloud) {
  // Views from opposite sides, each cloud with a blob of clutter 30 cm beside the mug: a region
  // of interest around the mug's place in the fixed frame keeps the mug and drops the clutter in
  // both, although that place has different coordinates in each camera frame.
  EstimatorParameters parameters;
  parameters.segmentation.mode = SegmentationMode::kRegionOfInterest;
  parameters.segmentation.roi_centre = worldFromObject().translation();
  parameters.segmentation.min_plane_fraction = 1.0;  // no table in these clouds: no plane removed
  OrientationEstimator estimator(test::quickMugModel(), parameters);
  for (const Eigen::Vector3d& direction :
       {Eigen::Vector3d(1, 0.2, 0.3), Eigen::Vector3d(-1, -0.2, 0.3)}) {
    auto [cloud, world_from_camera] = view(direction.normalized(), 0.5, 3);
    const std::size_t mug_points = countValidPoints(cloud);
    for (int i = 0; i < 400; ++i) {  // a 4 cm cube of clutter beside the mug (camera frame)
      cloud.push_back(
          pcl::PointXYZ(0.3f + 0.0001f * (i % 400), 0.002f * (i % 20), 0.6f + 0.002f * (i / 20)));
    }
    const ViewUpdate update = estimator.update(cloud, world_from_camera);
    ASSERT_TRUE(update.updated) << update.skip_reason;
    EXPECT_LE(update.object_points, static_cast<int>(mug_points));
    EXPECT_GE(update.object_points, static_cast<int>(0.9 * mug_points));
  }
  // A region of interest where nothing stands leaves no points: the view is skipped.
  parameters.segmentation.roi_centre = worldFromObject().translation() + Eigen::Vector3d(0, 0, 1);
  OrientationEstimator elsewhere(test::quickMugModel(), parameters);
  const auto [cloud, world_from_camera] = view(Eigen::Vector3d(1, 0, 0), 0, 4);
  const ViewUpdate update = elsewhere.update(cloud, world_from_camera);
  EXPECT_FALSE(update.updated);
  EXPECT_EQ(update.object_points, 0);
}

TEST_F(OrientationEstimatorTest, ResetForgetsBeliefAndPosition) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  const auto [cloud, world_from_camera] = view(Eigen::Vector3d(1, 0, 0.2).normalized(), 0, 9);
  ASSERT_TRUE(estimator.update(cloud, world_from_camera).updated);
  estimator.reset();
  EXPECT_EQ(estimator.updateCount(), 0);
  EXPECT_EQ(estimator.belief().size(), 1u);
  EXPECT_FALSE(estimator.positionEstimate().has_value());
}

}  // namespace
}  // namespace vdc
