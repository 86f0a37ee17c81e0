#include "view_direction_classification/planning/occluder_cloud.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "position_check.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Distance from p to the segment [a, b].
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double t = length_sq > 0.0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// An orthonormal frame whose third axis is `axis` (unit).
Eigen::Matrix3d frameAround(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = axis.cross(helper).normalized();
  Eigen::Matrix3d frame;
  frame << e1, axis.cross(e1), axis;
  return frame;
}

// The steps of OccluderCloud::hidden: the camera's image plane, the query points and occluder
// points projected onto it, a kd-tree of the occluders' images, and per query point an exact test
// of the occluders near its image.

// Rows e1, e2, axis of the image plane of a camera at `camera` looking at the object origin (or
// along -z if the camera is at the origin).
Eigen::Matrix3d viewingFrame(const Eigen::Vector3d& camera) {
  const Eigen::Vector3d axis =
      camera.norm() > 0.0 ? Eigen::Vector3d(-camera.normalized()) : Eigen::Vector3d(0, 0, -1);
  return frameAround(axis).transpose();
}

// Image coordinates (x/z, y/z) beyond this, 89.99994 degrees off the viewing axis, lie outside
// any camera's field of view. Such points are left out: as floats their images lose all precision
// or overflow, and FLANN's kd-tree, splitting at (min + max) / 2, aborts on an infinite span.
constexpr double kMaxImageCoordinate = 1e6;

bool imageInRange(const Eigen::Vector2d& image) {
  return image.cwiseAbs().maxCoeff() <= kMaxImageCoordinate;  // false for NaN too
}

// The query points' image coordinates (x/z, y/z); points behind the camera or out of range
// (above) are never hidden.
struct ProjectedSurface {
  std::vector<Eigen::Vector2d> image;
  std::vector<bool> in_front;
  double max_image_radius = 0.0;
  double max_depth = 0.0;
};

ProjectedSurface projectSurface(const Eigen::Matrix3d& frame, const Eigen::Vector3d& camera,
                                const std::vector<Eigen::Vector3d>& surface_points) {
  ProjectedSurface surface;
  surface.image.resize(surface_points.size());
  surface.in_front.assign(surface_points.size(), false);
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    const Eigen::Vector3d u = frame * (surface_points[i] - camera);
    if (u.z() <= 0.0) continue;
    surface.image[i] = u.head<2>() / u.z();
    if (!imageInRange(surface.image[i])) continue;
    surface.in_front[i] = true;
    surface.max_image_radius = std::max(surface.max_image_radius, surface.image[i].norm());
    surface.max_depth = std::max(surface.max_depth, u.z());
  }
  return surface;
}

// Occluder points at least 2 radii in front of the camera (points nearer the camera plane are
// left out: an occluder touching the lens), not beyond every query point (those cannot touch a
// line of sight) and with their image in range, projected the same way.
struct ProjectedOccluders {
  pcl::PointCloud<pcl::PointXYZ>::Ptr image{new pcl::PointCloud<pcl::PointXYZ>};
  std::vector<int> index;  // of each image point in the occluder cloud
  double min_depth = std::numeric_limits<double>::infinity();
  double max_image_radius = 0.0;
  Eigen::AlignedBox2d box;  // of the image points
};

ProjectedOccluders projectOccluders(const Eigen::Matrix3d& frame, const Eigen::Vector3d& camera,
                                    const std::vector<Eigen::Vector3d>& points, double radius,
                                    double max_surface_depth) {
  ProjectedOccluders occluders;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d u = frame * (points[i] - camera);
    if (u.z() <= 2.0 * radius || u.z() > max_surface_depth + radius) continue;
    const Eigen::Vector2d q = u.head<2>() / u.z();
    if (!imageInRange(q)) continue;
    occluders.image->push_back(
        pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()), 0.f));
    occluders.index.push_back(static_cast<int>(i));
    occluders.min_depth = std::min(occluders.min_depth, u.z());
    occluders.max_image_radius = std::max(occluders.max_image_radius, q.norm());
    occluders.box.extend(q);
  }
  return occluders;
}

