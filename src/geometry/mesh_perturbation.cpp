#include "view_direction_classification/geometry/mesh_perturbation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/number_text.h"

namespace vdc {
namespace {

// The dent radius when none is given, as a fraction of the bounding-box diagonal: a dent of a
// thumb's size on a mug.
constexpr double kDefaultDentRadiusFraction = 0.1;

// A perturbed object, not another one: scales beyond these would make float vertices degenerate
// or overflow.
constexpr double kSmallestScale = 0.1;
constexpr double kLargestScale = 10.0;

struct Dent {
  Eigen::Vector3d centre;
  Eigen::Vector3d normal;
};

// Area-weighted vertex normals, shared by vertices at the same position so that a mesh with
// split vertices does not tear open where its faces meet.
std::vector<Eigen::Vector3d> vertexNormals(const TriangleMesh& mesh) {
  std::map<std::array<float, 3>, Eigen::Vector3d> by_position;
  const auto key = [&mesh](int v) {
    const Eigen::Vector3f& p = mesh.vertices[static_cast<std::size_t>(v)];
    return std::array<float, 3>{p.x(), p.y(), p.z()};
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    // The cross product's length is twice the area: the weighting.
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[static_cast<std::size_t>(tri(0))].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[static_cast<std::size_t>(tri(1))].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[static_cast<std::size_t>(tri(2))].cast<double>();
    const Eigen::Vector3d weighted = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) {
      auto [it, inserted] = by_position.try_emplace(key(tri(k)), Eigen::Vector3d::Zero());
      it->second += weighted;
    }
  }
  std::vector<Eigen::Vector3d> normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto it = by_position.find(key(static_cast<int>(v)));
    if (it != by_position.end() && it->second.norm() > 0.0) normals[v] = it->second.normalized();
  }
  return normals;
}

// Dent centres area-uniform on the surface, with the face normal there.
std::vector<Dent> drawDents(const TriangleMesh& mesh, const MeshPerturbation& perturbation) {
  std::vector<double> areas(mesh.triangles.size());
  for (std::size_t t = 0; t < areas.size(); ++t) areas[t] = mesh.triangleArea(t);
  std::mt19937 rng(perturbation.seed);
  std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Dent> dents;
  for (int k = 0; k < perturbation.dents; ++k) {
    const std::size_t t = pick(rng);
    double u = unit(rng), w = unit(rng);
    if (u + w > 1.0) u = 1.0 - u, w = 1.0 - w;  // reflect into the triangle
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[static_cast<std::size_t>(tri(0))].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[static_cast<std::size_t>(tri(1))].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[static_cast<std::size_t>(tri(2))].cast<double>();
    dents.push_back({a + u * (b - a) + w * (c - a), mesh.triangleNormal(t).cast<double>()});
  }
  return dents;
}

// How far inward vertex p (normal n) moves: the deepest dent's push.
double dentDepthAt(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                   const std::vector<Dent>& dents, double depth, double radius) {
  double deepest = 0.0;
  for (const Dent& dent : dents) {
    const double r = (p - dent.centre).norm() / radius;
    if (r >= 1.0) continue;
    const double falloff = (1.0 - r * r) * (1.0 - r * r);
    deepest = std::max(deepest, depth * falloff * std::max(0.0, n.dot(dent.normal)));
  }
  return deepest;
}

void applyDents(const MeshPerturbation& perturbation, TriangleMesh* mesh) {
  if (perturbation.dents == 0 || perturbation.dent_depth == 0.0 || mesh->empty()) return;
  const double radius = perturbation.dent_radius > 0.0
                            ? perturbation.dent_radius
                            : kDefaultDentRadiusFraction * mesh->bounds().diagonal().norm();
  if (!(radius > 0.0)) return;  // a degenerate mesh: nothing to dent
  const std::vector<Dent> dents = drawDents(*mesh, perturbation);
  const std::vector<Eigen::Vector3d> normals = vertexNormals(*mesh);
  for (std::size_t v = 0; v < mesh->vertices.size(); ++v) {
    const Eigen::Vector3d p = mesh->vertices[v].cast<double>();
    const double push = dentDepthAt(p, normals[v], dents, perturbation.dent_depth, radius);
    if (push > 0.0) mesh->vertices[v] = (p - push * normals[v]).cast<float>();
  }
}

}  // namespace

bool MeshPerturbation::any() const {
  return scale != Eigen::Vector3d::Ones() || (dents > 0 && dent_depth > 0.0);
}

void checkMeshPerturbation(const MeshPerturbation& p) {
  for (int k = 0; k < 3; ++k) {
    if (!(p.scale(k) >= kSmallestScale && p.scale(k) <= kLargestScale)) {  // also NaN
      throw Error("the mesh scale must be in [0.1, 10] on every axis, got " +
                  numberText(p.scale(k)) + " on axis " + std::to_string(k));
    }
  }
  if (p.dents < 0) {
    throw Error("the number of mesh dents must not be negative, got " + std::to_string(p.dents));
  }
  if (!std::isfinite(p.dent_depth) || p.dent_depth < 0.0) {
    throw Error("the mesh dents' depth must be a finite number >= 0, got " +
                numberText(p.dent_depth) + " m");
  }
  if (!std::isfinite(p.dent_radius) || p.dent_radius < 0.0) {
    throw Error("the mesh dents' radius must be a finite number >= 0, got " +
                numberText(p.dent_radius) + " m");
  }
}

TriangleMesh perturbMesh(const TriangleMesh& mesh, const MeshPerturbation& perturbation) {
  checkMeshPerturbation(perturbation);
  TriangleMesh result = mesh;
  if (!perturbation.any()) return result;
  const Eigen::Vector3f scale = perturbation.scale.cast<float>();
  for (Eigen::Vector3f& v : result.vertices) v = v.cwiseProduct(scale);
  applyDents(perturbation, &result);
  return result;
}

}  // namespace vdc
