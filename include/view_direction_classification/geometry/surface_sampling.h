#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// The surface set S (doc/method.md section 1): points on the mesh surface with the outward unit
// normal of the triangle each lies on.
struct SurfaceSamples {
  std::vector<Eigen::Vector3f> points, normals;
  std::size_t size() const { return points.size(); }
};

// Uniform-density samples, round(area / spacing^2) of them. Stratified: the surface is cut into
// cells of at most about spacing^2 area (longest-edge bisection of each triangle), the cells are
// laid out in a spatially coherent order, and the k-th sample falls at (k + u_k) / N of their
// cumulative area. Every region therefore gets its share of points with far less clumping than
// independent draws. Deterministic for a given seed. Throws vdc::Error for an empty mesh, invalid
// indices, a non-positive spacing, or a spacing so small the set would exceed 50 million points.
SurfaceSamples sampleSurface(const TriangleMesh& mesh, double spacing, std::uint32_t seed);

}  // namespace vdc
