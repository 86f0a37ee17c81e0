#include "view_direction_classification/planning/occluder_cloud.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(OccluderCloud, DoesNotHideAPointByOccluderPointsOnItOrBehindIt) {
  const std::vector<Eigen::Vector3d> surface = {{0.05, 0, 0}};
  const Eigen::Vector3d camera(0.6, 0, 0);
  EXPECT_FALSE(OccluderCloud({{0.052, 0, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_FALSE(OccluderCloud({{-0.2, 0, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_FALSE(OccluderCloud({{0.3, 0.006, 0}}, 0.005).hidden(camera, surface)[0]);
  EXPECT_TRUE(OccluderCloud({{0.3, 0.004, 0}}, 0.005).hidden(camera, surface)[0]);
}

TEST(OccluderCloud, AgreesWithTheBruteForceSegmentDistanceTest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> box(-0.1, 0.1);
  std::vector<Eigen::Vector3d> occluder_points, surface;
  for (int i = 0; i < 120; ++i) occluder_points.emplace_back(box(rng), box(rng), box(rng) + 0.2);
  for (int i = 0; i < 600; ++i) surface.emplace_back(box(rng), box(rng), box(rng));
  const double radius = 0.006;
  const OccluderCloud occluder(occluder_points, radius);
  for (const Eigen::Vector3d& camera :
       {Eigen::Vector3d(0.05, -0.1, 0.6), Eigen::Vector3d(0.3, 0.2, 0.25)}) {
    const std::vector<bool> hidden = occluder.hidden(camera, surface);
    int hidden_count = 0;
    for (std::size_t i = 0; i < surface.size(); ++i) {
      const Eigen::Vector3d to_camera = camera - surface[i];
      const Eigen::Vector3d start = surface[i] + 2.0 * radius * to_camera.normalized();
      const Eigen::Vector3d segment = camera - start;
      bool expected = false;
      for (const auto& o : occluder_points) {
        // Points closer than 2 radii to the camera plane are left out by design.
        const Eigen::Vector3d axis = -camera.normalized();
        if ((o - camera).dot(axis) <= 2.0 * radius) continue;
        const double t = std::clamp((o - start).dot(segment) / segment.squaredNorm(), 0.0, 1.0);
        if ((start + t * segment - o).norm() <= radius) expected = true;
      }
      EXPECT_EQ(hidden[i], expected) << "surface point " << i;
      hidden_count += hidden[i] ? 1 : 0;
    }
    // The scene is built so that the test exercises both outcomes.
    EXPECT_GT(hidden_count, 10);
    EXPECT_LT(hidden_count, static_cast<int>(surface.size()) - 10);
  }
}

// Found by the server_requests fuzzer: occluder points far off the viewing axis have image
// coordinates near a float's maximum, where FLANN's kd-tree split, (min + max) / 2, overflows to
// infinity, and FLANN aborted the server on an assertion (Debian's PCL keeps FLANN's asserts).
// Such points lie outside any camera's field of view and cannot hide the object; the points near
// it still do.
TEST(OccluderCloud, PointsFarOffTheViewingAxisNeitherAbortNorHide) {
  const std::vector<Eigen::Vector3d> surface = {{0.05, 0, 0}, {0.05, 0.02, 0}};
  const Eigen::Vector3d camera(0.6, 0, 0);
  // One point hides the first surface point, 19 stand aside, and 20 lie 6-8e37 m out at 0.3 m
  // depth: images of 2-2.7e38, more than the kd-tree's leaf of 15, so it splits among them.
  std::vector<Eigen::Vector3d> points = {{0.3, 0.004, 0}};
  for (int i = 0; i < 19; ++i) points.emplace_back(0.3, -0.05 - 0.001 * i, 0);
  for (int i = 0; i < 20; ++i) points.emplace_back(0.3, -6e37 - 1e36 * i, 0);
  const std::vector<bool> hidden = OccluderCloud(points, 0.005).hidden(camera, surface);
  EXPECT_TRUE(hidden[0]);
  EXPECT_FALSE(hidden[1]);
}

TEST(OccluderCloud, RejectsAnEmptyCloudANonFinitePointAndABadRadius) {
  EXPECT_THROW(OccluderCloud({}, 0.005), Error);
  EXPECT_THROW(OccluderCloud({{0, std::nan(""), 0}}, 0.005), Error);
  EXPECT_THROW(OccluderCloud({{0, 0, 0}}, 0.0), Error);
}

}  // namespace
}  // namespace vdc
