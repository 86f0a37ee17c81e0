#include "view_direction_classification/recognition/instance_explanation.h"

#include <algorithm>

namespace vdc {

InstanceExplanation::InstanceExplanation(const ModelBundle& model)
    : surface_(std::make_unique<const NearestPoints>(model.surface_points)),
      normals_(model.surface_normals) {}

std::vector<bool> InstanceExplanation::explainedPoints(
    const std::vector<Eigen::Vector3f>& points_world, const Eigen::Isometry3d& world_from_object,
    double tolerance, const std::vector<Eigen::Vector3f>* normals_world,
    double min_normal_cosine) const {
  const Eigen::Isometry3f object_from_world = world_from_object.inverse().cast<float>();
  std::vector<Eigen::Vector3f> queries;
  queries.reserve(points_world.size());
  for (const Eigen::Vector3f& p : points_world) queries.push_back(object_from_world * p);
  std::vector<int> indices;
  std::vector<float> squared;
  surface_->search(queries, &indices, &squared, tolerance);
  const bool judge_normals = normals_world != nullptr &&
                             normals_world->size() == points_world.size() &&
                             normals_.size() == surface_->size();
  std::vector<bool> explained(points_world.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    explained[i] = indices[i] >= 0;
    if (!explained[i] || !judge_normals || !(*normals_world)[i].allFinite()) continue;
    const Eigen::Vector3f normal = object_from_world.linear() * (*normals_world)[i];
    explained[i] = normal.dot(normals_[static_cast<std::size_t>(indices[i])]) >= min_normal_cosine;
  }
  return explained;
}

double InstanceExplanation::explainedFraction(const std::vector<Eigen::Vector3f>& points_world,
                                              const Eigen::Isometry3d& world_from_object,
                                              double tolerance) const {
  if (points_world.empty()) return 0.0;
  const std::vector<bool> explained = explainedPoints(points_world, world_from_object, tolerance);
  return static_cast<double>(std::count(explained.begin(), explained.end(), true)) /
         static_cast<double>(points_world.size());
}

bool InstanceExplanation::explainsPart(const std::vector<Eigen::Vector3f>& points_world,
                                       const Eigen::Isometry3d& world_from_object, double tolerance,
                                       double min_fraction) const {
  return explainedFraction(points_world, world_from_object, tolerance) >= min_fraction;
}

}  // namespace vdc
