#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/bop/bop_types.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// BOP stores millimetres, the package works in metres (meshes, clouds, bundles): the one place
// the two meet.
constexpr double kMillimetresPerMetre = 1000.0;

Eigen::Isometry3d isometryOf(const BopPose& pose);  // t [mm] -> translation [m]
BopPose bopPoseOf(const Eigen::Isometry3d& pose);   // translation [m] -> t [mm]

// The mesh with every vertex multiplied by `factor` (1000: metres to mm, 0.001 back).
TriangleMesh scaledMesh(const TriangleMesh& mesh, double factor);

// The vertices [mm] of a mesh in metres, for the metrics.
std::vector<Eigen::Vector3d> verticesInMillimetres(const TriangleMesh& mesh_m);

// The largest distance between two vertices [mm] of a mesh in metres: models_info.json's
// diameter. Quadratic in the vertices (a model has thousands: well under a second).
double bopDiameter(const TriangleMesh& mesh_m);

}  // namespace vdc
