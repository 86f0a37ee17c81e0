#include "kept_poses.h"

#include <gtest/gtest.h>

#include <vector>

#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"

namespace vdc {
namespace {

// A converged, verified pose turned by angle_deg about the object's x from a fixed orientation.
RefinedPose pose(double angle_deg, double score, bool accepted = true) {
  RefinedPose p;
  p.orientation = quaternionFromAxisAngle(Eigen::Vector3d::UnitX(), angle_deg * M_PI / 180.0);
  p.world_from_object.linear() = quaternionToRotationMatrix(p.orientation);
  p.score.inlier_fraction = score;
  p.screened_in = true;
  p.converged = true;
  p.accepted = accepted;
  if (!accepted) p.rejection = "the refined orientation left the belief's credible region";
  return p;
}

double angleOf(const RefinedPose& p) {
  return rotationErrorDeg(p.orientation, Eigen::Vector4d(1, 0, 0, 0));
}

TEST(KeptPoses, TheDistinctAcceptedPosesWithinTheKeepMarginBestFirst) {
  const RefinementParameters parameters;  // keep margin 0.03, duplicates within 5 degrees
  const std::vector<RefinedPose> kept = keptPoses(
      {pose(90, 0.93), pose(0, 0.95), pose(2, 0.94), pose(180, 0.90), pose(45, 0.96, false)},
      parameters);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_NEAR(angleOf(kept[0]), 0.0, 1e-6);
  EXPECT_NEAR(angleOf(kept[1]), 90.0, 1e-6);
}

TEST(VerifiedAlternatives, AConvergedPoseWithinTheMeasurementMarginEntersWhateverRefusedIt) {
  RefinementParameters parameters;
  parameters.measurement_score_margin = 0.1;
  const std::vector<RefinedPose> tried{pose(0, 0.95), pose(180, 0.90, false), pose(90, 0.84),
                                       pose(120, 0.89, true)};
  const std::vector<RefinedPose> kept = keptPoses(tried, parameters);
  ASSERT_EQ(kept.size(), 1u);
  const std::vector<RefinedPose> alternatives = verifiedAlternatives(tried, kept, parameters);
  // The twin refused for leaving the credible region and the accepted 120-degree pose, best
  // first; the 90-degree one is 0.11 behind.
  ASSERT_EQ(alternatives.size(), 2u);
  EXPECT_NEAR(angleOf(alternatives[0]), 180.0, 1e-6);
  EXPECT_NEAR(angleOf(alternatives[1]), 120.0, 1e-6);
  parameters.measurement_score_margin = 0.0;
  EXPECT_TRUE(verifiedAlternatives(tried, kept, parameters).empty());
}

TEST(VerifiedAlternatives, NeitherUnconvergedPosesNorTheKeptPosesAgainNorTheirSectors) {
  const RefinementParameters parameters;
  RefinedPose unconverged = pose(180, 0.94);
  unconverged.converged = false;
  RefinedPose unscreened = pose(150, 0.94);
  unscreened.screened_in = false;
  RefinedPose kept_pose = pose(0, 0.95);
  // Its sector: turns about x up to 60 degrees verify as well.
  kept_pose.sector_axis = Eigen::Vector3d::UnitX();
  kept_pose.roll_sector_deg = 60.0;
  const std::vector<RefinedPose> tried{kept_pose,  pose(3, 0.91),         unconverged,
                                       unscreened, pose(50, 0.92, false), pose(100, 0.90)};
  const std::vector<RefinedPose> alternatives =
      verifiedAlternatives(tried, {kept_pose}, parameters);
  ASSERT_EQ(alternatives.size(), 1u);
  EXPECT_NEAR(angleOf(alternatives[0]), 100.0, 1e-6);
  EXPECT_TRUE(verifiedAlternatives(tried, {}, parameters).empty());
}

TEST(VerifiedAlternatives, AtMostMaxAlternativesAndNoTwoTheSame) {
  RefinementParameters parameters;
  parameters.max_alternatives = 2;
  const std::vector<RefinedPose> tried{pose(0, 0.95),   pose(60, 0.91),  pose(62, 0.92),
                                       pose(120, 0.90), pose(180, 0.89), pose(240, 0.88)};
  const std::vector<RefinedPose> alternatives = verifiedAlternatives(tried, {tried[0]}, parameters);
  ASSERT_EQ(alternatives.size(), 2u);
  EXPECT_NEAR(angleOf(alternatives[0]), 62.0, 1e-6);
  EXPECT_NEAR(angleOf(alternatives[1]), 120.0, 1e-6);
  parameters.max_alternatives = 0;
  EXPECT_TRUE(verifiedAlternatives(tried, {tried[0]}, parameters).empty());
}

}  // namespace
}  // namespace vdc
