#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace vdc {

// Nearest-neighbour search over a fixed set of 3D points that answers many queries in one call.
// A single-point search through PCL's KdTreeFLANN pays FLANN's per-call OpenMP set-up, about
// 7 us on the project's machine against under 1 us for the search itself; refinement asks
// hundreds of thousands of such questions per view, so it asks them in batches. Immutable after
// construction; search() is const and thread-safe.
class NearestPoints {
 public:
  explicit NearestPoints(std::vector<Eigen::Vector3f> points);
  ~NearestPoints();
  NearestPoints(const NearestPoints&) = delete;
  NearestPoints& operator=(const NearestPoints&) = delete;

  // For each query, the index of its nearest point and the squared distance to it (-1 and
  // infinity when there are no points).
  void search(const std::vector<Eigen::Vector3f>& queries, std::vector<int>* indices,
              std::vector<float>* squared_distances) const;
  std::size_t size() const { return points_.size(); }

 private:
  struct Index;
  std::vector<Eigen::Vector3f> points_;
  std::unique_ptr<Index> index_;
};

}  // namespace vdc
