// The estimator on camera streams (doc/method.md section 12): which frames are new views, how
// much nearby views count, tf jumps, a moved object and table-top scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/mug_scene.h"
#include "support/quick_mug_model.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {
namespace {

constexpr double kFrameSeconds = 1.0 / 30.0;
// The quick model's 12 directions are 63.4 degrees apart (acos(1 / sqrt 5)).
const double kSpacing = 1.1071;

double degrees(double deg) { return deg * M_PI / 180.0; }

// A camera stream around the mug of test::mugScene: each frame rendered with fresh noise.
class CameraStream {
 public:
  explicit CameraStream(const Scene& scene) : renderer_(sceneMesh(scene)) {}

  // The camera looks at `target` from the fixed-frame direction `direction` at 0.6 m.
  std::pair<pcl::PointCloud<pcl::PointXYZ>, Eigen::Isometry3d> frame(
      const Eigen::Vector3d& direction, const Eigen::Vector3d& target = test::kMugPosition) {
    const Eigen::Isometry3d camera_from_world = test::cameraFromWorld(direction, 0.6, target);
    return {renderer_.render(camera_from_world, DepthNoiseModel{true}, &rng_),
            camera_from_world.inverse()};
  }

 private:
  DepthRenderer renderer_;
  std::mt19937 rng_{3};
};

// The fixed-frame direction at `azimuth` [rad] around the mug, 30 degrees above the horizon.
Eigen::Vector3d around(double azimuth) {
  return Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), std::tan(degrees(30)));
}

TEST(OrientationEstimatorStream, AStillCameraFusesItsFirstFrameOnlyAndTheBeliefStaysAsItLeftIt) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  CameraStream stream(test::mugScene(false, false));
  double first_entropy = 0.0;
  int fused = 0, not_novel = 0;
  for (int k = 0; k < 30; ++k) {
    const auto [cloud, world_from_camera] = stream.frame(around(0.4));
    const ViewUpdate update = estimator.update(cloud, world_from_camera, k * kFrameSeconds);
    fused += update.outcome == FrameOutcome::kFused;
    not_novel += update.outcome == FrameOutcome::kNotNovel;
    if (k == 0) first_entropy = estimator.entropy();
    if (k > 0) {
      EXPECT_LT(update.view_separation, degrees(3)) << "frame " << k;
      EXPECT_EQ(update.features, 0) << "a frame that is not novel is not featurised";
    }
  }
  EXPECT_EQ(fused, 1);
  EXPECT_EQ(not_novel, 29);
  EXPECT_EQ(estimator.viewsFused(), 1);
  EXPECT_EQ(estimator.entropy(), first_entropy);
}

// Issue 14's target: a camera that never moves for 60 s leaves the belief no narrower than its
// first view did (noisy copies of one view are not new evidence). Every frame has fresh noise.
TEST(OrientationEstimatorStream,
     SixtySecondsOfAStillCameraAt30HzLeaveTheBeliefAsWideAsItsFirstView) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  CameraStream stream(test::mugScene(false, false));
  double first_cone90 = 0.0, first_entropy = 0.0;
  for (int k = 0; k <= 60 * 30; ++k) {
    const auto [cloud, world_from_camera] = stream.frame(around(1.2));
    const ViewUpdate update = estimator.update(cloud, world_from_camera, k * kFrameSeconds);
    ASSERT_NE(update.outcome, FrameOutcome::kSkipped) << "frame " << k << update.skip_reason;
    if (k == 0) {
      first_cone90 = estimator.spread().cone90;
      first_entropy = estimator.entropy();
    }
  }
  EXPECT_EQ(estimator.viewsFused(), 1);
  EXPECT_GE(estimator.spread().cone90, first_cone90);
  EXPECT_GE(estimator.entropy(), first_entropy);
}

TEST(OrientationEstimatorStream, AnArcFusesANewViewEachMinViewSeparationWithTemperedLikelihood) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  CameraStream stream(test::mugScene(false, false));
  std::vector<double> fused_at, exponents;
  for (int k = 0; k <= 60; ++k) {  // 2 degrees per frame over 120 degrees
    const double azimuth = degrees(2.0 * k);
    const auto [cloud, world_from_camera] = stream.frame(around(azimuth));
    const ViewUpdate update = estimator.update(cloud, world_from_camera, k * kFrameSeconds);
    ASSERT_NE(update.outcome, FrameOutcome::kSkipped) << update.skip_reason;
    if (update.outcome == FrameOutcome::kFused) {
      fused_at.push_back(2.0 * k);
      exponents.push_back(update.likelihood_exponent);
      if (k > 0) {
        // Half the spacing apart (plus up to one step and the position estimate's error), so
        // the likelihood is raised to about separation / spacing.
        EXPECT_GE(update.view_separation, 0.5 * kSpacing);
        EXPECT_LT(update.view_separation, 0.5 * kSpacing + degrees(6));
        EXPECT_NEAR(update.likelihood_exponent, update.view_separation / kSpacing, 1e-4);
      }
    }
  }
  // Along the arc about every 32 degrees: 0, ~32, ~64, ~96 (the camera's azimuth is measured
  // from the object's origin, the estimator's from its position estimate).
  ASSERT_EQ(fused_at.size(), 4u);
  EXPECT_EQ(exponents.front(), 1.0);
  for (std::size_t i = 1; i < fused_at.size(); ++i) {
    EXPECT_NEAR(fused_at[i] - fused_at[i - 1], 32.0, 6.0);
    EXPECT_NEAR(exponents[i], 0.5, 0.1);
  }
  EXPECT_EQ(estimator.viewsFused(), 4);
}

