#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

#include "visible_part.h"

namespace vdc {
namespace {

// A disc of radius 5 cm in the z = 0 plane, sampled every 2 mm: a visible part.
std::vector<Eigen::Vector3d> disc() {
  std::vector<Eigen::Vector3d> points;
  for (double x = -0.05; x <= 0.05; x += 0.002) {
    for (double y = -0.05; y <= 0.05; y += 0.002) {
      if (std::hypot(x, y) <= 0.05) points.emplace_back(x + 0.3, y, 0.0);
    }
  }
  return points;
}

TEST(PlacementAnchors, AWholeViewIsPlacedAtTheVisiblePartsCentroidOnly) {
  const std::vector<Eigen::Vector3d> visible = disc();
  const std::vector<Eigen::Vector3d> anchors =
      placementAnchors(visible, rmsRadius(visible), 0.9, 4);
  ASSERT_EQ(anchors.size(), 1u);
  EXPECT_LT((anchors.front() - Eigen::Vector3d(0.3, 0.0, 0.0)).norm(), 1e-3);
}

TEST(PlacementAnchors, APieceIsAlsoPlacedOnPatchesSpreadOverTheVisiblePart) {
  const std::vector<Eigen::Vector3d> visible = disc();
  // A piece a quarter of the disc's radius across.
  const double piece_rms = 0.25 * rmsRadius(visible);
  const std::vector<Eigen::Vector3d> anchors = placementAnchors(visible, piece_rms, 0.9, 4);
  ASSERT_EQ(anchors.size(), 5u);
  const Eigen::Vector3d centre(0.3, 0.0, 0.0);
  for (std::size_t i = 1; i < anchors.size(); ++i) {
    // Each patch lies on the disc, towards its rim, and apart from the others.
    EXPECT_LT((anchors[i] - centre).norm(), 0.05);
    EXPECT_GT((anchors[i] - centre).norm(), 0.025);
    for (std::size_t j = 1; j < i; ++j) EXPECT_GT((anchors[i] - anchors[j]).norm(), 0.03);
  }
  // No patches asked for: the centroid alone.
  EXPECT_EQ(placementAnchors(visible, piece_rms, 0.9, 0).size(), 1u);
}

TEST(PlacementAnchors, NothingVisibleGivesNoAnchor) {
  EXPECT_TRUE(placementAnchors({}, 0.01, 0.9, 4).empty());
  EXPECT_EQ(rmsRadius({}), 0.0);
}

}  // namespace
}  // namespace vdc
