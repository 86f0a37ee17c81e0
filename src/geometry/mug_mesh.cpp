#include "view_direction_classification/geometry/mug_mesh.h"

#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// A point of the body's profile: distance from the axis and height.
struct ProfilePoint {
  double r;
  double z;
};

void requirePositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("mug shape parameter ") + name + " must be positive, got " +
                std::to_string(value));
  }
}

void requireAtLeast(int value, int minimum, const char* name) {
  if (value < minimum) {
    throw Error(std::string("mug shape parameter ") + name + " must be at least " +
                std::to_string(minimum) + ", got " + std::to_string(value));
  }
}

void checkShape(const MugShape& s) {
  requirePositive(s.outer_radius, "outer_radius");
  requirePositive(s.height, "height");
  requirePositive(s.wall, "wall");
  requirePositive(s.bottom, "bottom");
  requirePositive(s.handle_tube_radius, "handle_tube_radius");
  requirePositive(s.handle_reach, "handle_reach");
  requirePositive(s.handle_span, "handle_span");
  if (!std::isfinite(s.handle_centre_z)) {
    throw Error("mug shape parameter handle_centre_z must be finite");
  }
  requireAtLeast(s.segments, 8, "segments");
  requireAtLeast(s.height_segments, 1, "height_segments");
  requireAtLeast(s.radial_segments, 1, "radial_segments");
  requireAtLeast(s.handle_segments, 4, "handle_segments");
  requireAtLeast(s.tube_segments, 6, "tube_segments");
  if (s.wall >= s.outer_radius) {
    throw Error("mug shape: the wall (" + std::to_string(s.wall) +
                " m) must be thinner than the outer radius (" + std::to_string(s.outer_radius) +
                " m)");
  }
  if (s.bottom >= s.height) {
    throw Error("mug shape: the bottom (" + std::to_string(s.bottom) +
                " m) must be thinner than the height (" + std::to_string(s.height) + " m)");
  }
  // The end caps sit at radius R - w/2; the cap's corners at y = +-r must stay inside the outer
  // wall, i.e. (R - w/2)^2 + r^2 < R^2.
  const double r = s.handle_tube_radius;
  const double sunk = s.outer_radius - 0.5 * s.wall;
  if (sunk * sunk + r * r >= s.outer_radius * s.outer_radius) {
    throw Error("mug shape: a handle tube of radius " + std::to_string(r) +
                " m does not fit into a wall of " + std::to_string(s.wall) +
                " m; its end caps would show");
  }
  // Near its ends the tube's inner side moves by (reach - r * half_span / reach) per unit of the
  // ellipse parameter; if that is negative the tube pokes through the inner wall.
  const double half_span = 0.5 * s.handle_span;
  if (s.handle_reach * s.handle_reach <= r * half_span) {
    throw Error("mug shape: the handle reach " + std::to_string(s.handle_reach) +
                " m is too short for its span and tube radius; the tube would cut into the mug");
  }
  if (s.handle_centre_z + half_span + r > 0.5 * s.height ||
      s.handle_centre_z - half_span - r < -0.5 * s.height + s.bottom) {
    throw Error("mug shape: the handle (span " + std::to_string(s.handle_span) + " m, centre z " +
                std::to_string(s.handle_centre_z) +
                " m) must stay between the inner bottom and the rim");
  }
}

// The closed profile of the body from the outer bottom's centre to the inner bottom's centre;
// its first and last points lie on the axis (poles of the surface of revolution).
std::vector<ProfilePoint> bodyProfile(const MugShape& s) {
  const double R = s.outer_radius;
  const double r_in = R - s.wall;
  const double z_low = -0.5 * s.height;
  const double z_high = 0.5 * s.height;
  const double z_floor = z_low + s.bottom;
  std::vector<ProfilePoint> profile;
  auto segment = [&profile](ProfilePoint from, ProfilePoint to, int steps) {
    for (int k = 0; k < steps; ++k) {
      const double f = static_cast<double>(k) / steps;
      profile.push_back({from.r + f * (to.r - from.r), from.z + f * (to.z - from.z)});
    }
  };
  segment({0.0, z_low}, {R, z_low}, s.radial_segments);         // outer bottom
  segment({R, z_low}, {R, z_high}, s.height_segments);          // outer wall
  segment({R, z_high}, {r_in, z_high}, 1);                      // rim
  segment({r_in, z_high}, {r_in, z_floor}, s.height_segments);  // inner wall
  segment({r_in, z_floor}, {0.0, z_floor}, s.radial_segments);  // inner bottom
  profile.push_back({0.0, z_floor});
  return profile;
}

