#include "view_direction_classification/geometry/primitive_meshes.h"

#include <cmath>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void requireLength(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string(name) + " must be a positive length, got " + std::to_string(value));
  }
}

// A prism: `profile`, a polygon in the (y, z) plane, counter-clockwise seen from +x and
// star-shaped about `centre` (each cap is a fan about it), extruded over x in [-length / 2,
// length / 2]. Closed and outward oriented.
TriangleMesh extrudedProfile(const std::vector<Eigen::Vector2f>& profile,
                             const Eigen::Vector2f& centre, float length) {
  TriangleMesh mesh;
  const int m = static_cast<int>(profile.size());
  const float half = 0.5f * length;
  for (const float x : {half, -half}) {  // the front ring (x > 0) is 0..m-1, the back m..2m-1
    for (const Eigen::Vector2f& p : profile) mesh.vertices.emplace_back(x, p.x(), p.y());
  }
  const int front_centre = 2 * m, back_centre = front_centre + 1;
  mesh.vertices.emplace_back(half, centre.x(), centre.y());
  mesh.vertices.emplace_back(-half, centre.x(), centre.y());
  for (int k = 0; k < m; ++k) {
    const int next = (k + 1) % m;
    mesh.triangles.emplace_back(front_centre, k, next);         // seen from +x
    mesh.triangles.emplace_back(back_centre, m + next, m + k);  // seen from -x
    mesh.triangles.emplace_back(k, m + k, m + next);  // the side through the edge k -> next:
    mesh.triangles.emplace_back(k, m + next, next);   // outwards is right of it, seen from +x
  }
  return mesh;
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

TriangleMesh makeCartonMesh(const Eigen::Vector3d& size, double gable, double fin_height,
                            double fin_thickness) {
  requireLength(size.x(), "the carton's x size");
  requireLength(size.y(), "the carton's y size");
  requireLength(size.z(), "the carton's height");
  requireLength(gable, "the carton's gable");
  if (!(fin_height >= 0.0) || !std::isfinite(fin_height)) {
    throw Error("the carton's fin height must be zero or a positive length, got " +
                std::to_string(fin_height));
  }
  requireLength(fin_thickness, "the carton's fin thickness");
  if (fin_height > 0.0 && fin_thickness >= size.y()) {
    throw Error("the carton's fin (" + std::to_string(fin_thickness) +
                " m thick) must be thinner than the carton (" + std::to_string(size.y()) + " m)");
  }
  const double wall = size.z() - gable - fin_height;
  if (!(wall > 0.0)) {
    throw Error("the carton's gable and fin (" + std::to_string(gable + fin_height) +
                " m) leave its walls no height in " + std::to_string(size.z()) + " m");
  }
  // The cross-section across the ridge, counter-clockwise seen from +x (y right, z up): the base,
  // the walls, the roof's slopes and, between them, the fin.
  const float a = static_cast<float>(0.5 * size.y()), w = static_cast<float>(wall);
  const float ridge = static_cast<float>(wall + gable), top = static_cast<float>(size.z());
  std::vector<Eigen::Vector2f> profile{{-a, 0.0f}, {a, 0.0f}, {a, w}};
  if (fin_height > 0.0) {
    const float t = static_cast<float>(0.5 * fin_thickness);
    const float roof_at_fin = ridge - (ridge - w) * t / a;  // the slope's height at |y| = t
    profile.insert(profile.end(), {{t, roof_at_fin}, {t, top}, {-t, top}, {-t, roof_at_fin}});
  } else {
    profile.emplace_back(0.0f, ridge);
  }
  profile.emplace_back(-a, w);
  // Every vertex, and every edge whole, is seen from the walls' mid-height on the axis.
  return extrudedProfile(profile, Eigen::Vector2f(0.0f, 0.5f * w), static_cast<float>(size.x()));
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
