#include "view_direction_classification/geometry/visibility_crop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mug_mesh.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

TEST(VisibilityCrop, KeepsExactlyThePointsWithinTheRadiusOfAnyAnchor) {
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(1, -2, 0.5), 0.7, 0.4);
  const std::vector<Eigen::Vector3d> anchors = {{0.05, 0, 0.02}, {0.05, 0, -0.02}};
  const double radius = 0.015;
  // An organised 20 x 10 cloud of object-frame points around the anchors, in the camera frame,
  // with a NaN hole.
  Cloud cloud(20, 10);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> offset(-0.04, 0.04);
  std::vector<bool> expected(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d object_point(0.05 + offset(rng), offset(rng), offset(rng));
    double nearest = 1e9;
    for (const auto& a : anchors) nearest = std::min(nearest, (object_point - a).norm());
    expected[i] = nearest <= radius;
    const Eigen::Vector3f p = (pose * object_point).cast<float>();
    cloud[i] = pcl::PointXYZ(p.x(), p.y(), p.z());
  }
  cloud[7].x = cloud[7].y = cloud[7].z = std::numeric_limits<float>::quiet_NaN();
  expected[7] = false;

  const Cloud cropped = cropToAnchors(cloud, pose, anchors, radius);
  ASSERT_EQ(cropped.width, 20u);
  ASSERT_EQ(cropped.height, 10u);
  EXPECT_FALSE(cropped.is_dense);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ(std::isfinite(cropped[i].z), expected[i]) << "point " << i;
    if (expected[i]) {
      EXPECT_EQ(cropped[i].x, cloud[i].x);
      ++kept;
    }
  }
  EXPECT_GT(kept, 5u);
  EXPECT_LT(kept, cloud.size() - 5);
}

TEST(VisibilityCrop, RadiusIsInclusive) {
  Cloud cloud(2, 1);
  cloud[0] = pcl::PointXYZ(0.0f, 0.0f, 1.0f);
  cloud[1] = pcl::PointXYZ(0.0f, 0.0f, 1.5f);
  const Cloud cropped =
      cropToAnchors(cloud, Eigen::Isometry3d::Identity(), {Eigen::Vector3d(0, 0, 0.75)}, 0.25);
  EXPECT_TRUE(std::isfinite(cropped[0].z));
  EXPECT_FALSE(std::isfinite(cropped[1].z));
}

TEST(VisibilityCrop, SurfaceFractionCountsSamplesNearAnyAnchor) {
  SurfaceSamples surface;
  for (int i = 0; i < 100; ++i) {
    surface.points.emplace_back(0.01f * i, 0.0f, 0.0f);
    surface.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  // Anchors at 0.1 and 0.8 with radius 0.045: points 6..14 and 76..84 (9 each).
  const std::vector<Eigen::Vector3d> anchors = {{0.1, 0, 0}, {0.8, 0, 0}};
  EXPECT_NEAR(surfaceFractionNearAnchors(surface, anchors, 0.045), 0.18, 1e-12);
}

TEST(VisibilityCrop, MugSurfaceFractionGrowsWithTheRadius) {
  const MugShape shape;
  const SurfaceSamples surface = sampleSurface(makeMug(shape), 0.003, 1);
  const std::vector<Eigen::Vector3d> anchors = mugHandleAnchors(shape);
  double previous = 0.0;
  for (double radius : {0.03, 0.04, 0.05, 0.06, 0.07, 0.08}) {
    const double fraction = surfaceFractionNearAnchors(surface, anchors, radius);
    EXPECT_GT(fraction, previous);
    previous = fraction;
  }
  EXPECT_LT(previous, 0.6);
}

TEST(VisibilityCrop, BadArgumentsThrow) {
  const Cloud cloud(4, 4);
  const std::vector<Eigen::Vector3d> anchors = {Eigen::Vector3d::Zero()};
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  EXPECT_THROW(cropToAnchors(cloud, pose, {}, 0.05), Error);
  EXPECT_THROW(cropToAnchors(cloud, pose, anchors, 0.0), Error);
  EXPECT_THROW(cropToAnchors(cloud, pose, anchors, -0.05), Error);
  EXPECT_THROW(cropToAnchors(cloud, pose, {Eigen::Vector3d(std::nan(""), 0, 0)}, 0.05), Error);
  SurfaceSamples empty;
  EXPECT_THROW(surfaceFractionNearAnchors(empty, anchors, 0.05), Error);
  SurfaceSamples one;
  one.points.emplace_back(0.0f, 0.0f, 0.0f);
  one.normals.emplace_back(0.0f, 0.0f, 1.0f);
  EXPECT_THROW(surfaceFractionNearAnchors(one, {}, 0.05), Error);
  EXPECT_THROW(surfaceFractionNearAnchors(one, anchors, std::nan("")), Error);
}

}  // namespace
}  // namespace vdc
