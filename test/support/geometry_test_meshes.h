#pragma once

// Small analytic meshes shared by the geometry tests.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"
#include "view_direction_classification/geometry/view_sphere.h"

namespace vdc::test {

// Axis-aligned box centred at the origin with the given half sizes, outward oriented, closed.
inline TriangleMesh makeBox(const Eigen::Vector3f& half) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                               (i & 4) ? half.z() : -half.z());
  }
  // Each face as a quad, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.emplace_back(q[0], q[1], q[2]);
    mesh.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

// Square of side `size` in the plane z = `z`, normal +z, centred on the z axis.
inline TriangleMesh makeSquare(float size, float z) {
  const float h = 0.5f * size;
  TriangleMesh mesh;
  mesh.vertices = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// Icosphere of the given radius (vertices on the sphere), outward oriented.
inline TriangleMesh makeSphere(float radius, int level) {
  const Icosphere sphere = makeIcosphere(level);
  TriangleMesh mesh;
  for (const Eigen::Vector3d& v : sphere.vertices)
    mesh.vertices.push_back(radius * v.cast<float>());
  mesh.triangles = sphere.faces;
  return mesh;
}

// Distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
inline double pointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// Index of the triangle nearest to p and its distance.
inline std::pair<int, double> nearestTriangle(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  std::pair<int, double> best{-1, 1e300};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const double d = pointTriangleDistance(p, mesh.vertices[tri[0]].cast<double>(),
                                           mesh.vertices[tri[1]].cast<double>(),
                                           mesh.vertices[tri[2]].cast<double>());
    if (d < best.second) best = {static_cast<int>(t), d};
  }
  return best;
}

// A 0.2 m square at 0.8 m in front of a 1.4 m square at 1 m, both facing a camera at the origin:
// one 0.2 m depth edge all around the small square, flat surfaces elsewhere (the sensor models'
// tests).
inline TriangleMesh makeDepthStep() {
  TriangleMesh mesh = makeSquare(0.2f, 0.8f);
  const TriangleMesh back = makeSquare(1.4f, 1.0f);
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), back.vertices.begin(), back.vertices.end());
  for (const Eigen::Vector3i& t : back.triangles) {
    mesh.triangles.emplace_back(t.array() + offset);
  }
  return mesh;
}

}  // namespace vdc::test
