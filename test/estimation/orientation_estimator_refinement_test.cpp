#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/quick_mug_model.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/camera_pose_covariance.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/estimation/refined_position.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {
namespace {

// The estimator with refinement = icp against the same views without (doc/method.md,
// "Refinement").
class EstimatorRefinementTest : public ::testing::Test {
 protected:
  static Eigen::Isometry3d worldFromObject() {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = quaternionToRotationMatrix(
        quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3).normalized(), 0.7));
    pose.translation() = Eigen::Vector3d(0.4, -0.2, 0.8);
    return pose;
  }
  static Eigen::Vector4d truth() {
    return quaternionFromRotationMatrix(worldFromObject().linear());
  }
  // The estimators fed two views whose camera poses are reported as if the mug stood upside
  // down (half a turn about its x axis through its origin): each belief becomes sure of that
  // pose. Returns the view from above that then sees the opening where that pose has the base.
  static std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> sureOfTheUpsideDownMug(
      const std::vector<OrientationEstimator*>& estimators);
  // The handle seen from the side and above, with noise.
  static std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> handleView() {
    const Eigen::Isometry3d camera_from_object =
        cameraFromObject(Eigen::Vector3d(0.3, 1.0, 0.4).normalized(), 0.6, 1.3);
    std::mt19937 rng(7);
    return {DepthRenderer(makeMug()).render(camera_from_object, DepthNoiseModel{true}, &rng),
            worldFromObject() * camera_from_object.inverse()};
  }
  static EstimatorParameters withoutRefinement() {
    EstimatorParameters parameters;
    parameters.refinement = RefinementMode::kNone;
    return parameters;
  }
  static EstimatorParameters withIcp() {
    EstimatorParameters parameters;
    parameters.refinement = RefinementMode::kIcp;
    // The quick model's 12 directions often miss the true one in the two heaviest components.
    parameters.refinement_parameters.hypotheses.max_components = 4;
    return parameters;
  }
  // The quick model with the default training's 2 mm surface set: its own 6 mm set is too coarse
  // to verify against.
  static std::shared_ptr<const ModelBundle> model() {
    static const std::shared_ptr<const ModelBundle> bundle = [] {
      ModelBundle copy = *test::quickMugModel();
      const SurfaceSamples samples = sampleSurface(makeMug(), 0.002, 1);
      copy.surface_points = samples.points;
      copy.surface_normals = samples.normals;
      copy.parameters.surface_spacing = 0.002;
      return std::make_shared<const ModelBundle>(std::move(copy));
    }();
    return bundle;
  }
};

TEST_F(EstimatorRefinementTest, OneViewGivesAGraspReadyPose) {
  // One view leaves the roll free; refinement settles it and the position with it.
  const auto [cloud, world_from_camera] = handleView();
  OrientationEstimator plain(model(), withoutRefinement());
  OrientationEstimator refined(model(), withIcp());
  ASSERT_TRUE(plain.update(cloud, world_from_camera).updated);
  const ViewUpdate update = refined.update(cloud, world_from_camera);
  ASSERT_TRUE(update.updated) << update.skip_reason;
  EXPECT_GE(update.refined_poses, 1) << update.refinement_skip_reason;
  EXPECT_GT(update.timing.refinement, 0.0);
  const double plain_error = rotationErrorDeg(plain.mapOrientation(), truth());
  const double refined_error = rotationErrorDeg(refined.mapOrientation(), truth());
  EXPECT_LT(refined_error, 5.0) << "without refinement " << plain_error << ", "
                                << update.refined_poses << " poses in " << update.timing.refinement
                                << " ms";
  EXPECT_LT(refined_error, plain_error);
  RecordProperty("refinement_ms", std::to_string(update.timing.refinement));
  RecordProperty("error_deg_without", std::to_string(plain_error));
  RecordProperty("error_deg_with", std::to_string(refined_error));
  const Eigen::Vector3d position = *refined.positionEstimate();
  RecordProperty("position_error_mm",
                 std::to_string(1000.0 * (position - worldFromObject().translation()).norm()));
  EXPECT_LT((position - worldFromObject().translation()).norm(), 0.003);
  // The refined position carries its fit's covariance; the belief alone has none.
  ASSERT_TRUE(refined.positionCovariance().has_value());
  EXPECT_GT(refined.positionCovariance()->trace(), 0.0);
  EXPECT_FALSE(plain.positionCovariance().has_value());
  // The belief stays a Bingham mixture with the verified pose as its peak.
  EXPECT_GT(refined.belief().density(truth()), plain.belief().density(truth()));
}

