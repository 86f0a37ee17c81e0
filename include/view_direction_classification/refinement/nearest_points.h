#pragma once

#include <Eigen/Core>

#include <limits>
#include <memory>
#include <vector>

namespace vdc {

// Exact nearest-neighbour search over a fixed set of 3D points that answers many queries in one
// call, through nanoflann's k-d tree. Refinement asks hundreds of thousands of such questions
// per view. A single-point search through PCL's KdTreeFLANN pays FLANN's per-call OpenMP set-up,
// about 7 us on the project's machine against under 1 us for the search itself; FLANN's batched
// search, used before nanoflann, made refinement about a quarter slower (doc/performance.md).
// Immutable after construction; search() is const and thread-safe.
class NearestPoints {
 public:
  explicit NearestPoints(std::vector<Eigen::Vector3f> points);
  // With the points' unit normals (the same size), so that a search can keep to the points that
  // face the query's camera (FacingFilter). Throws vdc::Error for another count.
  NearestPoints(std::vector<Eigen::Vector3f> points, std::vector<Eigen::Vector3f> normals);
  ~NearestPoints();
  NearestPoints(const NearestPoints&) = delete;
  NearestPoints& operator=(const NearestPoints&) = delete;

  // For each query, the index of its nearest point and the squared distance to it (-1 and
  // infinity when there are no points). With a finite max_distance [m] a query whose nearest
  // point lies farther is reported as having none: every caller drops such pairs anyway, and a
  // bounded search prunes the tree from the start, where an unbounded one explores everything
  // nearer than the first leaf it reaches (a point of a wrong pose's cloud far off the model).
  // Only points on the side of the surface a query's camera sees: a point whose normal n makes
  // n . towards_camera[q] >= min_cosine with the query's unit direction to its camera.
  struct FacingFilter {
    const std::vector<Eigen::Vector3f>* towards_camera = nullptr;  // one per query
    float min_cosine = 0.0f;
  };
  // With `facing`, only the points that face each query's camera are candidates; it needs the
  // normals and one direction per query (vdc::Error otherwise).
  void search(const std::vector<Eigen::Vector3f>& queries, std::vector<int>* indices,
              std::vector<float>* squared_distances,
              double max_distance = std::numeric_limits<double>::infinity(),
              const FacingFilter* facing = nullptr) const;
  std::size_t size() const { return points_.size(); }

 private:
  struct Index;
  std::vector<Eigen::Vector3f> points_;
  std::vector<Eigen::Vector3f> normals_;  // empty, or one per point
  std::unique_ptr<Index> index_;
};

}  // namespace vdc
