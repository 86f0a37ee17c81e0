#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Quality report of a triangle mesh. Edges are undirected vertex pairs; a closed 2-manifold has
// every edge shared by exactly two triangles.
struct MeshCheck {
  std::size_t boundary_edges = 0;        // edges of exactly one triangle (holes, open rims)
  std::size_t non_manifold_edges = 0;    // edges of three or more triangles
  std::size_t degenerate_triangles = 0;  // repeated vertex or (numerically) zero area
  std::size_t inconsistent_edges = 0;    // two-triangle edges walked in the same direction twice
  bool watertight = false;               // non-empty, no boundary and no non-manifold edges
  double largest_extent = 0.0;           // longest side of the bounding box [m]
  std::vector<std::string> warnings;     // one sentence per problem found
};

// Topology and scale report. Throws vdc::Error for triangle indices outside the vertex list or
// non-finite vertex coordinates (such a mesh cannot be used at all).
MeshCheck checkMesh(const TriangleMesh& mesh);

// Validation of an object mesh before training (`name` is the file or object name used in the
// messages). Throws vdc::Error for an empty mesh, invalid indices, non-finite coordinates, or an
// absurd scale (largest extent above 5 m: probably millimetres; below 5 mm: probably not metres).
// Returns the warnings (open or non-manifold surface, degenerate triangles) for the caller to
// print: such meshes still render and sample correctly.
std::vector<std::string> validateObjectMesh(const TriangleMesh& mesh, const std::string& name);

// Scale limits of validateObjectMesh [m].
constexpr double kMaxObjectExtent = 5.0;
constexpr double kMinObjectExtent = 0.005;

}  // namespace vdc
