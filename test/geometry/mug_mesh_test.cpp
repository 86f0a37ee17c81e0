#include "view_direction_classification/geometry/mug_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"

namespace vdc {
namespace {

TEST(MugMesh, IsWatertightConsistentlyOrientedAndFreeOfDegenerateTriangles) {
  const MeshCheck check = checkMesh(makeMug());
  EXPECT_TRUE(check.watertight);
  EXPECT_EQ(check.boundary_edges, 0u);
  EXPECT_EQ(check.non_manifold_edges, 0u);
  EXPECT_EQ(check.inconsistent_edges, 0u);
  EXPECT_EQ(check.degenerate_triangles, 0u);
}

TEST(MugMesh, HasAModerateTriangleCount) {
  const std::size_t triangles = makeMug().triangles.size();
  EXPECT_GT(triangles, 1000u);
  EXPECT_LT(triangles, 6000u);
}

TEST(MugMesh, SilhouetteOfDefaultSegmentsLooksRoundAtTrainingDistance) {
  // Largest gap between the polygon and the circle, in pixels at 0.6 m with f = 525.
  const MugShape shape;
  const double sagitta = shape.outer_radius * (1.0 - std::cos(M_PI / shape.segments));
  EXPECT_LT(525.0 * sagitta / 0.6, 0.2);
}

TEST(MugMesh, BodyStaysWithinItsStatedDimensions) {
  const MugShape shape;
  const TriangleMesh mug = makeMug(shape);
  const Eigen::AlignedBox3f box = mug.bounds();
  EXPECT_NEAR(box.min().z(), -shape.height / 2, 1e-6);
  EXPECT_NEAR(box.max().z(), shape.height / 2, 1e-6);
  EXPECT_NEAR(box.min().x(), -shape.outer_radius, 1e-6);
  EXPECT_NEAR(box.max().y(), shape.outer_radius, 1e-6);
  EXPECT_NEAR(box.min().y(), -shape.outer_radius, 1e-6);
  for (const auto& v : mug.vertices) {
    EXPECT_LE(std::hypot(v.y(), std::min(v.x(), 0.0f)), shape.outer_radius + 1e-6);
  }
}

TEST(MugMesh, EnclosedVolumeMatchesBodyPlusHandleSoAllShellsFaceOutwards) {
  const MugShape shape;
  const double n = shape.segments;
  auto polygon_area = [n](double r) { return 0.5 * n * r * r * std::sin(2.0 * M_PI / n); };
  const double body = polygon_area(shape.outer_radius) * shape.height -
                      polygon_area(shape.outer_radius - shape.wall) * (shape.height - shape.bottom);
  // Tube volume: cross-section times the centre line's length (half an ellipse, Ramanujan).
  const double a = shape.handle_reach, b = shape.handle_span / 2;
  const double h = std::pow(a - b, 2) / std::pow(a + b, 2);
  const double half_ellipse = 0.5 * M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
  const double handle = M_PI * std::pow(shape.handle_tube_radius, 2) * half_ellipse;
  // A flipped handle would be off by twice its volume, about 20 % of the total.
  EXPECT_NEAR(makeMug(shape).signedVolume(), body + handle, 0.02 * (body + handle));
}

TEST(MugMesh, HandleSticksOutOnPositiveXOnly) {
  const MugShape shape;
  const TriangleMesh mug = makeMug(shape);
  const double expected_reach =
      shape.outer_radius - shape.wall / 2 + shape.handle_reach + shape.handle_tube_radius;
  EXPECT_NEAR(mug.bounds().max().x(), expected_reach, 1e-4);
  for (const auto& v : mug.vertices) {
    const double radius = std::hypot(v.x(), v.y());
    if (radius > shape.outer_radius + 1e-6) {
      EXPECT_GT(v.x(), 0.0f);
      EXPECT_LE(std::abs(v.y()), shape.handle_tube_radius + 1e-6);
    }
  }
}

TEST(MugMesh, IsMirrorSymmetricInY) {
  const TriangleMesh mug = makeMug();
  std::map<std::tuple<long, long, long>, int> positions;
  auto key = [](float x, float y, float z) {
    return std::make_tuple(std::lround(x * 1e6), std::lround(y * 1e6), std::lround(z * 1e6));
  };
  for (const auto& v : mug.vertices) positions[key(v.x(), v.y(), v.z())]++;
  for (const auto& v : mug.vertices) {
    EXPECT_TRUE(positions.count(key(v.x(), -v.y(), v.z()))) << v.transpose();
  }
}

TEST(MugMesh, InsideIsOpenAtTheTopAndClosedAtTheBottom) {
  const MugShape shape;
  const TriangleMesh mug = makeMug(shape);
  // A ray down the axis from above first meets the inner bottom, a ray up from below the outer
  // bottom: both surfaces exist and nothing covers the opening.
  double highest_on_axis = -1.0, lowest_on_axis = 1.0;
  for (const auto& v : mug.vertices) {
    if (std::hypot(v.x(), v.y()) < 1e-7) {
      highest_on_axis = std::max<double>(highest_on_axis, v.z());
      lowest_on_axis = std::min<double>(lowest_on_axis, v.z());
    }
  }
  EXPECT_NEAR(highest_on_axis, -shape.height / 2 + shape.bottom, 1e-6);
  EXPECT_NEAR(lowest_on_axis, -shape.height / 2, 1e-6);
}

TEST(MugMesh, HandleAnchorsLieOnTheHandleSurfaceUpperThenLower) {
  const MugShape shape;
  const TriangleMesh mug = makeMug(shape);
  const std::vector<Eigen::Vector3d> anchors = mugHandleAnchors(shape);
  ASSERT_EQ(anchors.size(), 2u);
  EXPECT_GT(anchors[0].z(), 0.01);
  EXPECT_LT(anchors[1].z(), -0.01);
  for (const auto& anchor : anchors) {
    EXPECT_GT(anchor.x(), shape.outer_radius + shape.handle_tube_radius);
    EXPECT_NEAR(anchor.y(), 0.0, 1e-12);
    // On the polygonal tube: within its sagitta of the surface.
    EXPECT_LT(test::nearestTriangle(mug, anchor).second, 5e-4);
  }
}

TEST(MugMesh, ImpossibleShapesAreRefused) {
  MugShape thick_wall;
  thick_wall.wall = 0.05;
  EXPECT_THROW(makeMug(thick_wall), Error);
  MugShape fat_handle;
  fat_handle.handle_tube_radius = 0.02;
  EXPECT_THROW(makeMug(fat_handle), Error);
  MugShape tall_handle;
  tall_handle.handle_span = 0.09;
  EXPECT_THROW(makeMug(tall_handle), Error);
  MugShape coarse;
  coarse.segments = 3;
  EXPECT_THROW(makeMug(coarse), Error);
  MugShape negative;
  negative.height = -0.1;
  EXPECT_THROW(makeMug(negative), Error);
  EXPECT_THROW(mugHandleAnchors(negative), Error);
}

}  // namespace
}  // namespace vdc
