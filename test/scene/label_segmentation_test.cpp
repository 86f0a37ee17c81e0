// Object candidates from a detector's label image (segmentLabels): one per label, in
// segmentScene's contract, on synthetic grids and on a rendered table scene.
#include "view_direction_classification/scene/label_segmentation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/mug_scene.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {
namespace {

// An organised width x height cloud of a wall 1 m ahead (1 cm grid) and an all-background label
// image of its size.
struct Grid {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  LabelImage labels;

  Grid(int width, int height) : cloud(width, height), labels{width, height, {}} {
    labels.labels.assign(std::size_t(width) * height, 0);
    for (int row = 0; row < height; ++row) {
      for (int column = 0; column < width; ++column) {
        cloud.at(column, row) = pcl::PointXYZ(0.01f * column, 0.01f * row, 1.0f);
      }
    }
  }

  int index(int column, int row) const { return row * labels.width + column; }

  // Labels the rectangle [column, column + w) x [row, row + h) with `value`; its indices.
  std::vector<int> label(int column, int row, int w, int h, std::uint32_t value) {
    std::vector<int> indices;
    for (int r = row; r < row + h; ++r) {
      for (int c = column; c < column + w; ++c) {
        labels.labels[std::size_t(index(c, r))] = value;
        indices.push_back(index(c, r));
      }
    }
    std::sort(indices.begin(), indices.end());
    return indices;
  }
};

// The wall is one plane: without support planes every labelled point is an object point.
SceneSegmentationParameters withoutPlanes() {
  SceneSegmentationParameters parameters;
  parameters.max_support_planes = 0;
  parameters.min_cluster_points = 20;
  return parameters;
}

TEST(LabelSegmentation, TwoLabelledInstancesGiveTwoCandidatesWithTheirPoints) {
  Grid grid(64, 48);
  const std::vector<int> cup = grid.label(5, 5, 10, 10, 1001);
  const std::vector<int> box = grid.label(30, 20, 12, 12, 2001);
  const SceneSegments segments = segmentLabels(grid.cloud, grid.labels, withoutPlanes());
  ASSERT_EQ(segments.candidates.size(), 2u) << segments.note;
  // Most points first: the box's 144, then the cup's 100.
  EXPECT_EQ(segments.candidates[0].indices, box);
  EXPECT_EQ(segments.candidates[1].indices, cup);
  EXPECT_EQ(segments.candidates[0].class_id, 2);
  EXPECT_EQ(segments.candidates[1].class_id, 1);
  EXPECT_TRUE(segments.candidates[1].centroid.isApprox(Eigen::Vector3d(0.095, 0.095, 1.0), 1e-6));
  EXPECT_GE(segments.candidates[0].extent(0), 0.11 - 1e-6);  // a flat 11 x 11 cm square
  EXPECT_NEAR(segments.candidates[0].extent(2), 0.0, 1e-6);
  EXPECT_EQ(segments.dropped_clusters, 0);
  EXPECT_TRUE(segments.planes.empty());
}

TEST(LabelSegmentation, BackgroundAndPointsWithoutDepthAreNoCandidatesPoints) {
  Grid grid(64, 48);
  std::vector<int> cup = grid.label(5, 5, 10, 10, 7);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  grid.cloud.at(6, 6).z = nan;
  grid.cloud.at(7, 7).x = nan;
  cup.erase(std::remove_if(cup.begin(), cup.end(),
                           [&](int i) { return i == grid.index(6, 6) || i == grid.index(7, 7); }),
            cup.end());
  const SceneSegments segments = segmentLabels(grid.cloud, grid.labels, withoutPlanes());
  ASSERT_EQ(segments.candidates.size(), 1u) << segments.note;
  EXPECT_EQ(segments.candidates[0].indices, cup);  // 98 points: no NaN one, no background
  EXPECT_TRUE(segments.candidates[0].centroid.allFinite());
}

TEST(LabelSegmentation, ALabelWithTooFewMeasuredPointsIsIgnored) {
  Grid grid(64, 48);
  grid.label(5, 5, 10, 10, 1001);
  grid.label(30, 30, 4, 5, 1002);  // 20 points, but one without depth
  grid.cloud.at(30, 30).z = std::numeric_limits<float>::quiet_NaN();
  const SceneSegments segments = segmentLabels(grid.cloud, grid.labels, withoutPlanes());
  ASSERT_EQ(segments.candidates.size(), 1u);
  EXPECT_EQ(segments.candidates[0].pointCount(), 100);
  EXPECT_NE(segments.note.find("min_cluster_points"), std::string::npos) << segments.note;
}

TEST(LabelSegmentation, HundredsOfLabelsAreCappedByMaxCandidatesKeepingTheLargest) {
  Grid grid(200, 150);
  SceneSegmentationParameters parameters = withoutPlanes();
  parameters.min_cluster_points = 4;
  parameters.max_candidates = 30;
  // 300 labels of 2 x 2 points, and one of 5 x 5 that must be kept first.
  std::uint32_t value = 1;
  for (int row = 0; row < 30; ++row) {
    for (int column = 0; column < 10; ++column) grid.label(3 * column, 3 * row, 2, 2, value++);
  }
  const std::vector<int> large = grid.label(100, 100, 5, 5, 5000);
  const SceneSegments segments = segmentLabels(grid.cloud, grid.labels, parameters);
  ASSERT_EQ(segments.candidates.size(), 30u);
  EXPECT_EQ(segments.candidates[0].indices, large);
  EXPECT_EQ(segments.dropped_clusters, 271);
  EXPECT_NE(segments.note.find("max_candidates"), std::string::npos) << segments.note;
}

TEST(LabelSegmentation, ALabelImageOfAnotherSizeGivesNoCandidatesAndANote) {
  Grid grid(64, 48);
  grid.label(5, 5, 10, 10, 1001);
  LabelImage wider = grid.labels;
  wider.width = 48;
  wider.height = 64;  // the same number of labels, transposed
  SceneSegments segments = segmentLabels(grid.cloud, wider, withoutPlanes());
  EXPECT_TRUE(segments.candidates.empty());
  EXPECT_NE(segments.note.find("not the cloud's size"), std::string::npos) << segments.note;
  LabelImage truncated = grid.labels;
  truncated.labels.pop_back();
  segments = segmentLabels(grid.cloud, truncated, withoutPlanes());
  EXPECT_TRUE(segments.candidates.empty());
  EXPECT_FALSE(segments.note.empty());
  // An unorganised cloud of as many points is no match for a 64 x 48 image either.
  pcl::PointCloud<pcl::PointXYZ> flat = grid.cloud;
  flat.width = static_cast<std::uint32_t>(flat.size());
  flat.height = 1;
  segments = segmentLabels(flat, grid.labels, withoutPlanes());
  EXPECT_TRUE(segments.candidates.empty());
}

TEST(LabelSegmentation, TheClassIsTheLabelValueOverTheDivisor) {
  EXPECT_EQ(labelClass(26001, 1000), 26);
  EXPECT_EQ(labelClass(999, 1000), 0);  // class 0 (Cityscapes' "unlabeled" as an instance)
  EXPECT_EQ(labelClass(7, 1), 7);
  EXPECT_EQ(labelClass(0xFFFFFFFFu, 1), 4294967295LL);  // no overflow
  Grid grid(64, 48);
  grid.label(5, 5, 10, 10, 26001);
  grid.label(30, 5, 10, 10, 26002);
  grid.label(5, 30, 10, 10, 7);
  SceneSegmentationParameters parameters = withoutPlanes();
  SceneSegments segments = segmentLabels(grid.cloud, grid.labels, parameters);
  ASSERT_EQ(segments.candidates.size(), 3u);
  std::vector<std::int64_t> classes;
  for (const SceneCandidate& candidate : segments.candidates) classes.push_back(candidate.class_id);
  std::sort(classes.begin(), classes.end());
  EXPECT_EQ(classes, (std::vector<std::int64_t>{0, 26, 26}));
  parameters.label_class_divisor = 1;
  segments = segmentLabels(grid.cloud, grid.labels, parameters);
  classes.clear();
  for (const SceneCandidate& candidate : segments.candidates) classes.push_back(candidate.class_id);
  std::sort(classes.begin(), classes.end());
  EXPECT_EQ(classes, (std::vector<std::int64_t>{7, 26001, 26002}));
  parameters.label_class_divisor = 0;
  EXPECT_THROW(segmentLabels(grid.cloud, grid.labels, parameters), Error);
}

// A detector's mask of the mug on a rendered table, grown by a few pixels as real masks are: the
// table plane is found, the mask's table points are left out, and the mug stands on the plane.
TEST(LabelSegmentation, OnATableTheMasksTablePointsAreLeftOutAndTheSupportIsFound) {
  const Eigen::Isometry3d camera_from_world =
      test::cameraFromWorld(Eigen::Vector3d(1, 0.25, 0.8).normalized(), 0.8);
  std::mt19937 rng(3);
  const pcl::PointCloud<pcl::PointXYZ> cloud =
      DepthRenderer(sceneMesh(test::mugScene(true, false)))
          .render(camera_from_world, DepthNoiseModel{}, &rng);
  LabelImage labels{static_cast<int>(cloud.width), static_cast<int>(cloud.height),
                    std::vector<std::uint32_t>(cloud.size(), 0)};
  // The mask: every point within 8 cm of the mug's axis (fixed frame) and up to 12 cm above the
  // table, which takes in a ring of the table around the mug's foot.
  const Eigen::Isometry3d world_from_camera = camera_from_world.inverse();
  int table_points_in_mask = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!std::isfinite(cloud[i].z)) continue;
    const Eigen::Vector3d p = world_from_camera * cloud[i].getVector3fMap().cast<double>();
    const Eigen::Vector3d offset = p - test::kMugPosition;
    if (offset.head<2>().norm() > 0.08 || p.z() > test::tableTop() + 0.12) continue;
    labels.labels[i] = 1001;
    if (p.z() < test::tableTop() + 0.003) ++table_points_in_mask;
  }
  ASSERT_GT(table_points_in_mask, 200);
  const SceneSegments segments = segmentLabels(cloud, labels, SceneSegmentationParameters{});
  ASSERT_EQ(segments.planes.size(), 1u) << segments.note;
  ASSERT_EQ(segments.candidates.size(), 1u) << segments.note;
  const SceneCandidate& mug = segments.candidates[0];
  EXPECT_EQ(mug.support, 0);
  EXPECT_EQ(mug.class_id, 1);
  EXPECT_TRUE(std::is_sorted(mug.indices.begin(), mug.indices.end()));
  int on_table = 0;
  for (const int i : mug.indices) {
    const Eigen::Vector3d p = world_from_camera * cloud[i].getVector3fMap().cast<double>();
    if (p.z() < test::tableTop() + 0.003) ++on_table;
  }
  EXPECT_LT(on_table, table_points_in_mask / 20) << "the mask's table points were kept";
  // Its box is the mug's (9.5 cm tall, about 12 cm across with the handle), not the table ring's.
  EXPECT_LT(mug.extent(0), 0.14);
}

}  // namespace
}  // namespace vdc
