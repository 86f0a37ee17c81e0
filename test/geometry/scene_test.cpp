#include "view_direction_classification/geometry/scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"

namespace vdc {
namespace {

Eigen::Isometry3d poseAt(const Eigen::Vector3d& translation, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = translation;
  return pose;
}

TEST(PrimitiveMeshes, BoxAndCylinderAreClosedOutwardSolidsStandingOnZeroWithTheirSizes) {
  const TriangleMesh box = makeBoxMesh(Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_TRUE(checkMesh(box).watertight);
  EXPECT_NEAR(box.signedVolume(), 0.1 * 0.2 * 0.3, 1e-9);
  EXPECT_NEAR(box.bounds().min().z(), 0.0, 1e-9);
  EXPECT_NEAR(box.bounds().max().z(), 0.3, 1e-7);
  EXPECT_NEAR(box.bounds().center().x(), 0.0, 1e-9);

  const TriangleMesh cylinder = makeCylinderMesh(0.03, 0.2, 64);
  const MeshCheck check = checkMesh(cylinder);
  EXPECT_TRUE(check.watertight);
  EXPECT_EQ(check.inconsistent_edges, 0u);
  // The inscribed 64-gon's area is (64/2) sin(2 pi/64) r^2.
  EXPECT_NEAR(cylinder.signedVolume(), 32 * std::sin(2 * M_PI / 64) * 0.03 * 0.03 * 0.2, 1e-9);
  EXPECT_NEAR(cylinder.bounds().min().z(), 0.0, 1e-9);
}

// The gable-top carton is a prism across its ridge: its volume is its length times the area of
// its cross-section (walls, roof triangle, and the fin's rectangle above the slopes).
TEST(PrimitiveMeshes, CartonIsAClosedOutwardPrismWithItsRoofAndFin) {
  const double width = 0.1, depth = 0.09, height = 0.25, gable = 0.03, fin = 0.02, thick = 0.006;
  const TriangleMesh carton =
      makeCartonMesh(Eigen::Vector3d(width, depth, height), gable, fin, thick);
  const MeshCheck check = checkMesh(carton);
  EXPECT_TRUE(check.watertight);
  EXPECT_EQ(check.inconsistent_edges, 0u);
  EXPECT_EQ(check.degenerate_triangles, 0u);
  const double wall = height - gable - fin;
  // The fin stands on the slopes: above them it fills thick x fin, plus the slopes' fall over
  // its half thickness, gable * thick^2 / (2 depth).
  const double section =
      depth * wall + 0.5 * depth * gable + thick * fin + gable * thick * thick / (2.0 * depth);
  EXPECT_NEAR(carton.signedVolume(), width * section, 1e-9);
  const Eigen::AlignedBox3f bounds = carton.bounds();
  EXPECT_TRUE(bounds.min().isApprox(Eigen::Vector3f(-0.05f, -0.045f, 0.0f), 1e-6f));
  EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3f(0.05f, 0.045f, 0.25f), 1e-6f));
  // Only the fin's vertices stand above the ridge: 3 mm either side of y = 0.
  for (const Eigen::Vector3f& v : carton.vertices) {
    if (v.z() > wall + gable + 1e-6) {
      EXPECT_NEAR(std::abs(v.y()), 0.003, 1e-7);
    }
  }

