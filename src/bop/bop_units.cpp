#include "view_direction_classification/bop/bop_units.h"

#include <algorithm>
#include <cmath>

namespace vdc {

Eigen::Isometry3d isometryOf(const BopPose& pose) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = pose.R;
  result.translation() = pose.t / kMillimetresPerMetre;
  return result;
}

BopPose bopPoseOf(const Eigen::Isometry3d& pose) {
  return {pose.linear(), pose.translation() * kMillimetresPerMetre};
}

TriangleMesh scaledMesh(const TriangleMesh& mesh, double factor) {
  TriangleMesh scaled = mesh;
  for (Eigen::Vector3f& v : scaled.vertices) v *= static_cast<float>(factor);
  return scaled;
}

std::vector<Eigen::Vector3d> verticesInMillimetres(const TriangleMesh& mesh_m) {
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh_m.vertices.size());
  for (const Eigen::Vector3f& v : mesh_m.vertices) {
    vertices.push_back(v.cast<double>() * kMillimetresPerMetre);
  }
  return vertices;
}

double bopDiameter(const TriangleMesh& mesh_m) {
  const std::vector<Eigen::Vector3d> vertices = verticesInMillimetres(mesh_m);
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    for (std::size_t j = i + 1; j < vertices.size(); ++j) {
      largest_squared = std::max(largest_squared, (vertices[i] - vertices[j]).squaredNorm());
    }
  }
  return std::sqrt(largest_squared);
}

}  // namespace vdc
