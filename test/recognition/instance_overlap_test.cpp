// Whether an identified object is an instance already held (InstanceOverlap): two mugs side by
// side share little of their volume, a mug moved a few centimetres or turned in place most of it.
#include "view_direction_classification/recognition/instance_overlap.h"

#include <gtest/gtest.h>

#include "support/mug_scene.h"
#include "support/quick_mug_model.h"

namespace vdc {
namespace {

using test::kMugPosition;
using test::placed;

class InstanceOverlapTest : public ::testing::Test {
 protected:
  InstanceOverlapTest()
      : library_({{"mug", test::quickMugModel()}}),
        overlap_(library_),
        sizes_(library_.models().front().bundle->bounds.sizes()) {}

  double overlapWith(const Eigen::Vector3d& shift, double yaw = 0.0) const {
    return overlap_.overlap(0, placed(kMugPosition), placed(kMugPosition + shift, yaw));
  }

  ModelLibrary library_;
  InstanceOverlap overlap_;
  Eigen::Vector3d sizes_;  // the mug's box
};

TEST_F(InstanceOverlapTest, APoseSharesAllOfItsVolumeWithItself) {
  EXPECT_DOUBLE_EQ(overlapWith(Eigen::Vector3d::Zero()), 1.0);
}

// The scene estimator takes an identified object for an instance it overlaps by 0.1 or more.
TEST_F(InstanceOverlapTest, TwoMugsSideBySideShareNothing) {
  // Touching: bodies side by side (the mug's width), handle to body (its length).
  EXPECT_EQ(overlapWith(Eigen::Vector3d(0.0, sizes_.y(), 0.0)), 0.0);
  EXPECT_LT(overlapWith(Eigen::Vector3d(sizes_.x(), 0.0, 0.0)), 0.01);
  // Turned the other way, the handle reaches into the other's hull beside it.
  EXPECT_LT(overlapWith(Eigen::Vector3d(0.0, sizes_.y() + 0.005, 0.0), 3.14), 0.1);
}

TEST_F(InstanceOverlapTest, AMugMovedUpToSixCentimetresOrTurnedInPlaceSharesATenthOrMore) {
  EXPECT_GT(overlapWith(Eigen::Vector3d(0.03, 0.0, 0.0)), 0.4);
  EXPECT_GT(overlapWith(Eigen::Vector3d(0.0, 0.03, 0.0)), 0.4);
  EXPECT_GT(overlapWith(Eigen::Vector3d(0.036, 0.048, 0.0)), 0.1);
  EXPECT_GT(overlapWith(Eigen::Vector3d::Zero(), 1.5), 0.6);
}

TEST_F(InstanceOverlapTest, OverlapFallsAsTheMugMovesAway) {
  double previous = 1.0;
  for (double shift = 0.01; shift < sizes_.x() + 0.02; shift += 0.01) {
    const double shared = overlapWith(Eigen::Vector3d(shift, 0.0, 0.0));
    EXPECT_LE(shared, previous) << "at " << shift << " m";
    previous = shared;
  }
  EXPECT_EQ(previous, 0.0);
}

TEST_F(InstanceOverlapTest, OverlapIsSymmetric) {
  const Eigen::Isometry3d a = placed(kMugPosition, 0.3);
  const Eigen::Isometry3d b = placed(kMugPosition + Eigen::Vector3d(0.02, -0.03, 0.0), -1.1);
  EXPECT_DOUBLE_EQ(overlap_.overlap(0, a, b), overlap_.overlap(0, b, a));
}

}  // namespace
}  // namespace vdc
