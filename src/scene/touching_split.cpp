// Touching objects are split by local convexity (supervoxels + LCCP, Stein et al. 2014) rather
// than by region growing on normals: region growing cuts wherever the normal turns, so a box
// falls apart into its faces, while the objects of a tabletop are (mostly) convex and meet their
// neighbours in concave edges, which is exactly where LCCP cuts. A cylinder's side and a box's
// faces stay together; a cylinder against a box, or two boxes side by side at different heights
// or angles, come apart. What LCCP cannot see: two identical boxes flush side by side form one
// convex box, and no geometry-only split can separate them.

#include "touching_split.h"

#include <pcl/search/kdtree.h>
#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>

namespace vdc::scene {
namespace {

using Supervoxels = std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr>;

// Segments of at most this many supervoxels join their largest neighbour (LCCP's own rule): noise
// makes single supervoxels at edges look concave.
constexpr std::size_t kSmallSegmentSupervoxels = 3;

// Per supervoxel label, its segment's label, after the segments of at most
// kSmallSegmentSupervoxels supervoxels joined their largest neighbour (ties: the lower label), the
// smallest first, until none is left that has a neighbour. LCCP would do the same
// (setMinSegmentSize), but it walks its graph (boost setS vertices) in the order of their heap
// addresses: the same cloud came out cut differently depending on what the process had
// allocated before (a scene's candidates in the scene evaluation changed with the scenes run
// before it). LCCP numbers its segments in that order too, so each is first named after its
// lowest supervoxel label (supervoxel labels do not depend on it; never 0), and every order
// here is those names'.
std::map<std::uint32_t, std::uint32_t> joinSmallSegments(
    std::map<std::uint32_t, std::uint32_t> segment_of,
    const std::multimap<std::uint32_t, std::uint32_t>& adjacency) {
  std::map<std::uint32_t, std::uint32_t> name;  // LCCP's segment label -> its lowest supervoxel
  for (const auto& [supervoxel, segment] : segment_of) name.emplace(segment, supervoxel);
  for (auto& entry : segment_of) entry.second = name[entry.second];
  std::map<std::uint32_t, std::size_t> size;
  for (const auto& [supervoxel, segment] : segment_of) ++size[segment];
  for (;;) {
    std::set<std::pair<std::size_t, std::uint32_t>> small;  // (size, label): smallest first
    for (const auto& [segment, count] : size) {
      if (count <= kSmallSegmentSupervoxels) small.emplace(count, segment);
    }
    bool joined = false;
    for (const auto& [count, segment] : small) {
      std::set<std::uint32_t> neighbours;
      for (const auto& [a, b] : adjacency) {
        const auto from = segment_of.find(a), to = segment_of.find(b);
        if (from == segment_of.end() || to == segment_of.end()) continue;
        if (from->second == segment && to->second != segment) neighbours.insert(to->second);
      }
      if (neighbours.empty()) continue;
      std::uint32_t largest = *neighbours.begin();
      for (const std::uint32_t neighbour : neighbours) {
        if (size[neighbour] > size[largest]) largest = neighbour;
      }
      for (auto& entry : segment_of) {
        if (entry.second == segment) entry.second = largest;
      }
      size[largest] += count;
      size.erase(segment);
      joined = true;
      break;  // the sizes changed: choose again
    }
    if (!joined) return segment_of;
  }
}

// The LCCP label of each point of `points` (0: in no supervoxel). Empty if there are fewer than
// two supervoxels (nothing to split).
std::vector<std::uint32_t> convexPartLabels(const pcl::PointCloud<pcl::PointXYZ>::Ptr& points,
                                            const SceneSegmentationParameters& parameters) {
  const auto voxel = static_cast<float>(parameters.supervoxel_voxel);
  const auto seed = static_cast<float>(parameters.supervoxel_seed);
  pcl::SupervoxelClustering<pcl::PointXYZ> supervoxel_clustering(voxel, seed);
  // The points are an unorganised cut of the scene; the camera transform would also make an
  // organised and an unorganised input of one scene disagree.
  supervoxel_clustering.setUseSingleCameraTransform(false);
  supervoxel_clustering.setColorImportance(0.0f);  // no colour in PointXYZ
  supervoxel_clustering.setSpatialImportance(1.0f);
  supervoxel_clustering.setNormalImportance(4.0f);
  supervoxel_clustering.setInputCloud(points);
  Supervoxels supervoxels;
  supervoxel_clustering.extract(supervoxels);
  if (supervoxels.size() < 2) return {};
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  supervoxel_clustering.getSupervoxelAdjacency(adjacency);

  pcl::LCCPSegmentation<pcl::PointXYZ> lccp;
  lccp.setConcavityToleranceThreshold(static_cast<float>(parameters.concavity_tolerance_deg));
  lccp.setSanityCheck(true);
  lccp.setSmoothnessCheck(true, voxel, seed, 0.1f);
  // Plain convexity: extended convexity (k = 1) also cuts single boxes along their edges.
  lccp.setKFactor(0);
  lccp.setMinSegmentSize(0);  // joinSmallSegments
  lccp.setInputSupervoxels(supervoxels, adjacency);
  lccp.segment();
  std::map<std::uint32_t, std::uint32_t> segment_of;
  lccp.getSupervoxelToSegmentMap(segment_of);
  segment_of = joinSmallSegments(std::move(segment_of), adjacency);

  const pcl::PointCloud<pcl::PointXYZL>::Ptr labelled = supervoxel_clustering.getLabeledCloud();
  std::vector<std::uint32_t> labels(labelled->size(), 0);
  for (std::size_t k = 0; k < labelled->size(); ++k) {
    const auto found = segment_of.find((*labelled)[k].label);
    if (found != segment_of.end()) labels[k] = found->second;  // 0: in no supervoxel
  }
  return labels;
}

// Parts of at least `min_points` keep their points; the points of smaller parts (a handle, a
// patch of noise) and of no part join the part of their nearest kept point.
std::vector<std::vector<int>> joinSmallParts(const pcl::PointCloud<pcl::PointXYZ>& points,
                                             const std::vector<int>& cluster,
                                             const std::vector<std::uint32_t>& labels,
                                             std::size_t min_points) {
  std::map<std::uint32_t, std::vector<int>> members;  // label -> positions in the cluster
  for (std::size_t k = 0; k < labels.size(); ++k) members[labels[k]].push_back(static_cast<int>(k));
  std::vector<int> part_of(labels.size(), -1);
  pcl::PointCloud<pcl::PointXYZ>::Ptr kept(new pcl::PointCloud<pcl::PointXYZ>);
  std::vector<int> kept_part;
  int parts = 0;
  for (const auto& [label, positions] : members) {
    if (label == 0 || positions.size() < min_points) continue;
    for (const int k : positions) {
      part_of[static_cast<std::size_t>(k)] = parts;
      kept->push_back(points[k]);
      kept_part.push_back(parts);
    }
    ++parts;
  }
  if (parts < 2) return {cluster};
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud(kept);
  std::vector<int> nearest(1);
  std::vector<float> distance(1);
  std::vector<std::vector<int>> split(static_cast<std::size_t>(parts));
  for (std::size_t k = 0; k < cluster.size(); ++k) {
    int part = part_of[k];
    if (part < 0 && tree.nearestKSearch(points[k], 1, nearest, distance) == 1)
      part = kept_part[static_cast<std::size_t>(nearest[0])];
    if (part >= 0) split[static_cast<std::size_t>(part)].push_back(cluster[k]);
  }
  return split;
}

}  // namespace

std::vector<std::vector<int>> splitTouching(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                            const std::vector<int>& cluster,
                                            const SceneSegmentationParameters& parameters) {
  const auto min_points = static_cast<std::size_t>(
      std::max<double>(parameters.min_cluster_points,
                       parameters.min_part_fraction * static_cast<double>(cluster.size())));
  if (cluster.size() < 2 * min_points) return {cluster};
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  points->reserve(cluster.size());
  for (const int i : cluster) points->push_back(cloud[i]);
  const std::vector<std::uint32_t> labels = convexPartLabels(points, parameters);
  if (labels.size() != cluster.size()) return {cluster};
  return joinSmallParts(*points, cluster, labels, min_points);
}

}  // namespace vdc::scene
