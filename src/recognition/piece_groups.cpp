#include "piece_groups.h"

#include <pcl/kdtree/kdtree_flann.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <set>

namespace vdc {
namespace {

// The candidate's finite points' ray directions (unit vectors) and depths along them.
struct Rays {
  pcl::PointCloud<pcl::PointXYZ>::Ptr directions =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::vector<float> ranges;
  Eigen::AlignedBox3f direction_box;  // of the directions
  float nearest_range = std::numeric_limits<float>::infinity();
};

Rays raysOf(const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneCandidate& candidate) {
  Rays rays;
  for (int index : candidate.indices) {
    const Eigen::Vector3f p = cloud[index].getVector3fMap();
    const float range = p.norm();
    if (!std::isfinite(range) || range <= 0.0f) continue;
    const Eigen::Vector3f d = p / range;
    rays.directions->push_back(pcl::PointXYZ(d.x(), d.y(), d.z()));
    rays.ranges.push_back(range);
    rays.direction_box.extend(d);
    rays.nearest_range = std::min(rays.nearest_range, range);
  }
  return rays;
}

// Whether no ray of `other` can be beside one of `rays`: the boxes of their directions lie
// further apart than the widest angle touch_distance spans at other's nearest point (a chord
// between unit vectors is never longer than their angle). Most pairs of a scene's candidates
// are decided here, without a search per point.
bool farApart(const Rays& rays, const Rays& other, double touch_distance) {
  const double widest = touch_distance / other.nearest_range;
  return rays.direction_box.exteriorDistance(other.direction_box) > widest;
}

bool beside(const pcl::KdTreeFLANN<pcl::PointXYZ>& tree, const Rays& other, double touch_distance) {
  std::vector<int> index(1);
  std::vector<float> squared(1);
  for (std::size_t i = 0; i < other.ranges.size(); ++i) {
    // The angle touch_distance spans at this point's range: far points may be behind a gap.
    const double angle = touch_distance / other.ranges[i];
    if (tree.nearestKSearch((*other.directions)[i], 1, index, squared) > 0 &&
        squared[0] <= angle * angle) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::vector<std::size_t>> adjacentCandidateGroups(
    const pcl::PointCloud<pcl::PointXYZ>& cloud,
    const std::vector<const SceneCandidate*>& candidates, double touch_distance) {
  const std::size_t n = candidates.size();
  std::vector<Rays> rays;
  std::vector<pcl::KdTreeFLANN<pcl::PointXYZ>> trees(n);
  for (std::size_t i = 0; i < n; ++i) {
    rays.push_back(raysOf(cloud, *candidates[i]));
    if (!rays.back().ranges.empty()) trees[i].setInputCloud(rays.back().directions);
  }
  std::vector<std::vector<bool>> adjacent(n, std::vector<bool>(n, false));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (rays[i].ranges.empty() || rays[j].ranges.empty() ||
          farApart(rays[i], rays[j], touch_distance)) {
        continue;
      }
      adjacent[i][j] = adjacent[j][i] = beside(trees[i], rays[j], touch_distance);
    }
  }
  // Pairs beside each other, and where they lie in different clusters, each with the other's
  // whole cluster: an object that hides part of itself is its near part and what lies behind it.
  const auto cluster_of = [&](std::size_t i) {
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < n; ++k) {
      if (k == i ||
          (candidates[i]->cluster >= 0 && candidates[k]->cluster == candidates[i]->cluster)) {
        members.push_back(k);
      }
    }
    return members;
  };
  std::set<std::vector<std::size_t>> seen;
  std::vector<std::vector<std::size_t>> groups;
  const auto add = [&](std::vector<std::size_t> group) {
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    if (seen.insert(group).second) groups.push_back(std::move(group));
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!adjacent[i][j]) continue;
      add({i, j});
      if (candidates[i]->cluster == candidates[j]->cluster && candidates[i]->cluster >= 0) continue;
      std::vector<std::size_t> with_cluster = cluster_of(j);
      with_cluster.push_back(i);
      add(with_cluster);
      with_cluster = cluster_of(i);
      with_cluster.push_back(j);
      add(with_cluster);
      // Both clusters whole: an object whose near part hides its middle falls into two clusters,
      // each of them in pieces (an elephant's head and trunk in front of its body).
      std::vector<std::size_t> both = cluster_of(i);
      const std::vector<std::size_t> other = cluster_of(j);
      both.insert(both.end(), other.begin(), other.end());
      add(both);
    }
  }
  const auto points = [&](const std::vector<std::size_t>& group) {
    std::size_t total = 0;
    for (std::size_t k : group) total += candidates[k]->indices.size();
    return total;
  };
  const auto clusters = [&](const std::vector<std::size_t>& group) {
    std::set<int> spanned;
    for (std::size_t k : group) spanned.insert(candidates[k]->cluster);
    return spanned.size();
  };
  std::stable_sort(groups.begin(), groups.end(), [&](const auto& a, const auto& b) {
    const bool a_across = clusters(a) > 1;
    const bool b_across = clusters(b) > 1;
    if (a_across != b_across) return a_across;
    return points(a) < points(b);
  });
  return groups;
}

}  // namespace vdc