TEST(OrientationEstimatorStream, SelectionAndTemperingCanBeSwitchedOff) {
  EstimatorParameters parameters;
  parameters.selection.min_view_separation = 0.0;          // every frame a new view
  parameters.selection.independent_view_separation = 0.0;  // untempered
  OrientationEstimator estimator(test::quickMugModel(), parameters);
  CameraStream stream(test::mugScene(false, false));
  for (int k = 0; k < 3; ++k) {
    const auto [cloud, world_from_camera] = stream.frame(around(degrees(5.0 * k)));
    const ViewUpdate update = estimator.update(cloud, world_from_camera, k * kFrameSeconds);
    EXPECT_EQ(update.outcome, FrameOutcome::kFused);
    EXPECT_EQ(update.likelihood_exponent, 1.0);
  }
  EXPECT_EQ(estimator.viewsFused(), 3);
}

TEST(OrientationEstimatorStream, InformationGainAdmitsAViewTheSeparationAloneWouldNot) {
  EstimatorParameters parameters;
  parameters.selection.min_view_separation = 3.0;  // no frame is new by separation
  // The quick model's belief after two views still splits between hypotheses: the same view
  // again is predicted ~1.9 nats, tempered to ~0.03 by its separation of ~1 degree.
  parameters.selection.min_information_gain = 0.1;
  OrientationEstimator estimator(test::quickMugModel(), parameters);
  CameraStream stream(test::mugScene(false, false));
  const Eigen::Vector3d directions[] = {around(0.0), around(degrees(70)), around(degrees(70))};
  FrameOutcome outcomes[3];
  for (int k = 0; k < 3; ++k) {
    const auto [cloud, world_from_camera] = stream.frame(directions[k]);
    outcomes[k] = estimator.update(cloud, world_from_camera, k * 2.0).outcome;
  }
  EXPECT_EQ(outcomes[0], FrameOutcome::kFused);
  EXPECT_EQ(outcomes[1], FrameOutcome::kFused) << "a view 70 degrees away predicts information";
  // The same view again: its likelihood exponent (separation / spacing) is ~0, so is its gain.
  EXPECT_EQ(outcomes[2], FrameOutcome::kNotNovel);
}

TEST(OrientationEstimatorStream, AJumpingCameraPoseIsSkippedAndTheNextConsistentFrameUsed) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  CameraStream stream(test::mugScene(false, false));
  auto [cloud, world_from_camera] = stream.frame(around(0.0));
  ASSERT_EQ(estimator.update(cloud, world_from_camera, 0.0).outcome, FrameOutcome::kFused);
  // Within one frame the camera is 100 degrees around the mug (0.9 m away): a teleport.
  std::tie(cloud, world_from_camera) = stream.frame(around(degrees(100)));
  ViewUpdate update = estimator.update(cloud, world_from_camera, kFrameSeconds);
  EXPECT_EQ(update.outcome, FrameOutcome::kSkipped);
  EXPECT_NE(update.skip_reason.find("jumped"), std::string::npos) << update.skip_reason;
  // It stays there: the next frame is consistent with the last and a new view.
  std::tie(cloud, world_from_camera) = stream.frame(around(degrees(100)));
  update = estimator.update(cloud, world_from_camera, 2 * kFrameSeconds);
  EXPECT_EQ(update.outcome, FrameOutcome::kFused) << update.skip_reason;
  EXPECT_EQ(estimator.viewsFused(), 2);
}

