#include "view_direction_classification/geometry/primitive_meshes.h"

#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void requireLength(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string(name) + " must be a positive length, got " + std::to_string(value));
  }
}

}  // namespace

TriangleMesh makeBoxMesh(const Eigen::Vector3d& size) {
  requireLength(size.x(), "the box's x size");
  requireLength(size.y(), "the box's y size");
  requireLength(size.z(), "the box's z size");
  const Eigen::Vector3f half = (0.5 * size).cast<float>();
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                               (i & 4) ? 2.0f * half.z() : 0.0f);
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

TriangleMesh makeCylinderMesh(double radius, double height, int segments) {
  requireLength(radius, "the cylinder's radius");
  requireLength(height, "the cylinder's height");
  if (segments < 8) {
    throw Error("a cylinder needs at least 8 segments, got " + std::to_string(segments));
  }
  TriangleMesh mesh;
  const float h = static_cast<float>(height);
  // Vertex 2k on the bottom rim, 2k + 1 above it on the top rim; then the two cap centres.
  for (int k = 0; k < segments; ++k) {
    const double angle = 2.0 * M_PI * k / segments;
    const float x = static_cast<float>(radius * std::cos(angle));
    const float y = static_cast<float>(radius * std::sin(angle));
    mesh.vertices.emplace_back(x, y, 0.0f);
    mesh.vertices.emplace_back(x, y, h);
  }
  const int bottom_centre = 2 * segments, top_centre = bottom_centre + 1;
  mesh.vertices.emplace_back(0.0f, 0.0f, 0.0f);
  mesh.vertices.emplace_back(0.0f, 0.0f, h);
  for (int k = 0; k < segments; ++k) {
    const int b0 = 2 * k, t0 = b0 + 1;
    const int b1 = 2 * ((k + 1) % segments), t1 = b1 + 1;
    mesh.triangles.emplace_back(b0, b1, t1);  // side, counter-clockwise seen from outside
    mesh.triangles.emplace_back(b0, t1, t0);
    mesh.triangles.emplace_back(bottom_centre, b1, b0);  // bottom, seen from below
    mesh.triangles.emplace_back(top_centre, t0, t1);     // top, seen from above
  }
  return mesh;
}

TriangleMesh makeRectangleMesh(const Eigen::Vector2d& size) {
  requireLength(size.x(), "the rectangle's x size");
  requireLength(size.y(), "the rectangle's y size");
  const float hx = static_cast<float>(0.5 * size.x()), hy = static_cast<float>(0.5 * size.y());
  TriangleMesh mesh;
  mesh.vertices = {{-hx, -hy, 0.0f}, {hx, -hy, 0.0f}, {hx, hy, 0.0f}, {-hx, hy, 0.0f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace vdc
