#include "view_direction_classification/recognition/instance_association.h"

#include <gtest/gtest.h>

namespace vdc {
namespace {

TEST(InstanceAssociation, NearestPairsFirstEachTakenOnce) {
  // Two instances 8 cm apart (two mugs side by side) and three candidates: one near each
  // instance, one new object far away.
  const std::vector<Eigen::Vector3d> instances{{0.0, 0.0, 0.0}, {0.08, 0.0, 0.0}};
  const std::vector<Eigen::Vector3d> candidates{
      {0.075, 0.01, 0.0}, {0.01, 0.0, 0.0}, {0.5, 0.0, 0.0}};
  EXPECT_EQ(associateCandidates(candidates, instances, 0.05), (std::vector<int>{1, 0, -1}));
}

TEST(InstanceAssociation, OneInstanceIsNeverTwoCandidates) {
  const std::vector<Eigen::Vector3d> instances{{0.0, 0.0, 0.0}};
  const std::vector<Eigen::Vector3d> candidates{{0.02, 0.0, 0.0}, {0.01, 0.0, 0.0}};
  EXPECT_EQ(associateCandidates(candidates, instances, 0.05), (std::vector<int>{-1, 0}));
}

TEST(InstanceAssociation, NothingIsAssociatedBeyondTheDistance) {
  EXPECT_EQ(associateCandidates({{0.06, 0.0, 0.0}}, {{0.0, 0.0, 0.0}}, 0.05),
            (std::vector<int>{-1}));
  EXPECT_TRUE(associateCandidates({}, {{0.0, 0.0, 0.0}}, 0.05).empty());
}

}  // namespace
}  // namespace vdc
