#include "view_direction_classification/geometry/mesh_check.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

bool anyContains(const std::vector<std::string>& lines, const std::string& word) {
  for (const auto& line : lines) {
    if (line.find(word) != std::string::npos) return true;
  }
  return false;
}

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(MeshCheck, ClosedBoxIsWatertightWithoutWarnings) {
  const MeshCheck check = checkMesh(test::makeBox({0.05f, 0.05f, 0.05f}));
  EXPECT_TRUE(check.watertight);
  EXPECT_EQ(check.boundary_edges, 0u);
  EXPECT_EQ(check.non_manifold_edges, 0u);
  EXPECT_EQ(check.degenerate_triangles, 0u);
  EXPECT_EQ(check.inconsistent_edges, 0u);
  EXPECT_NEAR(check.largest_extent, 0.1, 1e-7);
  EXPECT_TRUE(check.warnings.empty());
}

TEST(MeshCheck, MissingTriangleLeavesThreeBoundaryEdgesAndAnOpenWarning) {
  TriangleMesh box = test::makeBox({0.05f, 0.05f, 0.05f});
  box.triangles.pop_back();
  const MeshCheck check = checkMesh(box);
  EXPECT_FALSE(check.watertight);
  EXPECT_EQ(check.boundary_edges, 3u);
  EXPECT_TRUE(anyContains(check.warnings, "open"));
}

TEST(MeshCheck, EdgeSharedByThreeTrianglesIsNonManifold) {
  TriangleMesh fan;
  fan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshCheck check = checkMesh(fan);
  EXPECT_EQ(check.non_manifold_edges, 1u);
  EXPECT_FALSE(check.watertight);
  EXPECT_TRUE(anyContains(check.warnings, "non-manifold"));
}

TEST(MeshCheck, FlippedTriangleIsReportedAsInconsistentlyOriented) {
  TriangleMesh box = test::makeBox({0.05f, 0.05f, 0.05f});
  std::swap(box.triangles[0][1], box.triangles[0][2]);
  const MeshCheck check = checkMesh(box);
  EXPECT_TRUE(check.watertight);  // topology is still closed
  EXPECT_EQ(check.inconsistent_edges, 3u);
  EXPECT_TRUE(anyContains(check.warnings, "oriented"));
}

TEST(MeshCheck, CollinearAndRepeatedVertexTrianglesAreDegenerate) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 0, 3}, {0, 1, 3}};
  EXPECT_EQ(checkMesh(mesh).degenerate_triangles, 2u);
}

TEST(MeshCheck, OutOfRangeIndexOrNonFiniteVertexThrows) {
  TriangleMesh mesh = test::makeSquare(1.0f, 0.0f);
  mesh.triangles.emplace_back(0, 1, 7);
  EXPECT_NE(messageOf([&] { checkMesh(mesh); }).find("vertex 7"), std::string::npos);
  TriangleMesh nan_mesh = test::makeSquare(1.0f, 0.0f);
  nan_mesh.vertices[2].x() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(checkMesh(nan_mesh), Error);
}

TEST(ValidateObjectMesh, MetreScaleClosedMeshPassesWithoutWarnings) {
  EXPECT_TRUE(validateObjectMesh(test::makeBox({0.05f, 0.05f, 0.05f}), "box.ply").empty());
}

TEST(ValidateObjectMesh, MillimetreScaleMeshIsRefusedWithAHint) {
  const std::string message = messageOf([] {
    validateObjectMesh(test::makeBox({50.0f, 50.0f, 50.0f}), "mug_mm.stl");
  });
  EXPECT_NE(message.find("mug_mm.stl"), std::string::npos);
  EXPECT_NE(message.find("millimetres"), std::string::npos);
}

TEST(ValidateObjectMesh, TinyMeshIsRefused) {
  const std::string message = messageOf([] {
    validateObjectMesh(test::makeBox({0.001f, 0.001f, 0.001f}), "tiny.obj");
  });
  EXPECT_NE(message.find("tiny.obj"), std::string::npos);
  EXPECT_NE(message.find("metres"), std::string::npos);
}

TEST(ValidateObjectMesh, EmptyMeshIsRefusedNamingIt) {
  const std::string message = messageOf([] { validateObjectMesh(TriangleMesh(), "empty.off"); });
  EXPECT_NE(message.find("empty.off"), std::string::npos);
  EXPECT_NE(message.find("no triangles"), std::string::npos);
}

TEST(ValidateObjectMesh, InvalidIndicesAreRefusedNamingTheMesh) {
  TriangleMesh mesh = test::makeBox({0.05f, 0.05f, 0.05f});
  mesh.triangles[3][1] = -1;
  EXPECT_NE(messageOf([&] { validateObjectMesh(mesh, "broken.ply"); }).find("broken.ply"),
            std::string::npos);
}

TEST(ValidateObjectMesh, OpenMeshIsUsableButWarnsNamingIt) {
  TriangleMesh box = test::makeBox({0.05f, 0.05f, 0.05f});
  box.triangles.resize(10);
  const std::vector<std::string> warnings = validateObjectMesh(box, "open_box.ply");
  ASSERT_FALSE(warnings.empty());
  EXPECT_TRUE(anyContains(warnings, "open_box.ply"));
  EXPECT_TRUE(anyContains(warnings, "open"));
}

}  // namespace
}  // namespace vdc
