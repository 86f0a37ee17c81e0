#include "view_direction_classification/estimation/tabletop_segmentation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/mug_scene.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/estimation/object_segmentation.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc {
namespace {

using test::cameraFromWorld;
using test::kMugPosition;
using test::mugScene;
using test::placed;
using test::tableTop;

pcl::PointCloud<pcl::PointXYZ> render(const Scene& scene,
                                      const Eigen::Isometry3d& camera_from_world) {
  return DepthRenderer(sceneMesh(scene)).render(camera_from_world);
}

ObjectExtent mugExtent() {
  const Eigen::AlignedBox3f bounds = makeMug().bounds();
  return ObjectExtent::of(
      Eigen::AlignedBox3d(bounds.min().cast<double>(), bounds.max().cast<double>()));
}

pcl::PointCloud<pcl::PointXYZ> finitePoints(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  pcl::PointCloud<pcl::PointXYZ> finite;
  for (const auto& p : cloud.points) {
    if (std::isfinite(p.z)) finite.push_back(p);
  }
  return finite;
}

// How many of the chosen cluster's points lie on the mug: within its bounding sphere (9.4 cm
// from its origin, the handle included).
int pointsOnTheMug(const pcl::PointCloud<pcl::PointXYZ>& points, const std::vector<int>& indices,
                   const Eigen::Isometry3d& camera_from_world) {
  const Eigen::Vector3d mug = camera_from_world * kMugPosition;
  int on = 0;
  for (const int i : indices)
    on += (points[i].getVector3fMap().cast<double>() - mug).norm() < 0.095;
  return on;
}

TEST(ObjectExtent, SortsTheBoxSidesLargestFirst) {
  const ObjectExtent extent = ObjectExtent::of(Eigen::AlignedBox3d(
      Eigen::Vector3d(-0.04, -0.04, -0.0475), Eigen::Vector3d(0.071, 0.04, 0.0475)));
  EXPECT_NEAR(extent.sizes(0), 0.111, 1e-12);
  EXPECT_NEAR(extent.sizes(1), 0.095, 1e-12);
  EXPECT_NEAR(extent.sizes(2), 0.08, 1e-12);
  EXPECT_THROW(ObjectExtent::of(Eigen::AlignedBox3d()), Error);
}

TEST(TabletopSegmentation, FindsTheMugAmongDistractorsThatDoNotFitItsSize) {
  for (const Eigen::Vector3d& direction :
       {Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(-0.3, 1, 0.8), Eigen::Vector3d(0.2, -1, 0.5)}) {
    const Eigen::Isometry3d camera_from_world = cameraFromWorld(direction, 0.6);
    const auto points = finitePoints(render(mugScene(true, true), camera_from_world));
    const TabletopResult result = segmentTabletop(points, {}, mugExtent(), std::nullopt);
    ASSERT_GE(result.chosen, 0) << result.failure;
    ASSERT_TRUE(result.table.has_value());
    // The table's normal points up, towards the camera, and the camera is 0.6 m from the mug.
    const Eigen::Vector3d up = camera_from_world.linear() * Eigen::Vector3d::UnitZ();
    EXPECT_GT(result.table->head<3>().dot(up), 0.999);
    const auto& mug = result.clusters[static_cast<std::size_t>(result.chosen)];
    EXPECT_EQ(pointsOnTheMug(points, mug.indices, camera_from_world),
              static_cast<int>(mug.indices.size()));
    EXPECT_GT(mug.indices.size(), 3000u);
    int unfit = 0;
    for (const auto& cluster : result.clusters) unfit += !cluster.fits;
    EXPECT_GE(unfit, 2) << "the distractors in view were not told apart by their size";
  }
}

TEST(TabletopSegmentation, AnEmptyTableOrOnlyWrongSizedObjectsGiveAReason) {
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0, 1), 0.6);
  // The table alone (as the scene's object) where the mug stood.
  Scene table_only;
  table_only.object = {makeRectangleMesh(Eigen::Vector2d(1.4, 1.0)),
                       placed(Eigen::Vector3d(kMugPosition.x(), kMugPosition.y(), tableTop()))};
  TabletopResult result = segmentTabletop(finitePoints(render(table_only, camera_from_world)), {},
                                          mugExtent(), std::nullopt);
  EXPECT_EQ(result.chosen, -1);
  EXPECT_NE(result.failure.find("nothing stands on the table"), std::string::npos)
      << result.failure;

  Scene wrong_size = table_only;
  wrong_size.distractors.push_back(
      {makeCylinderMesh(0.03, 0.25),
       placed(Eigen::Vector3d(kMugPosition.x(), kMugPosition.y(), tableTop()))});
  result = segmentTabletop(finitePoints(render(wrong_size, camera_from_world)), {}, mugExtent(),
                           std::nullopt);
  EXPECT_EQ(result.chosen, -1);
  EXPECT_NE(result.failure.find("fits the model's size"), std::string::npos) << result.failure;
}

