// Which unions of candidates the scene layer tries as one object: the candidates beside each
// other in the image, in front or behind, with the clusters of the ones behind.
#include "piece_groups.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vdc {
namespace {

// A square patch of points facing the camera: rows x columns at `spacing` [m], from (x0, y0) at
// depth z, appended to cloud and returned as a candidate of `cluster`.
SceneCandidate patch(pcl::PointCloud<pcl::PointXYZ>* cloud, double x0, double y0, double z,
                     int rows, int columns, int cluster) {
  SceneCandidate candidate;
  const double spacing = 0.002;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      candidate.indices.push_back(static_cast<int>(cloud->size()));
      cloud->push_back(pcl::PointXYZ(static_cast<float>(x0 + c * spacing),
                                     static_cast<float>(y0 + r * spacing), static_cast<float>(z)));
    }
  }
  candidate.cluster = cluster;
  return candidate;
}

std::vector<const SceneCandidate*> pointers(const std::vector<SceneCandidate>& candidates) {
  std::vector<const SceneCandidate*> result;
  for (const SceneCandidate& candidate : candidates) result.push_back(&candidate);
  return result;
}

std::size_t points(const std::vector<SceneCandidate>& candidates,
                   const std::vector<std::size_t>& group) {
  std::size_t total = 0;
  for (std::size_t k : group) total += candidates[k].indices.size();
  return total;
}

bool contains(const std::vector<std::vector<std::size_t>>& groups,
              const std::vector<std::size_t>& group) {
  return std::find(groups.begin(), groups.end(), group) != groups.end();
}

TEST(AdjacentCandidateGroups, ANearPartAndThePartItHidesAreAGroupAcrossTheDepthJump) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<SceneCandidate> candidates;
  // A flange's face at 0.80 m; right of its edge in the image, 6 cm behind, the core (cluster
  // 1); far to the side, another object.
  candidates.push_back(patch(&cloud, 0.0, 0.0, 0.80, 20, 20, 0));
  candidates.push_back(patch(&cloud, 0.0425, 0.0, 0.86, 20, 20, 1));
  candidates.push_back(patch(&cloud, 0.30, 0.0, 0.80, 20, 20, 2));
  const auto groups = adjacentCandidateGroups(cloud, pointers(candidates), 0.01);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups.front(), (std::vector<std::size_t>{0, 1}));
}

TEST(AdjacentCandidateGroups, APartBesideAPieceIsAlsoTriedWithThatPiecesWholeCluster) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<SceneCandidate> candidates;
  // The near flange (cluster 0) beside the core; the core and the far flange are cluster 1, and
  // the far flange is not beside the near one in the image.
  candidates.push_back(patch(&cloud, 0.0, 0.0, 0.80, 30, 30, 0));
  candidates.push_back(patch(&cloud, 0.0625, 0.0, 0.86, 30, 10, 1));
  candidates.push_back(patch(&cloud, 0.0825, 0.0, 0.86, 30, 30, 1));
  const auto groups = adjacentCandidateGroups(cloud, pointers(candidates), 0.01);
  EXPECT_TRUE(contains(groups, {0, 1}));
  EXPECT_TRUE(contains(groups, {0, 1, 2})) << "the near part with the core's whole cluster";
  EXPECT_FALSE(contains(groups, {0, 2})) << "the far flange is not beside the near one";
  // The groups across the two clusters, then those within one; each kind fewest points first.
  const auto across = [&](const std::vector<std::size_t>& group) {
    return std::any_of(group.begin(), group.end(),
                       [&](std::size_t k) { return candidates[k].cluster == 0; }) &&
           std::any_of(group.begin(), group.end(),
                       [&](std::size_t k) { return candidates[k].cluster == 1; });
  };
  EXPECT_TRUE(across(groups.front()));
  EXPECT_FALSE(across(groups.back())) << "the core and the far flange, within cluster 1";
  for (std::size_t g = 1; g < groups.size(); ++g) {
    if (across(groups[g - 1]) != across(groups[g])) continue;
    EXPECT_LE(points(candidates, groups[g - 1]), points(candidates, groups[g]));
  }
}

TEST(AdjacentCandidateGroups, TwoClustersBesideEachOtherAreTriedWholeBeforePairsWithinOne) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<SceneCandidate> candidates;
  // An elephant's head and trunk (cluster 0, two pieces) in front of its body (cluster 1, two
  // pieces), 6 cm behind; the head's right piece is beside the body's left one in the image.
  candidates.push_back(patch(&cloud, 0.0, 0.0, 0.80, 10, 10, 0));
  candidates.push_back(patch(&cloud, 0.0225, 0.0, 0.80, 10, 10, 0));
  candidates.push_back(patch(&cloud, 0.0475, 0.0, 0.86, 10, 10, 1));
  candidates.push_back(patch(&cloud, 0.0700, 0.0, 0.86, 10, 10, 1));
  const auto groups = adjacentCandidateGroups(cloud, pointers(candidates), 0.01);
  const auto whole = std::find(groups.begin(), groups.end(), std::vector<std::size_t>{0, 1, 2, 3});
  ASSERT_NE(whole, groups.end()) << "both clusters whole";
  const auto within = std::find(groups.begin(), groups.end(), std::vector<std::size_t>{0, 1});
  ASSERT_NE(within, groups.end()) << "the head's two pieces";
  EXPECT_LT(whole, within) << "the groups across clusters come first, though larger";
}

TEST(AdjacentCandidateGroups, CandidatesApartInTheImageOrEmptyFormNoGroup) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<SceneCandidate> candidates;
  candidates.push_back(patch(&cloud, 0.0, 0.0, 0.80, 10, 10, 0));
  candidates.push_back(patch(&cloud, 0.05, 0.0, 0.80, 10, 10, 1));  // a 3 cm gap
  candidates.push_back(SceneCandidate{});                           // no points at all
  cloud.push_back(pcl::PointXYZ(std::nanf(""), 0.0f, 0.0f));
  candidates.back().indices.push_back(static_cast<int>(cloud.size()) - 1);
  EXPECT_TRUE(adjacentCandidateGroups(cloud, pointers(candidates), 0.01).empty());
  EXPECT_TRUE(adjacentCandidateGroups(cloud, {}, 0.01).empty());
}

}  // namespace
}  // namespace vdc
