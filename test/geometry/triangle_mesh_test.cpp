#include "view_direction_classification/geometry/triangle_mesh.h"

#include <gtest/gtest.h>

#include "support/geometry_test_meshes.h"

namespace vdc {
namespace {

TEST(TriangleMesh, AreaOfBoxIsSumOfItsFaces) {
  const TriangleMesh box = test::makeBox({0.1f, 0.2f, 0.3f});
  const double expected = 2.0 * (0.2 * 0.4 + 0.2 * 0.6 + 0.4 * 0.6);
  EXPECT_NEAR(box.area(), expected, 1e-7);
}

TEST(TriangleMesh, BoundsEncloseExactlyTheVertices) {
  const Eigen::AlignedBox3f box = test::makeBox({0.1f, 0.2f, 0.3f}).bounds();
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector3f(-0.1f, -0.2f, -0.3f)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector3f(0.1f, 0.2f, 0.3f)));
  EXPECT_TRUE(TriangleMesh().bounds().isEmpty());
}

TEST(TriangleMesh, SignedVolumeOfOutwardBoxIsPositiveAndFlipsWithWinding) {
  TriangleMesh box = test::makeBox({0.1f, 0.2f, 0.3f});
  EXPECT_NEAR(box.signedVolume(), 0.2 * 0.4 * 0.6, 1e-7);
  for (auto& tri : box.triangles) std::swap(tri[1], tri[2]);
  EXPECT_NEAR(box.signedVolume(), -0.2 * 0.4 * 0.6, 1e-7);
}

TEST(TriangleMesh, TriangleNormalIsUnitAndFollowsCounterClockwiseOrder) {
  const TriangleMesh square = test::makeSquare(0.2f, 0.5f);
  EXPECT_TRUE(square.triangleNormal(0).isApprox(Eigen::Vector3f::UnitZ()));
  EXPECT_NEAR(square.triangleArea(1), 0.02, 1e-8);
  TriangleMesh degenerate;
  degenerate.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  degenerate.triangles = {{0, 1, 2}};
  EXPECT_EQ(degenerate.triangleNormal(0), Eigen::Vector3f::Zero());
}

TEST(TriangleMesh, AppendReindexesTheAppendedTriangles) {
  TriangleMesh mesh = test::makeSquare(1.0f, 0.0f);
  mesh.append(test::makeSquare(1.0f, 1.0f));
  ASSERT_EQ(mesh.vertices.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.triangles[2], Eigen::Vector3i(4, 5, 6));
  EXPECT_NEAR(mesh.area(), 2.0, 1e-6);
}

}  // namespace
}  // namespace vdc