TEST_F(EstimatorRefinementTest,
       AnUncertainCameraPoseAndModelWidenThePositionCovarianceByTheirShare) {
  const auto [cloud, world_from_camera] = handleView();
  EstimatorParameters uncertain = withIcp();
  uncertain.refined_fusion.camera_pose_uncertainty_deg = 2.0;
  uncertain.refined_fusion.camera_pose_uncertainty_mm = 5.0;
  uncertain.refined_fusion.model_error_mm = 3.0;
  OrientationEstimator exact(model(), withIcp());
  OrientationEstimator widened(model(), uncertain);
  exact.update(cloud, world_from_camera);
  widened.update(cloud, world_from_camera);
  ASSERT_TRUE(exact.positionCovariance() && widened.positionCovariance());
  // The same fit (the camera's error does not enter it), so the difference is the camera's.
  ASSERT_LT((*widened.positionEstimate() - *exact.positionEstimate()).norm(), 1e-9);
  const Eigen::Matrix3d added =
      cameraPosePositionCovariance(*exact.positionEstimate() - world_from_camera.translation(), 2.0,
                                   5.0) +
      modelErrorPositionCovariance(3.0);
  EXPECT_TRUE((*widened.positionCovariance() - *exact.positionCovariance()).isApprox(added, 1e-9));
  // 2 degrees at about 0.6 m: centimetres, where the fit alone says millimetres.
  EXPECT_GT(std::sqrt(widened.positionCovariance()->trace()), 0.01);
  EXPECT_GT(widened.positionCovariance()->trace(), 10.0 * exact.positionCovariance()->trace());
}

TEST_F(EstimatorRefinementTest, ASkippedRefinementLeavesTheBeliefAsWithout) {
  const auto [cloud, world_from_camera] = handleView();
  EstimatorParameters parameters = withIcp();
  parameters.refinement_parameters.min_points = 1000000;  // no view has that many points
  OrientationEstimator plain(model(), withoutRefinement());
  OrientationEstimator skipped(model(), parameters);
  plain.update(cloud, world_from_camera);
  const ViewUpdate update = skipped.update(cloud, world_from_camera);
  EXPECT_EQ(update.refined_poses, 0);
  EXPECT_NE(update.refinement_skip_reason.find("finite object points"), std::string::npos);
  EXPECT_EQ(skipped.belief().size(), plain.belief().size());
  EXPECT_LT(rotationErrorDeg(skipped.mapOrientation(), plain.mapOrientation()), 1e-9);
  EXPECT_LT((*skipped.positionEstimate() - *plain.positionEstimate()).norm(), 1e-12);
  EXPECT_FALSE(skipped.positionCovariance().has_value());
}

// A view of the mug from above its rim (its opening in sight) with noise, at the true pose.
std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> viewFromAbove(
    const Eigen::Isometry3d& world_from_object) {
  const Eigen::Isometry3d camera_from_object =
      cameraFromObject(Eigen::Vector3d(-0.4, 0.3, 0.9).normalized(), 0.6, 0.4);
  std::mt19937 rng(11);
  return {DepthRenderer(makeMug()).render(camera_from_object, DepthNoiseModel{true}, &rng),
          world_from_object * camera_from_object.inverse()};
}

// A side view of the mug with its handle away from the camera, with noise.
std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> viewFromSide(
    const Eigen::Isometry3d& world_from_object) {
  const Eigen::Isometry3d camera_from_object =
      cameraFromObject(Eigen::Vector3d(-1.0, -0.2, 0.1).normalized(), 0.6, 2.0);
  std::mt19937 rng(13);
  return {DepthRenderer(makeMug()).render(camera_from_object, DepthNoiseModel{true}, &rng),
          world_from_object * camera_from_object.inverse()};
}

