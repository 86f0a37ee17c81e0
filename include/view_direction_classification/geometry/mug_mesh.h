#pragma once

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// The built-in object (doc/method.md section 1): a mug with a closed bottom, an open top and a
// C-shaped handle on +x. Object frame: axis +z with the opening towards +z, origin at the centre
// of the body (z in [-height/2, height/2]), symmetry plane y = 0. All lengths in metres.
struct MugShape {
  double outer_radius = 0.04;
  double height = 0.095;
  double wall = 0.004;    // side wall thickness
  double bottom = 0.004;  // bottom thickness
  double handle_tube_radius = 0.006;
  // The handle's centre line is a half ellipse in the plane y = 0, starting and ending inside
  // the side wall (at radius outer_radius - wall / 2, so its end caps are hidden in the wall).
  double handle_reach = 0.03;    // horizontal half axis: from the sunk ends to the outermost point
  double handle_span = 0.055;    // vertical distance between the two ends of the centre line
  double handle_centre_z = 0.0;  // height of the ellipse's centre
  int segments = 48;             // around the body: keeps the silhouette within 0.1 px at 0.6 m
  int height_segments = 4;       // along each wall, keeps triangles from becoming needles
  int radial_segments = 3;       // across the bottom faces
  int handle_segments = 32;      // along the handle's centre line
  int tube_segments = 16;        // around the handle tube
};

// Triangle mesh of the mug, outward oriented. It consists of two closed shells (every edge is
// shared by exactly two triangles): the body, a solid of revolution including the inner wall
// and inner bottom, and the handle tube with end caps sunk into the side wall. Throws vdc::Error
// for a shape that cannot be built (non-positive sizes, a wall thicker than the radius, a handle
// that would poke through the inner wall or leave the body's height, too few segments).
TriangleMesh makeMug(const MugShape& shape = {});

// Two object-frame points on the handle's outer surface, the first on its upper part, the second
// on its lower part (at 45 degrees from the ends along the centre-line ellipse). They are the
// centres of the visibility crop of the occlusion experiment (doc/method.md section 11).
std::vector<Eigen::Vector3d> mugHandleAnchors(const MugShape& shape = {});

}  // namespace vdc