// An occluder point o within `radius` of a segment point p (on s's pixel ray) is joined to p by a
// 3D segment of length <= radius whose depth stays >= min_depth - radius and whose image stays
// within max_image_radius of the centre (perspective maps segments to segments). The
// projection's gradient norm there is sqrt(1 + |q|^2) / z, which bounds the image distance.
double imageSearchRadius(double radius, double max_image_radius, double min_depth) {
  return 1.01 * radius * std::sqrt(1.0 + max_image_radius * max_image_radius) /
         (min_depth - radius);
}

// Whether one of the occluder points points[index[n]] for n in `neighbours` lies within `radius`
// of the sight line from s to the camera, leaving out the first 2 radii next to s.
bool sightLineBlocked(const Eigen::Vector3d& s, const Eigen::Vector3d& camera, double radius,
                      const std::vector<Eigen::Vector3d>& points, const std::vector<int>& index,
                      const std::vector<int>& neighbours) {
  const Eigen::Vector3d to_camera = camera - s;
  const double length = to_camera.norm();
  if (length <= 2.0 * radius) return false;
  const Eigen::Vector3d start = s + (2.0 * radius / length) * to_camera;
  for (int n : neighbours) {
    if (distanceToSegment(points[static_cast<std::size_t>(index[static_cast<std::size_t>(n)])],
                          start, camera) <= radius) {
      return true;
    }
  }
  return false;
}

}  // namespace

OccluderCloud::OccluderCloud(std::vector<Eigen::Vector3d> points_object, double radius)
    : points_(std::move(points_object)), radius_(radius) {
  if (points_.empty()) throw Error("The occluder cloud is empty.");
  for (const auto& p : points_) {
    if (!p.allFinite()) throw Error("The occluder cloud contains a non-finite point.");
  }
  if (!(radius_ > 0.0) || !std::isfinite(radius_)) {
    throw Error("The occluder radius must be positive and finite, got " + std::to_string(radius_) +
                " m.");
  }
}

std::vector<bool> OccluderCloud::hidden(const Eigen::Vector3d& camera_object,
                                        const std::vector<Eigen::Vector3d>& surface_points) const {
  checkFinitePosition(camera_object, "camera position");
  std::vector<bool> result(surface_points.size(), false);
  if (surface_points.empty()) return result;
  const Eigen::Matrix3d frame = viewingFrame(camera_object);
  const ProjectedSurface surface = projectSurface(frame, camera_object, surface_points);
  const ProjectedOccluders occluders =
      projectOccluders(frame, camera_object, points_, radius_, surface.max_depth);
  if (occluders.index.empty()) return result;
  const double search_radius = imageSearchRadius(
      radius_, std::max(surface.max_image_radius, occluders.max_image_radius), occluders.min_depth);
  Eigen::AlignedBox2d search_box = occluders.box;
  search_box.min() -= Eigen::Vector2d::Constant(search_radius);
  search_box.max() += Eigen::Vector2d::Constant(search_radius);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setSortedResults(false);
  tree.setInputCloud(occluders.image);
  std::vector<int> neighbours;
  std::vector<float> distances_sq;
  for (std::size_t i = 0; i < surface_points.size(); ++i) {
    if (!surface.in_front[i] || !search_box.contains(surface.image[i])) continue;
    const pcl::PointXYZ query(static_cast<float>(surface.image[i].x()),
                              static_cast<float>(surface.image[i].y()), 0.f);
    if (tree.radiusSearch(query, search_radius, neighbours, distances_sq) == 0) continue;
    result[i] = sightLineBlocked(surface_points[i], camera_object, radius_, points_,
                                 occluders.index, neighbours);
  }
  return result;
}

}  // namespace vdc
