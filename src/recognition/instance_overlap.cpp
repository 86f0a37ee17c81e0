#include "view_direction_classification/recognition/instance_overlap.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/surface/convex_hull.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/recognition/instance_presence.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc {
namespace {

// Points of the hull's volume each model keeps: enough to tell a tenth of it shared from a fifth
// within a few percent, few enough that one comparison stays far below a millisecond.
constexpr double kVolumeSamples = 1500.0;

// The hull's facets as planes n . x + d = 0, n pointing out: inside where every n . x + d <= 0.
std::vector<Eigen::Vector4d> convexHullPlanes(const std::vector<Eigen::Vector3f>& points) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3f& p : points) {
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    centroid += p.cast<double>();
  }
  centroid /= static_cast<double>(std::max<std::size_t>(1, points.size()));
  pcl::ConvexHull<pcl::PointXYZ> hull;
  hull.setInputCloud(cloud);
  hull.setDimension(3);
  pcl::PointCloud<pcl::PointXYZ> vertices;
  std::vector<pcl::Vertices> facets;
  hull.reconstruct(vertices, facets);
  std::vector<Eigen::Vector4d> planes;
  for (const pcl::Vertices& facet : facets) {
    if (facet.vertices.size() < 3) continue;
    const Eigen::Vector3d a = vertices[facet.vertices[0]].getVector3fMap().cast<double>();
    const Eigen::Vector3d b = vertices[facet.vertices[1]].getVector3fMap().cast<double>();
    const Eigen::Vector3d c = vertices[facet.vertices[2]].getVector3fMap().cast<double>();
    Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-12) continue;
    normal.normalize();
    if (normal.dot(centroid - a) > 0.0) normal = -normal;
    planes.emplace_back(normal.x(), normal.y(), normal.z(), -normal.dot(a));
  }
  return planes;
}

bool insideHull(const std::vector<Eigen::Vector4d>& planes, const Eigen::Vector3d& point) {
  return std::all_of(planes.begin(), planes.end(), [&](const Eigen::Vector4d& plane) {
    return plane.head<3>().dot(point) + plane.w() <= 0.0;
  });
}

// Points on a regular grid over the box that lie inside the hull.
std::vector<Eigen::Vector3d> volumeSamples(const std::vector<Eigen::Vector4d>& planes,
                                           const Eigen::AlignedBox3d& box) {
  const Eigen::Vector3d sizes = box.sizes();
  const double step = std::cbrt(sizes.prod() / kVolumeSamples);
  std::vector<Eigen::Vector3d> samples;
  if (!(step > 0.0)) return samples;
  for (double x = box.min().x() + 0.5 * step; x < box.max().x(); x += step) {
    for (double y = box.min().y() + 0.5 * step; y < box.max().y(); y += step) {
      for (double z = box.min().z() + 0.5 * step; z < box.max().z(); z += step) {
        const Eigen::Vector3d point(x, y, z);
        if (insideHull(planes, point)) samples.push_back(point);
      }
    }
  }
  return samples;
}

}  // namespace

std::optional<Eigen::Isometry3d> believedPose(const OrientationEstimator& estimator) {
  const std::optional<Eigen::Vector3d> position = estimator.positionEstimate();
  if (!position) return std::nullopt;
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  world_from_object.linear() = quaternionToRotationMatrix(estimator.mapOrientation());
  world_from_object.translation() = *position;
  return world_from_object;
}

InstanceOverlap::InstanceOverlap(const ModelLibrary& library) {
  for (const LibraryModel& model : library.models()) {
    ModelHull hull;
    hull.box = model.bundle->bounds;
    hull.planes = convexHullPlanes(model.bundle->surface_points);
    hull.samples = volumeSamples(hull.planes, hull.box);
    hulls_.push_back(std::move(hull));
  }
}

double InstanceOverlap::insideFraction(int model, const Eigen::Isometry3d& samples_pose,
                                       const Eigen::Isometry3d& hull_pose) const {
  const ModelHull& hull = hulls_.at(static_cast<std::size_t>(model));
  if (hull.samples.empty()) return 0.0;
  const Eigen::Isometry3d hull_from_samples = hull_pose.inverse() * samples_pose;
  const auto inside =
      std::count_if(hull.samples.begin(), hull.samples.end(), [&](const Eigen::Vector3d& p) {
        const Eigen::Vector3d q = hull_from_samples * p;
        return hull.box.contains(q) && insideHull(hull.planes, q);
      });
  return static_cast<double>(inside) / static_cast<double>(hull.samples.size());
}

double InstanceOverlap::overlap(int model, const Eigen::Isometry3d& a,
                                const Eigen::Isometry3d& b) const {
  return 0.5 * (insideFraction(model, a, b) + insideFraction(model, b, a));
}

int InstanceOverlap::overlappingInstance(const std::vector<ObjectInstance>& instances, int model,
                                         const Eigen::Isometry3d& world_from_object,
                                         double min_overlap) const {
  int best = -1;
  double best_overlap = min_overlap;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const ObjectInstance& instance = instances[i];
    if (instance.model != model || instance.presence.state == InstanceState::kGone) continue;
    const std::optional<Eigen::Isometry3d> pose = believedPose(*instance.estimator);
    if (!pose) continue;
    const double shared = overlap(model, world_from_object, *pose);
    if (shared >= best_overlap) {
      best = static_cast<int>(i);
      best_overlap = shared;
    }
  }
  return best;
}

}  // namespace vdc