TEST(TabletopSegmentation, TakesTheFittingClusterNearestToWhereTheObjectWas) {
  Scene two_mugs = mugScene(true, false);
  two_mugs.distractors.push_back({makeMug(), placed(kMugPosition + Eigen::Vector3d(0, 0.25, 0))});
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0.1, 0.9), 0.7);
  const auto points = finitePoints(render(two_mugs, camera_from_world));
  for (const Eigen::Vector3d& expected :
       {kMugPosition, Eigen::Vector3d(kMugPosition + Eigen::Vector3d(0, 0.25, 0))}) {
    const Eigen::Vector3d in_camera = camera_from_world * expected;
    const TabletopResult result = segmentTabletop(points, {}, mugExtent(), in_camera);
    ASSERT_GE(result.chosen, 0) << result.failure;
    EXPECT_LT(
        (result.clusters[static_cast<std::size_t>(result.chosen)].centroid - in_camera).norm(),
        0.05);
  }
}

TEST(TabletopSegmentation, WithoutATableTheMugsOwnBottomIsNotTakenForOne) {
  // From below the mug's closed bottom is a plane holding much of the view; it is smaller than
  // the mug's diagonal, so nothing is removed and the whole mug is the object.
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(0.3, 0.1, -1), 0.6);
  const auto points = finitePoints(render(mugScene(false, false), camera_from_world));
  const TabletopResult result = segmentTabletop(points, {}, mugExtent(), std::nullopt);
  ASSERT_GE(result.chosen, 0) << result.failure;
  EXPECT_FALSE(result.table.has_value());
  EXPECT_EQ(result.clusters[static_cast<std::size_t>(result.chosen)].indices.size(), points.size());
}

TEST(TabletopSegmentation, SegmentObjectKeepsTheIndicesIntoTheOrganisedCloud) {
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0, 1), 0.6);
  const auto cloud = render(mugScene(true, true), camera_from_world);
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kTabletop;
  SegmentationContext context;
  context.extent = mugExtent();
  const ObjectSegment object = segmentObject(cloud, parameters, context);
  ASSERT_TRUE(object.failure.empty()) << object.failure;
  ASSERT_EQ(object.indices.size(), object.points.size());
  for (std::size_t k = 0; k < object.indices.size(); k += 97) {
    EXPECT_EQ(object.points[k].getVector3fMap(), cloud[object.indices[k]].getVector3fMap());
  }
  EXPECT_EQ(pointsOnTheMug(cloud, object.indices, camera_from_world),
            static_cast<int>(object.indices.size()));
}

TEST(TabletopSegmentation, AMugCutByTheImageBorderIsRefused) {
  // The camera looks 25 cm beside the mug: the mug sits across the image's left or right edge.
  const Eigen::Vector3d beside = kMugPosition + Eigen::Vector3d(0, 0.3, 0);
  const Eigen::Isometry3d camera_from_world =
      cameraFromWorld(Eigen::Vector3d(1, 0, 0.6), 0.5, beside);
  const auto cloud = render(mugScene(true, false), camera_from_world);
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kTabletop;
  parameters.extent_tolerance = 0.9;  // even a small part of the mug fits
  SegmentationContext context;
  context.extent = mugExtent();
  const ObjectSegment object = segmentObject(cloud, parameters, context);
  EXPECT_NE(object.failure.find("image border"), std::string::npos) << object.failure;
}

}  // namespace
}  // namespace vdc