  // Without a fin the roof ends in the ridge: walls, then a triangle of the gable's height.
  const TriangleMesh plain = makeCartonMesh(Eigen::Vector3d(0.095, 0.095, 0.23), 0.03);
  EXPECT_TRUE(checkMesh(plain).watertight);
  EXPECT_EQ(checkMesh(plain).inconsistent_edges, 0u);
  EXPECT_NEAR(plain.signedVolume(), 0.095 * 0.095 * (0.2 + 0.5 * 0.03), 1e-9);
  EXPECT_NEAR(plain.bounds().max().z(), 0.23, 1e-7);
  EXPECT_NEAR(plain.bounds().min().z(), 0.0, 1e-9);
}

TEST(PrimitiveMeshes, RefuseSizesThatAreNotPositiveLengths) {
  EXPECT_THROW(makeBoxMesh(Eigen::Vector3d(0.1, 0.0, 0.1)), Error);
  EXPECT_THROW(makeBoxMesh(Eigen::Vector3d(0.1, NAN, 0.1)), Error);
  EXPECT_THROW(makeCylinderMesh(-0.1, 0.1), Error);
  EXPECT_THROW(makeCylinderMesh(0.1, 0.1, 3), Error);
  EXPECT_THROW(makeRectangleMesh(Eigen::Vector2d(1.0, INFINITY)), Error);
  const Eigen::Vector3d carton(0.1, 0.1, 0.2);
  EXPECT_THROW(makeCartonMesh(carton, 0.0), Error);
  EXPECT_THROW(makeCartonMesh(carton, 0.03, -0.01), Error);
  EXPECT_THROW(makeCartonMesh(carton, 0.03, 0.02, 0.1), Error);  // as thick as the carton
  EXPECT_THROW(makeCartonMesh(carton, 0.16, 0.05), Error);       // no room for the walls
  EXPECT_THROW(makeCartonMesh(Eigen::Vector3d(0.1, NAN, 0.2), 0.03), Error);
}

TEST(Scene, TableStandsUnderTheObjectsLowestPointAndEveryPartIsPlacedInTheFixedFrame) {
  Scene scene;
  scene.object.mesh = makeMug();
  scene.object.world_from_part = poseAt(Eigen::Vector3d(0.5, -0.2, 0.8), 1.0);
  scene.table_size = Eigen::Vector2d(1.0, 0.6);
  scene.distractors.push_back({makeBoxMesh(Eigen::Vector3d(0.05, 0.05, 0.1)),
                               poseAt(Eigen::Vector3d(0.7, -0.2, 0.8 - 0.0475))});
  // The upright mug's bottom is 9.5 / 2 cm below its origin.
  EXPECT_NEAR(tableHeight(scene), 0.8 - 0.0475, 1e-6);
  const TriangleMesh mesh = sceneMesh(scene);
  EXPECT_EQ(mesh.triangles.size(), scene.object.mesh.triangles.size() + 2 + 12);
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  EXPECT_NEAR(bounds.min().x(), 0.0, 1e-6);  // the table spans 0.5 +- 0.5 in x
  EXPECT_NEAR(bounds.max().y(), 0.1, 1e-6);  // and -0.2 +- 0.3 in y
  EXPECT_NEAR(bounds.min().z(), 0.8 - 0.0475, 1e-6);

  // A camera 0.6 m above the table looking straight down sees the table at its height around
  // the mug and the box's top 10 cm above it.
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  world_from_camera.translation() = Eigen::Vector3d(0.6, -0.2, 0.8 + 0.6);
  const DepthRenderer renderer(mesh);
  const auto cloud = renderer.render(world_from_camera.inverse());
  int table = 0, box_top = 0;
  for (const auto& p : cloud.points) {
    if (!std::isfinite(p.z)) continue;
    const double z = (world_from_camera * p.getVector3fMap().cast<double>()).z();
    if (std::abs(z - (0.8 - 0.0475)) < 1e-4) ++table;
    if (std::abs(z - (0.8 - 0.0475 + 0.1)) < 1e-4) ++box_top;
  }
  EXPECT_GT(table, 100000);
  EXPECT_GT(box_top, 1000);  // 5 x 5 cm at 0.5 m: ~ 2750 pixels
}

// The simulated camera keeps the table where it was placed while the object moves: the table is
// a part of its own, the same one sceneMesh puts under the object.
TEST(Scene, TheTableAsAPartIsSceneMeshsTableAndPartsMeshJoinsPartsInTheirPoses) {
  Scene scene;
  scene.object = {makeMug(), poseAt(Eigen::Vector3d(0.5, -0.2, 0.8), 1.0)};
  scene.table_size = Eigen::Vector2d(1.0, 0.6);
  const ScenePart table = tablePart(scene);
  EXPECT_TRUE(
      table.world_from_part.translation().isApprox(Eigen::Vector3d(0.5, -0.2, 0.8 - 0.0475), 1e-6));
  const TriangleMesh whole = sceneMesh(scene);
  const TriangleMesh joined = partsMesh({scene.object, table});
  ASSERT_EQ(joined.vertices.size(), whole.vertices.size());
  EXPECT_EQ(joined.triangles, whole.triangles);
  for (std::size_t i = 0; i < whole.vertices.size(); ++i) {
    EXPECT_TRUE(joined.vertices[i].isApprox(whole.vertices[i])) << i;
  }
  // The object moved 30 cm: the table part stays put.
  ScenePart moved = scene.object;
  moved.world_from_part.translation().x() += 0.3;
  EXPECT_NEAR(partsMesh({moved, table}).bounds().min().x(), 0.0, 1e-6);
  EXPECT_TRUE(partsMesh({}).vertices.empty());

  Scene no_table = scene;
  no_table.table_size.reset();
  EXPECT_THROW(tablePart(no_table), Error);
  ScenePart not_finite = scene.object;
  not_finite.world_from_part.translation().x() = std::nan("");
  EXPECT_THROW(partsMesh({not_finite}), Error);
}

TEST(Scene, DistractorDescriptionsNameBoxesCylindersOrMeshFiles) {
  EXPECT_NEAR(distractorMesh("box 0.1 0.2 0.3").signedVolume(), 0.006, 1e-9);
  EXPECT_NEAR(distractorMesh("cylinder 0.03 0.2").bounds().max().z(), 0.2, 1e-7);
  // A carton's fin may be left out.
  EXPECT_NEAR(distractorMesh("carton 0.1 0.1 0.2 0.04").signedVolume(),
              0.1 * 0.1 * (0.16 + 0.5 * 0.04), 1e-9);
  EXPECT_NEAR(distractorMesh("carton 0.1 0.1 0.25 0.03 0.02").bounds().max().z(), 0.25, 1e-7);
  EXPECT_THROW(distractorMesh("carton 0.1 0.1 0.2"), Error);
  EXPECT_THROW(distractorMesh("carton 0.1 0.1 0.2 0.03 0.01 0.5"), Error);
  EXPECT_THROW(distractorMesh("carton 0.1 0.1 0.2 0.3"), Error);
  EXPECT_THROW(distractorMesh("box 0.1 0.2"), Error);
  EXPECT_THROW(distractorMesh("box 0.1 0.2 0.3 0.4"), Error);
  EXPECT_THROW(distractorMesh("cylinder 0.03 tall"), Error);
  EXPECT_THROW(distractorMesh("box 0.1 -0.2 0.3"), Error);
  EXPECT_THROW(distractorMesh(""), Error);
  EXPECT_THROW(distractorMesh("/no/such/mesh.ply"), Error);
}

}  // namespace
}  // namespace vdc
