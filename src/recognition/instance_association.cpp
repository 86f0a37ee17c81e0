#include "view_direction_classification/recognition/instance_association.h"

#include <algorithm>
#include <tuple>

namespace vdc {

std::vector<int> associateCandidates(const std::vector<Eigen::Vector3d>& candidate_centroids,
                                     const std::vector<Eigen::Vector3d>& instance_centroids,
                                     double max_distance) {
  // Greedy nearest-first: the scene's objects are several centimetres apart while an instance's
  // centroid moves by millimetres between views, so the globally optimal assignment would not
  // differ in practice.
  std::vector<std::tuple<double, int, int>> pairs;
  for (int c = 0; c < static_cast<int>(candidate_centroids.size()); ++c) {
    for (int i = 0; i < static_cast<int>(instance_centroids.size()); ++i) {
      const double distance = (candidate_centroids[c] - instance_centroids[i]).norm();
      if (distance < max_distance) pairs.emplace_back(distance, c, i);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> instance_of(candidate_centroids.size(), -1);
  std::vector<bool> taken(instance_centroids.size(), false);
  for (const auto& [distance, c, i] : pairs) {
    if (instance_of[c] >= 0 || taken[i]) continue;
    instance_of[c] = i;
    taken[i] = true;
  }
  return instance_of;
}

}  // namespace vdc