// Surface of revolution of the profile about z. Triangles (a, b, c) with a -> b along +theta
// and b -> c along the profile have normal e_theta x t_profile, which points out of the solid
// for this profile's direction (outwards on the outer wall, into the cavity on the inner one).
TriangleMesh makeBody(const MugShape& s) {
  const std::vector<ProfilePoint> profile = bodyProfile(s);
  const int n = s.segments;
  TriangleMesh mesh;
  // first vertex index of every profile point: poles have one vertex, other points a ring
  std::vector<int> first(profile.size());
  for (std::size_t i = 0; i < profile.size(); ++i) {
    first[i] = static_cast<int>(mesh.vertices.size());
    const bool pole = i == 0 || i + 1 == profile.size();
    if (pole) {
      mesh.vertices.emplace_back(0.0f, 0.0f, static_cast<float>(profile[i].z));
      continue;
    }
    for (int j = 0; j < n; ++j) {
      const double theta = 2.0 * M_PI * j / n;
      mesh.vertices.emplace_back(static_cast<float>(profile[i].r * std::cos(theta)),
                                 static_cast<float>(profile[i].r * std::sin(theta)),
                                 static_cast<float>(profile[i].z));
    }
  }
  auto vertex = [&](std::size_t i, int j) {
    const bool pole = i == 0 || i + 1 == profile.size();
    return pole ? first[i] : first[i] + (j % n);
  };
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = vertex(i, j), b = vertex(i, j + 1);
      const int c = vertex(i + 1, j + 1), d = vertex(i + 1, j);
      if (a != b) mesh.triangles.emplace_back(a, b, c);
      if (c != d) mesh.triangles.emplace_back(a, c, d);
    }
  }
  return mesh;
}

// The handle's centre line (half ellipse in y = 0) and its frame at parameter t in [0, pi]:
// `outward` is the in-plane unit normal pointing away from the ellipse's centre (the handle's
// outer side); y is the other cross-section axis.
struct HandleFrame {
  Eigen::Vector3d centre, tangent, outward;
};

HandleFrame handleFrame(const MugShape& s, double t) {
  const double sunk = s.outer_radius - 0.5 * s.wall;
  const double half_span = 0.5 * s.handle_span;
  HandleFrame f;
  f.centre = {sunk + s.handle_reach * std::sin(t), 0.0,
              s.handle_centre_z + half_span * std::cos(t)};
  f.tangent =
      Eigen::Vector3d(s.handle_reach * std::cos(t), 0.0, -half_span * std::sin(t)).normalized();
  f.outward = f.tangent.cross(Eigen::Vector3d::UnitY());
  return f;
}

// Closed tube along the centre line. With u = cos(phi) outward + sin(phi) y, quads walked
// (t, phi) -> (t+, phi) -> (t+, phi+) have normal tangent x du/dphi = u: outwards.
TriangleMesh makeHandle(const MugShape& s) {
  const int along = s.handle_segments;
  const int around = s.tube_segments;
  const double r = s.handle_tube_radius;
  TriangleMesh mesh;
  for (int i = 0; i <= along; ++i) {
    const HandleFrame f = handleFrame(s, M_PI * i / along);
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * M_PI * j / around;
      const Eigen::Vector3d p =
          f.centre + r * (std::cos(phi) * f.outward + std::sin(phi) * Eigen::Vector3d::UnitY());
      mesh.vertices.push_back(p.cast<float>());
    }
  }
  auto ring = [around](int i, int j) { return i * around + (j % around); };
  for (int i = 0; i < along; ++i) {
    for (int j = 0; j < around; ++j) {
      const int a = ring(i, j), b = ring(i + 1, j), c = ring(i + 1, j + 1), d = ring(i, j + 1);
      mesh.triangles.emplace_back(a, b, c);
      mesh.triangles.emplace_back(a, c, d);
    }
  }
  // End caps: fans around the centre line's end points, facing away from the tube (-tangent at
  // the start, +tangent at the end).
  const int start_centre = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back(handleFrame(s, 0.0).centre.cast<float>());
  const int end_centre = start_centre + 1;
  mesh.vertices.push_back(handleFrame(s, M_PI).centre.cast<float>());
  for (int j = 0; j < around; ++j) {
    mesh.triangles.emplace_back(start_centre, ring(0, j), ring(0, j + 1));
    mesh.triangles.emplace_back(end_centre, ring(along, j + 1), ring(along, j));
  }
  return mesh;
}

}  // namespace

TriangleMesh makeMug(const MugShape& shape) {
  checkShape(shape);
  TriangleMesh mesh = makeBody(shape);
  mesh.append(makeHandle(shape));
  return mesh;
}

std::vector<Eigen::Vector3d> mugHandleAnchors(const MugShape& shape) {
  checkShape(shape);
  std::vector<Eigen::Vector3d> anchors;
  for (double t : {0.25 * M_PI, 0.75 * M_PI}) {
    const HandleFrame f = handleFrame(shape, t);
    anchors.push_back(f.centre + shape.handle_tube_radius * f.outward);
  }
  return anchors;
}

}  // namespace vdc