std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d>
EstimatorRefinementTest::sureOfTheUpsideDownMug(
    const std::vector<OrientationEstimator*>& estimators) {
  Eigen::Isometry3d upside_down = Eigen::Isometry3d::Identity();
  upside_down.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Isometry3d world_from_object = worldFromObject();
  const Eigen::Isometry3d wrong = world_from_object * upside_down;
  const auto [first, world_from_camera] = handleView();
  const Eigen::Isometry3d reported = wrong * world_from_object.inverse() * world_from_camera;
  const auto [side, side_reported] = viewFromSide(wrong);
  for (OrientationEstimator* estimator : estimators) {
    EXPECT_TRUE(estimator->update(first, reported).updated);
    EXPECT_TRUE(estimator->update(side, side_reported).updated);
  }
  return viewFromAbove(world_from_object);
}

TEST_F(EstimatorRefinementTest, AViewTheSureBeliefCannotExplainRebuildsIt) {
  OrientationEstimator checked(model(), withIcp());
  EstimatorParameters unchecked_parameters = withIcp();
  unchecked_parameters.belief_check.search_below_score = 0.0;
  OrientationEstimator unchecked(model(), unchecked_parameters);
  const auto [second, second_pose] = sureOfTheUpsideDownMug({&checked, &unchecked});
  for (OrientationEstimator* estimator : {&checked, &unchecked}) {
    ASSERT_GT(rotationErrorDeg(estimator->mapOrientation(), truth()), 170.0);
  }
  const ViewUpdate update = checked.update(second, second_pose);
  ASSERT_TRUE(update.updated) << update.skip_reason;
  EXPECT_TRUE(update.searched);
  EXPECT_NE(update.rebuild_reason.find("contradicted the belief"), std::string::npos);
  EXPECT_LT(rotationErrorDeg(checked.mapOrientation(), truth()), 5.0);
  EXPECT_LT((*checked.positionEstimate() - worldFromObject().translation()).norm(), 0.005);

  // Without the check the belief stays sure of the upside-down mug.
  const ViewUpdate stuck = unchecked.update(second, second_pose);
  EXPECT_FALSE(stuck.searched);
  EXPECT_TRUE(stuck.rebuild_reason.empty());
  EXPECT_GT(rotationErrorDeg(unchecked.mapOrientation(), truth()), 90.0);
}

// The scene layer defers the search (BeliefSearch::kDeferred) and completes it only when no
// model explains a candidate at once: completed, it must do what it does at once.
TEST_F(EstimatorRefinementTest, ADeferredSearchCompletedRebuildsTheBeliefAsOneAtOnce) {
  OrientationEstimator at_once(model(), withIcp());
  OrientationEstimator deferred(model(), withIcp());
  const auto [second, second_pose] = sureOfTheUpsideDownMug({&at_once, &deferred});
  const ViewUpdate searched = at_once.update(second, second_pose);
  ASSERT_TRUE(searched.searched);

  const ViewUpdate pending =
      deferred.update(second, second_pose, std::nullopt, {{}, BeliefSearch::kDeferred, nullptr});
  ASSERT_TRUE(pending.updated) << pending.skip_reason;
  EXPECT_TRUE(pending.search_pending);
  EXPECT_FALSE(pending.searched);
  EXPECT_GT(rotationErrorDeg(deferred.mapOrientation(), truth()), 90.0) << "searched already";
  const ViewUpdate completed = deferred.completeSearch(pending);
  EXPECT_FALSE(completed.search_pending);
  EXPECT_TRUE(completed.searched);
  EXPECT_EQ(completed.rebuild_reason, searched.rebuild_reason);
  EXPECT_EQ(completed.refined_poses, searched.refined_poses);
  EXPECT_EQ(completed.verified_score, searched.verified_score);
  EXPECT_LT(rotationErrorDeg(deferred.mapOrientation(), at_once.mapOrientation()), 1e-6);
  EXPECT_EQ(deferred.updateCount(), at_once.updateCount());
  // Nothing is pending any more: completing again changes nothing.
  EXPECT_EQ(deferred.completeSearch(completed).verified_score, completed.verified_score);
  EXPECT_EQ(deferred.updateCount(), at_once.updateCount());
}

