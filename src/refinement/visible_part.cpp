#include "visible_part.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace vdc {

std::vector<Eigen::Vector3d> visibleSamples(const ModelSurface& surface,
                                            const Eigen::Vector3d& camera) {
  const Eigen::Vector3d forward = -camera.normalized();
  const Eigen::Vector3d side = forward.unitOrthogonal();
  const Eigen::Vector3d up = forward.cross(side);
  const double cell = 2.0 * surface.spacing() / camera.norm();
  std::unordered_map<std::uint64_t, std::pair<double, Eigen::Vector3d>> nearest;
  for (const auto& sample : surface.cloud()->points) {
    const Eigen::Vector3d s = sample.getVector3fMap().cast<double>();
    const Eigen::Vector3d ray = s - camera;
    const double depth = ray.dot(forward);
    if (depth <= 0.0 || sample.getNormalVector3fMap().cast<double>().dot(ray) >= 0.0) continue;
    const auto u = static_cast<std::int64_t>(std::floor(ray.dot(side) / depth / cell));
    const auto v = static_cast<std::int64_t>(std::floor(ray.dot(up) / depth / cell));
    // Unsigned: shifting a negative cell index left is undefined behaviour before C++20.
    const std::uint64_t key =
        (static_cast<std::uint64_t>(u) << 32) ^ (static_cast<std::uint64_t>(v) & 0xffffffffu);
    auto [it, inserted] = nearest.try_emplace(key, depth, s);
    if (!inserted && depth < it->second.first) it->second = {depth, s};
  }
  std::vector<Eigen::Vector3d> visible;
  visible.reserve(nearest.size());
  for (const auto& [key, hit] : nearest) visible.push_back(hit.second);
  return visible;
}

namespace {

Eigen::Vector3d centroidOf(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return points.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(points.size()));
}

// Indices of up to `count` samples spread over the points: each the farthest from those before,
// starting from the one farthest from the centroid (deterministic).
std::vector<std::size_t> farthestPoints(const std::vector<Eigen::Vector3d>& points,
                                        const Eigen::Vector3d& centroid, int count) {
  std::vector<double> distance(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) distance[i] = (points[i] - centroid).norm();
  std::vector<std::size_t> seeds;
  while (static_cast<int>(seeds.size()) < count) {
    std::size_t farthest = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      if (distance[i] > distance[farthest]) farthest = i;
    }
    if (distance[farthest] <= 0.0) break;
    seeds.push_back(farthest);
    for (std::size_t i = 0; i < points.size(); ++i) {
      distance[i] = std::min(distance[i], (points[i] - points[farthest]).norm());
    }
  }
  return seeds;
}

}  // namespace

double rmsRadius(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return 0.0;
  const Eigen::Vector3d centroid = centroidOf(points);
  double sum = 0.0;
  for (const Eigen::Vector3d& p : points) sum += (p - centroid).squaredNorm();
  return std::sqrt(sum / static_cast<double>(points.size()));
}

std::vector<Eigen::Vector3d> placementAnchors(const std::vector<Eigen::Vector3d>& visible,
                                              double observed_rms, double partial_ratio,
                                              int max_patches) {
  std::vector<Eigen::Vector3d> anchors;
  if (visible.empty()) return anchors;
  const Eigen::Vector3d centroid = centroidOf(visible);
  anchors.push_back(centroid);
  if (max_patches <= 0 || !(observed_rms < partial_ratio * rmsRadius(visible))) return anchors;
  const double radius = std::sqrt(2.0) * observed_rms;
  for (const std::size_t seed : farthestPoints(visible, centroid, max_patches)) {
    std::vector<Eigen::Vector3d> patch;
    for (const Eigen::Vector3d& p : visible) {
      if ((p - visible[seed]).norm() <= radius) patch.push_back(p);
    }
    anchors.push_back(centroidOf(patch));
  }
  return anchors;
}

VisibleParts::VisibleParts(const ModelSurface& surface, double observed_rms, double partial_ratio,
                           int max_patches)
    : surface_(surface),
      observed_rms_(observed_rms),
      partial_ratio_(partial_ratio),
      max_patches_(max_patches) {}

const std::vector<Eigen::Vector3d>& VisibleParts::anchors(const Eigen::Vector3d& camera) {
  for (const auto& [known, anchors] : known_) {
    // 1 % of the distance: the visible part shifts by far less than ICP's reach.
    if ((known - camera).norm() < 0.01 * camera.norm()) return anchors;
  }
  known_.emplace_back(camera, placementAnchors(visibleSamples(surface_, camera), observed_rms_,
                                               partial_ratio_, max_patches_));
  return known_.back().second;
}

}  // namespace vdc
