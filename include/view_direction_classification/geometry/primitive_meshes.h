#pragma once

#include <Eigen/Core>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Simple closed solids for scenes (table-top distractors, simple known objects). All stand on the
// plane z = 0 of their own frame (origin at the centre of the bottom face, +z up), so a pose whose
// z is the table's height puts them on the table. Outward oriented, every edge shared by two
// triangles.

// A box of the given full sizes [m] along x, y, z. Throws vdc::Error for a size that is not
// positive and finite.
TriangleMesh makeBoxMesh(const Eigen::Vector3d& size);

// A cylinder about +z of `radius` and `height` [m] with `segments` sides (>= 8). Throws vdc::Error
// for a non-positive or non-finite size or too few segments.
TriangleMesh makeCylinderMesh(double radius, double height, int segments = 32);

// A gable-top carton (milk, juice): a box of size.x() by size.y() [m] whose top is a roof of two
// slopes rising `gable` [m] from the tops of the walls along x to a ridge along x (the walls
// across x end in gable triangles), and on the ridge the sealed seam, a fin `fin_height` [m] high
// (0: none) and `fin_thickness` [m] thick across y. size.z() is the whole height, fin included,
// so the walls are size.z() - gable - fin_height high. A real carton's fin stands about half the
// roof's rise above the ridge, where a camera above the table sees it: a model without it leaves
// those points unexplained. Throws vdc::Error for a
// size that is not a positive length, a negative fin, a fin not thinner than the carton or walls
// without height.
TriangleMesh makeCartonMesh(const Eigen::Vector3d& size, double gable, double fin_height = 0.0,
                            double fin_thickness = 0.005);

// A horizontal rectangle of full sizes size.x() by size.y() [m] in the plane z = 0, centred on the
// origin, normal +z (the renderer draws both faces). Throws vdc::Error for a non-positive size.
TriangleMesh makeRectangleMesh(const Eigen::Vector2d& size);

}  // namespace vdc
