#pragma once

#include <Eigen/Core>

#include <cstdint>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// How a real object differs from its mesh, for rendering views of an object the model does not
// quite match: a per-axis scale about the object origin, then smooth dents.
// A dent has a centre on the (scaled) surface, drawn area-uniformly from the seed, and pushes each
// vertex within dent_radius of it inward, against the vertex normal, by
//   depth * (1 - (d / radius)^2)^2 * max(0, n_vertex . n_centre)
// (d: the vertex's distance from the centre): the full depth at the centre, smoothly zero at the
// rim, and nothing on surfaces facing away (the far side of a thin wall). Where dents overlap a
// vertex moves by the deepest one's amount, so no vertex moves by more than the depth. Only
// vertices move: a coarse mesh shows a dent only where it has vertices.
struct MeshPerturbation {
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();  // per axis, object frame
  int dents = 0;
  double dent_depth = 0.0;   // [m]
  double dent_radius = 0.0;  // [m]; <= 0: a tenth of the mesh's bounding-box diagonal
  std::uint32_t seed = 1;    // of the dents' centres

  // False for the identity (scale 1, no dents): the mesh is returned unchanged.
  bool any() const;
};

// Throws vdc::Error naming the first bad value: a scale outside [0.1, 10] (or NaN), a negative
// dent count, a depth or radius negative or not finite.
void checkMeshPerturbation(const MeshPerturbation& perturbation);

// The perturbed copy of `mesh` (same triangles, moved vertices). Vertices at the same position
// (meshes whose faces do not share vertices) get one normal and so move together.
TriangleMesh perturbMesh(const TriangleMesh& mesh, const MeshPerturbation& perturbation);

}  // namespace vdc