TEST(OrientationEstimatorStream, AMovedObjectResetsTheBeliefAndAnEmptyViewIsSkipped) {
  OrientationEstimator estimator(test::quickMugModel(), {});
  CameraStream stream(test::mugScene(false, false));
  auto [cloud, world_from_camera] = stream.frame(around(0.0));
  ASSERT_EQ(estimator.update(cloud, world_from_camera, 0.0).outcome, FrameOutcome::kFused);
  // The mug 15 cm further right in the same camera's cloud.
  Scene moved = test::mugScene(false, false);
  moved.object.world_from_part.translation() += Eigen::Vector3d(0, 0.15, 0);
  CameraStream moved_stream(moved);
  std::tie(cloud, world_from_camera) = moved_stream.frame(around(0.0));
  const ViewUpdate update = estimator.update(cloud, world_from_camera, 1.0);
  EXPECT_NE(update.reset_reason.find("moved"), std::string::npos) << update.reset_reason;
  EXPECT_EQ(update.outcome, FrameOutcome::kFused) << "the frame is the first view after the reset";
  EXPECT_EQ(estimator.viewsFused(), 1);
  EXPECT_NEAR(
      (update.observed_centroid_world - (test::kMugPosition + Eigen::Vector3d(0, 0.15, 0))).norm(),
      0.0, 0.04);

  const ViewUpdate empty =
      estimator.update(pcl::PointCloud<pcl::PointXYZ>(), world_from_camera, 2.0);
  EXPECT_EQ(empty.outcome, FrameOutcome::kSkipped);
  EXPECT_NE(empty.skip_reason.find("not in view"), std::string::npos) << empty.skip_reason;
  EXPECT_EQ(estimator.viewsFused(), 1);
}

EstimatorParameters tabletop() {
  EstimatorParameters parameters;
  parameters.segmentation.mode = SegmentationMode::kTabletop;
  return parameters;
}

TEST(OrientationEstimatorStream, TabletopFollowsTheMugAmongDistractorsAroundTheTable) {
  OrientationEstimator estimator(test::quickMugModel(), tabletop());
  CameraStream stream(test::mugScene(true, true));
  int fused = 0;
  for (int k = 0; k <= 45; ++k) {  // 4 degrees per frame, 180 degrees around the table
    const auto [cloud, world_from_camera] = stream.frame(around(degrees(4.0 * k)));
    const ViewUpdate update = estimator.update(cloud, world_from_camera, k * kFrameSeconds);
    ASSERT_NE(update.outcome, FrameOutcome::kSkipped)
        << "frame " << k << ": " << update.skip_reason;
    if (update.outcome != FrameOutcome::kFused) continue;
    ++fused;
    // The mug's own points: its visible part's centroid is within 4 cm of its origin.
    EXPECT_LT((update.observed_centroid_world - test::kMugPosition).norm(), 0.04) << "frame " << k;
  }
  EXPECT_GE(fused, 5);
  EXPECT_LE(fused, 7);  // 180 / 31.7 + 1
}

TEST(OrientationEstimatorStream, TabletopSkipsAFrameWithoutAFittingClusterAndFindsAMovedMug) {
  OrientationEstimator estimator(test::quickMugModel(), tabletop());
  // Only the distractors on the table: nothing fits the mug.
  Scene no_mug = test::mugScene(true, true);
  no_mug.object.world_from_part.translation() += Eigen::Vector3d(0, 0, -1.0);  // under the table
  no_mug.table_size.reset();
  no_mug.distractors.push_back(
      {makeRectangleMesh(Eigen::Vector2d(1.4, 1.0)),
       test::placed(
           Eigen::Vector3d(test::kMugPosition.x(), test::kMugPosition.y(), test::tableTop()))});
  auto [cloud, world_from_camera] = CameraStream(no_mug).frame(around(0.0));
  ViewUpdate update = estimator.update(cloud, world_from_camera, 0.0);
  EXPECT_EQ(update.outcome, FrameOutcome::kSkipped);
  EXPECT_NE(update.skip_reason.find("fits the model's size"), std::string::npos)
      << update.skip_reason;

  CameraStream stream(test::mugScene(true, true));
  std::tie(cloud, world_from_camera) = stream.frame(around(0.0));
  ASSERT_EQ(estimator.update(cloud, world_from_camera, 1.0).outcome, FrameOutcome::kFused);
  // Someone puts the mug 25 cm to the left on the same table; the camera, looking where it was,
  // sees the table through its old place and finds it anew.
  Scene moved = test::mugScene(true, true);
  const Eigen::Vector3d new_place = test::kMugPosition + Eigen::Vector3d(-0.05, -0.2, 0);
  moved.object.world_from_part.translation() = new_place;
  std::tie(cloud, world_from_camera) = CameraStream(moved).frame(around(0.0));
  update = estimator.update(cloud, world_from_camera, 2.0);
  EXPECT_NE(update.reset_reason.find("moved"), std::string::npos)
      << update.reset_reason << update.skip_reason;
  EXPECT_EQ(update.outcome, FrameOutcome::kFused) << update.skip_reason;
  EXPECT_LT((update.observed_centroid_world - new_place).norm(), 0.04);
}

}  // namespace
}  // namespace vdc
