#include "start_screening.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "distance_field.h"

namespace vdc {

pcl::PointCloud<pcl::PointXYZ>::Ptr evenSubsample(const pcl::PointCloud<pcl::PointXYZ>& points,
                                                  int count) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr subsample(new pcl::PointCloud<pcl::PointXYZ>);
  const std::size_t size = points.size();
  const std::size_t stride = count > 0 && size > static_cast<std::size_t>(count)
                                 ? size / static_cast<std::size_t>(count)
                                 : 1;
  for (std::size_t i = 0; i < size; i += stride) subsample->push_back(points[i]);
  return subsample;
}

double meanTruncatedDistance(const ModelSurface& surface,
                             const pcl::PointCloud<pcl::PointXYZ>& points_world,
                             const Eigen::Isometry3d& world_from_object, double truncation) {
  if (points_world.empty()) return truncation;
  const Eigen::Isometry3f object_from_world = world_from_object.inverse().cast<float>();
  const TruncatedDistanceField& field = surface.distanceField(truncation);
  double sum = 0.0;
  for (const auto& p : points_world.points) {
    sum += field.distance(object_from_world * p.getVector3fMap());
  }
  return sum / static_cast<double>(points_world.size());
}

std::vector<std::size_t> bestStarts(const std::vector<double>& distances,
                                    const std::vector<int>& components, int count) {
  std::vector<std::size_t> order(distances.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distances[a] < distances[b]; });
  if (count <= 0) return order;
  std::map<int, int> taken;  // starts chosen so far per component
  std::vector<std::size_t> best;
  for (const std::size_t index : order) {
    if (taken[components[index]]++ < count) best.push_back(index);
  }
  return best;
}

}  // namespace vdc
