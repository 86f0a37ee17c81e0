#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// The shadow of an object standing on a table, seen from above: the convex hull of its vertices
// projected onto the table plane (the fixed frame's x, y). Two objects standing on the same table
// can only interpenetrate if their footprints overlap, so the scene generator tests footprints
// instead of meshes (exact for convex objects, conservative for the rest, e.g. a mug's handle).
struct Footprint {
  std::vector<Eigen::Vector2d> corners;  // convex polygon, counter-clockwise, no repeated corner

  // The mean of the corners: a point inside the polygon.
  Eigen::Vector2d centre() const;
  Footprint shifted(const Eigen::Vector2d& offset) const;
};

// The footprint of `mesh` at `world_from_object`. Throws vdc::Error for a mesh without vertices.
Footprint footprintOf(const TriangleMesh& mesh, const Eigen::Isometry3d& world_from_object);

// The largest gap [m] between the two polygons along any of their edge normals (separating axis
// theorem): positive iff they are apart, where it is a lower bound of their distance (equal to it
// when the nearest features include an edge); negative when they overlap (minus the depth).
double footprintSeparation(const Footprint& a, const Footprint& b);

// Whether every corner lies in the rectangle of full sizes `size` centred on the origin.
bool footprintInsideRectangle(const Footprint& footprint, const Eigen::Vector2d& size);

}  // namespace vdc
