#pragma once

#include <Eigen/Core>

#include <vector>

namespace vdc {

// An occluder point cloud in the object frame (e.g. the clutter around the object). A surface
// point s is hidden from a camera at c if an occluder point lies within `radius` of the segment
// from s to c; the first 2 * radius of the segment next to s are left out, so occluder points on
// the object's own surface (or touching it) do not hide the point they lie on.
// Per candidate the occluder points in front of the camera are projected onto its image plane
// and put in a kd-tree (pcl::KdTreeFLANN); a surface point's neighbours within a conservative
// image radius are then tested exactly (point-to-segment distance), so the test is exact and
// costs O(log n) per surface point.
class OccluderCloud {
 public:
  // Throws vdc::Error for an empty cloud, a non-finite point or a non-positive radius.
  explicit OccluderCloud(std::vector<Eigen::Vector3d> points_object, double radius = 0.005);
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  double radius() const { return radius_; }

  // For each query point, whether it is hidden from the camera centre camera_object (object
  // frame). Throws vdc::Error for a non-finite camera position.
  std::vector<bool> hidden(const Eigen::Vector3d& camera_object,
                           const std::vector<Eigen::Vector3d>& surface_points) const;

 private:
  std::vector<Eigen::Vector3d> points_;
  double radius_;
};

}  // namespace vdc
