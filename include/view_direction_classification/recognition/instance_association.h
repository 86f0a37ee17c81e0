#pragma once

#include <Eigen/Core>

#include <vector>

namespace vdc {

// Which candidate of this frame is which known instance: pairs nearer than `max_distance` [m]
// (fixed frame: the candidates' centroids against where each instance was last seen), nearest
// pair first, each candidate and instance taken once. Returns, per candidate, the index of its
// instance or -1 (a new or unknown object).
std::vector<int> associateCandidates(const std::vector<Eigen::Vector3d>& candidate_centroids,
                                     const std::vector<Eigen::Vector3d>& instance_centroids,
                                     double max_distance);

}  // namespace vdc
