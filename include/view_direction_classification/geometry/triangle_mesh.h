#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace vdc {

// An indexed triangle mesh in metres, in the object's own frame. Triangles list their vertices
// counter-clockwise when seen from outside, so (v1 - v0) x (v2 - v0) points outwards.
struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3i> triangles;  // indices into vertices

  // Total surface area [m^2]. Assumes valid indices (see checkMesh).
  double area() const;
  // Axis-aligned bounding box of the vertices (empty box for a mesh without vertices).
  Eigen::AlignedBox3f bounds() const;

  bool empty() const { return triangles.empty(); }
  // Area of triangle t [m^2] and its unit normal (zero for a degenerate triangle).
  double triangleArea(std::size_t t) const;
  Eigen::Vector3f triangleNormal(std::size_t t) const;
  // Signed enclosed volume [m^3] (divergence theorem): positive for closed, outward-oriented
  // shells; meaningful only for closed meshes.
  double signedVolume() const;
  // Appends `other`, reindexing its triangles (used to assemble multi-part objects).
  void append(const TriangleMesh& other);
};

}  // namespace vdc
