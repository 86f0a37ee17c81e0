#pragma once

#include <Eigen/Core>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Simple closed solids for scenes (table-top distractors). Both stand on the plane z = 0 of their
// own frame (origin at the centre of the bottom face, +z up), so a pose whose z is the table's
// height puts them on the table. Outward oriented, every edge shared by two triangles.

// A box of the given full sizes [m] along x, y, z. Throws vdc::Error for a size that is not
// positive and finite.
TriangleMesh makeBoxMesh(const Eigen::Vector3d& size);

// A cylinder about +z of `radius` and `height` [m] with `segments` sides (>= 8). Throws vdc::Error
// for a non-positive or non-finite size or too few segments.
TriangleMesh makeCylinderMesh(double radius, double height, int segments = 32);

// A horizontal rectangle of full sizes size.x() by size.y() [m] in the plane z = 0, centred on the
// origin, normal +z (the renderer draws both faces). Throws vdc::Error for a non-positive size.
TriangleMesh makeRectangleMesh(const Eigen::Vector2d& size);

}  // namespace vdc
