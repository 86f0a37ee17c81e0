#include "view_direction_classification/estimation/object_tracking.h"

#include <gtest/gtest.h>

#include "support/mug_scene.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {
namespace {

using test::cameraFromWorld;
using test::kMugPosition;

pcl::PointCloud<pcl::PointXYZ> render(const Scene& scene,
                                      const Eigen::Isometry3d& camera_from_world) {
  return DepthRenderer(sceneMesh(scene)).render(camera_from_world);
}

// The mug tracked at its origin on its table (normal +z through the table top).
ObjectTrack mugTrack() {
  ObjectTrack track;
  track.centroid = kMugPosition;
  track.table = Eigen::Vector4d(0, 0, 1, -test::tableTop());
  return track;
}

SightingParameters mugSighting() {
  SightingParameters parameters;
  parameters.radius = 0.13;  // the largest centroid offset + bounding radius + 1 cm
  return parameters;
}

TEST(ObjectTracking, TheMugIsSeenWhereItIsTrackedWithoutItsTableOrTheDistractors) {
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0.3, 0.8), 0.6);
  const auto cloud = render(test::mugScene(true, true), camera_from_world);
  const ObjectSighting sighting =
      lookForTrackedObject(cloud, camera_from_world.inverse(), mugTrack(), mugSighting());
  EXPECT_EQ(sighting.status, SightingStatus::kSeen);
  // Alone the mug shows as many points (its own render, no table).
  const auto alone = render(test::mugScene(false, false), camera_from_world);
  EXPECT_NEAR(sighting.points, static_cast<int>(countValidPoints(alone)), 0.05 * sighting.points);
  EXPECT_LT((sighting.centroid - kMugPosition).norm(), 0.04);
}

TEST(ObjectTracking, AnEmptyPlaceSeenOnTheTableIsLeftAndALookElsewhereIsNotInView) {
  Scene without_mug = test::mugScene(true, true);
  // The mug stands 3 m away now; the table stays where it was.
  const Scene with_mug = without_mug;
  without_mug.object.world_from_part.translation() += Eigen::Vector3d(0, 3, 0);
  without_mug.table_size.reset();
  without_mug.distractors.push_back(
      {makeRectangleMesh(Eigen::Vector2d(1.4, 1.0)),
       test::placed(Eigen::Vector3d(kMugPosition.x(), kMugPosition.y(), test::tableTop()))});
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0.3, 0.8), 0.6);
  ObjectSighting sighting =
      lookForTrackedObject(render(without_mug, camera_from_world), camera_from_world.inverse(),
                           mugTrack(), mugSighting());
  EXPECT_EQ(sighting.status, SightingStatus::kLeft);
  EXPECT_LT(sighting.points, 50);
  EXPECT_GT(sighting.seen_through, 50);

  // Looking 1 m beside the mug: neither the mug nor its place is in the image.
  const Eigen::Isometry3d away =
      cameraFromWorld(Eigen::Vector3d(1, 0.3, 0.8), 0.6, kMugPosition + Eigen::Vector3d(0, 1, 0));
  sighting =
      lookForTrackedObject(render(with_mug, away), away.inverse(), mugTrack(), mugSighting());
  EXPECT_EQ(sighting.status, SightingStatus::kNotInView);
}

TEST(ObjectTracking, WithoutARadiusEveryFinitePointIsTheObject) {
  const Eigen::Isometry3d camera_from_world = cameraFromWorld(Eigen::Vector3d(1, 0, 0.2), 0.6);
  const auto cloud = render(test::mugScene(false, false), camera_from_world);
  ObjectTrack track;
  track.centroid = kMugPosition + Eigen::Vector3d(1, 1, 1);  // not used without a radius
  const ObjectSighting sighting =
      lookForTrackedObject(cloud, camera_from_world.inverse(), track, SightingParameters{});
  EXPECT_EQ(sighting.status, SightingStatus::kSeen);
  EXPECT_EQ(sighting.points, static_cast<int>(countValidPoints(cloud)));
}

}  // namespace
}  // namespace vdc