TEST_F(EstimatorRefinementTest, ViewsTheBeliefExplainsNeverRebuildIt) {
  const auto [first, world_from_camera] = handleView();
  const auto [second, second_pose] = viewFromAbove(worldFromObject());
  OrientationEstimator estimator(model(), withIcp());
  for (const ViewUpdate& update :
       {estimator.update(first, world_from_camera), estimator.update(second, second_pose)}) {
    ASSERT_TRUE(update.updated) << update.skip_reason;
    EXPECT_TRUE(update.rebuild_reason.empty()) << update.rebuild_reason;
  }
  EXPECT_LT(rotationErrorDeg(estimator.mapOrientation(), truth()), 5.0);
}

// `cloud` with every twentieth finite point moved 10 mm along its ray, towards the camera or away:
// the long tails of a stereo camera's depth, which keep even the right pose's verification below
// search_below_score (PCL's real stereo scan: 0.90).
pcl::PointCloud<pcl::PointXYZ> withDepthTails(pcl::PointCloud<pcl::PointXYZ> cloud) {
  int finite = 0;
  for (auto& p : cloud.points) {
    if (!std::isfinite(p.z) || finite++ % 20 != 0) continue;
    const Eigen::Vector3f ray = p.getVector3fMap().normalized();
    p.getVector3fMap() += (finite % 40 == 1 ? 0.01f : -0.01f) * ray;
  }
  return cloud;
}

TEST_F(EstimatorRefinementTest, ANoisyCameraSearchesOnceNotOnEveryView) {
  const auto [first, world_from_camera] = handleView();
  const auto [second, second_pose] = viewFromAbove(worldFromObject());
  OrientationEstimator estimator(model(), withIcp());
  const ViewUpdate searched = estimator.update(withDepthTails(first), world_from_camera);
  ASSERT_TRUE(searched.updated) << searched.skip_reason;
  EXPECT_TRUE(searched.searched) << "the right pose should verify below search_below_score";
  EXPECT_TRUE(searched.rebuild_reason.empty()) << searched.rebuild_reason;
  // The search found nothing better: the next view that fits as well is this camera's normal.
  const ViewUpdate next = estimator.update(withDepthTails(second), second_pose);
  ASSERT_TRUE(next.updated) << next.skip_reason;
  EXPECT_GE(next.refined_poses, 1) << next.refinement_skip_reason;
  EXPECT_FALSE(next.searched);
  EXPECT_LT(rotationErrorDeg(estimator.mapOrientation(), truth()), 5.0);
  RecordProperty("first_view_refinement_ms", std::to_string(searched.timing.refinement));
  RecordProperty("second_view_refinement_ms", std::to_string(next.timing.refinement));
  // A reset forgets what the camera reaches: the first view after it searches again.
  estimator.reset();
  EXPECT_TRUE(estimator.update(withDepthTails(second), second_pose).searched);
}

TEST(BeliefCheckParametersTest, RefusesNonsense) {
  const auto refused = [](auto change) {
    BeliefCheckParameters parameters;
    change(&parameters);
    EXPECT_THROW(checkBeliefCheckParameters(parameters), Error);
  };
  EXPECT_NO_THROW(checkBeliefCheckParameters(BeliefCheckParameters{}));
  refused([](BeliefCheckParameters* p) { p->search_below_score = 1.5; });
  refused([](BeliefCheckParameters* p) { p->search_below_score = std::nan(""); });
  refused([](BeliefCheckParameters* p) { p->rebuild_margin = -0.1; });
  refused([](BeliefCheckParameters* p) { p->check_views = 0; });
  refused([](BeliefCheckParameters* p) { p->search_girdle_step_deg = 0.0; });
  refused([](BeliefCheckParameters* p) { p->search_max_refined = 0; });
  EstimatorParameters estimator;
  estimator.belief_check.check_views = 0;
  EXPECT_THROW(OrientationEstimator(test::quickMugModel(), estimator), Error);
}

}  // namespace
}  // namespace vdc
