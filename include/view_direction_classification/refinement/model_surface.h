#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <mutex>
#include <vector>

#include "view_direction_classification/refinement/nearest_points.h"

namespace vdc {

class TruncatedDistanceField;

// The model's surface as refinement uses it (doc/method.md, "Refinement"): surface samples with
// their outward normals in the object frame (the bundle's set S, thinned to `spacing`), a k-d tree
// over them and the object's extent. Immutable after construction; searches are const, so one
// instance may serve several threads.
class ModelSurface {
 public:
  // points and normals: the same size, finite, normals unit. spacing [m] > 0: the samples are
  // thinned (every k-th of the stratified set, which keeps its uniform density) to about this
  // spacing when they are denser; source_spacing is theirs. bounds: the object's box. Throws
  // vdc::Error for fewer than 10 samples, a size mismatch, non-finite values, an empty box or a
  // non-positive spacing.
  ModelSurface(const std::vector<Eigen::Vector3f>& points,
               const std::vector<Eigen::Vector3f>& normals, const Eigen::AlignedBox3d& bounds,
               double source_spacing, double spacing);

  const pcl::PointCloud<pcl::PointNormal>::Ptr& cloud() const { return cloud_; }
  // The samples' index for batched nearest-sample searches (nearest_points.h), built once; every
  // search of refinement asks it.
  const NearestPoints& nearest() const { return *nearest_; }
  // The samples' distance field truncated at `truncation` [m] (distance_field.h: the screening of
  // refinement's starts), built on first use for each truncation and kept; thread-safe.
  const TruncatedDistanceField& distanceField(double truncation) const;
  std::size_t size() const { return cloud_->size(); }
  // [m] The thinned samples' spacing (never below the source's).
  double spacing() const { return spacing_; }
  const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  double diagonal() const { return bounds_.diagonal().norm(); }
  // Three orthogonal lines (object frame) about which a nearly symmetric object looks nearly the
  // same when turned, where ICP settles into the wrong turn (pose_refiner.h, restarts): first
  // the axis about which the surface is as nearly rotationally symmetric as it gets
  // (nearSymmetryAxes() in model_surface.cpp), then the two orthogonal to it that meet it in the
  // middle of the surface, the first of them the one a half turn about which moves the surface
  // least (half_turn_axes.h).
  // Found on first use and kept; thread-safe. Refinement builds surfaces that are never
  // restarted from (the polish's facing parts, built per view).
  const std::vector<Eigen::ParametrizedLine<double, 3>>& symmetryAxes() const;

 private:
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud_;
  std::unique_ptr<const NearestPoints> nearest_;
  mutable std::mutex fields_mutex_;
  mutable std::vector<std::shared_ptr<const TruncatedDistanceField>> fields_;
  double spacing_;
  Eigen::AlignedBox3d bounds_;
  mutable std::once_flag symmetry_axes_once_;
  mutable std::vector<Eigen::ParametrizedLine<double, 3>> symmetry_axes_;
};

// The points of a cloud in the fixed frame, moved into the object frame of the model's samples:
// the queries of a batched ModelSurface::nearest() search.
template <typename Point>
std::vector<Eigen::Vector3f> objectFramePoints(const pcl::PointCloud<Point>& points_world,
                                               const Eigen::Isometry3f& object_from_world) {
  std::vector<Eigen::Vector3f> points;
  points.reserve(points_world.size());
  for (const auto& p : points_world.points)
    points.push_back(object_from_world * p.getVector3fMap());
  return points;
}

}  // namespace vdc
