#include "view_direction_classification/planning/next_best_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/axis_model_bundle.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

using test::makeAxisBundle;
using test::sharpAround;

TEST(RankCandidates, OrdersByDescendingUtilityAndReportsTheViewSeen) {
  const ViewUtilityScorer scorer(makeAxisBundle());
  PlanningScene scene;
  scene.object_position = Eigen::Vector3d(1, 0, 0);
  // The object is turned by a half turn about z: a camera at world -x sees its +x face.
  scene.orientation = quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI);
  const std::vector<Eigen::Vector3d> candidates = {
      {1.6, 0, 0}, {0.4, 0, 0}, {1, 0, 0.6}};  // sees -x (0.5), +x (2), +z (1.25)
  const auto ranked = rankCandidates(scorer, candidates, ViewUtility::kInformativeness, scene);
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0].index, 0);
  EXPECT_EQ(ranked[0].view, 1);
  EXPECT_NEAR(ranked[0].utility, -0.5, 1e-9);
  EXPECT_EQ(ranked[1].index, 2);
  EXPECT_EQ(ranked[2].index, 1);
  EXPECT_EQ(ranked[2].view, 0);

  // With two hypotheses (identity, half turn) only the x candidates tell them apart.
  scene.belief = BinghamMixture(
      {0.5, 0.5}, {sharpAround(Eigen::Vector4d(1, 0, 0, 0)), sharpAround(scene.orientation)});
  const auto gains = rankCandidates(scorer, candidates, ViewUtility::kInformationGain, scene);
  EXPECT_NEAR(gains[0].utility, std::log(2.0), 1e-9);
  EXPECT_NEAR(gains[1].utility, std::log(2.0), 1e-9);
  EXPECT_EQ(gains[2].index, 2);
  EXPECT_NEAR(gains[2].utility, 0.0, 1e-9);

  EXPECT_THROW(rankCandidates(scorer, {}, ViewUtility::kInformativeness, scene), Error);
  EXPECT_THROW(rankCandidates(scorer, {{1, 0, 0}}, ViewUtility::kInformativeness, scene), Error);
}

TEST(SampleCandidatePoses, PutsCamerasAtTheDistanceLookingAtTheObject) {
  const Eigen::Vector3d object(0.5, -0.2, 0.8);
  const auto poses = sampleCandidatePoses(42, 0.7, object);
  ASSERT_EQ(poses.size(), 42u);
  for (const auto& pose : poses) {
    EXPECT_NEAR((pose.translation() - object).norm(), 0.7, 1e-9);
    const Eigen::Vector3d optical_axis = pose.linear().col(2);
    EXPECT_NEAR(optical_axis.dot((object - pose.translation()).normalized()), 1.0, 1e-9);
  }
  EXPECT_THROW(sampleCandidatePoses(1, 0.7, object), Error);
  // More would hold the server for seconds (the sphere grows with the count's square).
  EXPECT_THROW(sampleCandidatePoses(kMaxSampledCandidates + 1, 0.7, object), Error);
  EXPECT_THROW(sampleCandidatePoses(10, 0.0, object), Error);
}

}  // namespace
}  // namespace vdc
